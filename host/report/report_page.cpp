#include "report/report_page.h"

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "common/errors.h"
#include "formats/commit_record.h"

namespace fs = std::filesystem;

namespace brdfbake {

namespace {

std::string escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    if (c == '<')
      o += "&lt;";
    else if (c == '>')
      o += "&gt;";
    else if (c == '&')
      o += "&amp;";
    else if (c == '"')
      o += "&quot;";
    else
      o += c;
  }
  return o;
}

void writeFile(const fs::path& p, const std::string& text) {
  std::ofstream f(p, std::ios::binary);
  f << text;
  f.close();
  if (!f) throw Error(kExitIoErr, "cannot write " + p.string());
}

// The gnuplot to run: $BRDFBAKE_GNUPLOT when set (a path), else gnuplot on PATH.
std::string gnuplotProgram() {
  const char* env = std::getenv("BRDFBAKE_GNUPLOT");
  return env && *env ? env : "gnuplot";
}

// gnuplot on `script` inside `dir`; true when it ran and exited 0.
bool runGnuplot(const fs::path& dir, const std::string& script) {
  pid_t pid = fork();
  if (pid < 0) return false;
  if (pid == 0) {
    if (chdir(dir.c_str()) != 0) _exit(127);
    FILE* devnull = std::fopen("/dev/null", "w");
    if (devnull) dup2(fileno(devnull), STDERR_FILENO);
    std::string prog = gnuplotProgram();
    execlp(prog.c_str(), prog.c_str(), script.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

}  // namespace

bool ReportPage::gnuplotAvailable() {
  std::string prog = gnuplotProgram();
  if (prog.find('/') != std::string::npos) return access(prog.c_str(), X_OK) == 0;
  const char* path = std::getenv("PATH");
  if (!path) return false;
  std::string p = path;
  size_t start = 0;
  while (start <= p.size()) {
    size_t colon = p.find(':', start);
    std::string d = p.substr(start, colon == std::string::npos ? std::string::npos : colon - start);
    if (!d.empty() && access((d + "/" + prog).c_str(), X_OK) == 0) return true;
    if (colon == std::string::npos) break;
    start = colon + 1;
  }
  return false;
}

void ReportPage::verdict(Outcome outcome, const std::string& text) {
  outcome_ = outcome;
  verdict_ = text;
}
void ReportPage::heading(const std::string& text) { items_.push_back({Item::Heading, text, "", "", {}}); }
void ReportPage::paragraph(const std::string& text) { items_.push_back({Item::Paragraph, text, "", "", {}}); }
void ReportPage::preformatted(const std::string& text) { items_.push_back({Item::Pre, text, "", "", {}}); }
void ReportPage::data(const std::string& fileName, const std::string& csv) {
  items_.push_back({Item::Data, fileName, csv, "", {}});
}
void ReportPage::plot(const std::string& plotName, const std::string& script, const std::string& caption) {
  items_.push_back({Item::Plot, plotName, script, caption, {}});
}
void ReportPage::image(const std::string& fileName, const std::string& caption,
                       std::function<void(const std::string&)> write) {
  items_.push_back({Item::Image, fileName, "", caption, std::move(write)});
}

std::string ReportPage::write(const std::string& dirName) const {
  fs::path dir(dirName);
  const fs::path parent = dir.parent_path().empty() ? fs::path(".") : dir.parent_path();
  std::error_code ec;
  fs::create_directories(parent, ec);
  if (ec) throw Error(kExitCantCreat, "cannot create " + parent.string() + ": " + ec.message());
  // the whole write under the parent's lock (the bakes' lock): a bake there sweeps temporaries
  // under it, so it never sees this one half-written, and sweeps one a killed run left; two runs
  // writing the same page each land whole, the later one last
  DirLock lock(parent.string(), true);
  recoverDirectory(parent.string());
  // `.<page>.brdfbake-tmp-<pid>-XXXXXX`: a sweep removes it only once this process is gone
  std::string tmpl = (parent / ("." + dir.filename().string() + temporaryMarker() + "XXXXXX")).string();
  if (!::mkdtemp(tmpl.data())) throwFileError(errno, "cannot create a temporary directory in " + parent.string());
  const fs::path tmp = tmpl;
  ::chmod(tmp.c_str(), 0777 & ~currentUmask());  // mkdtemp's 0700: the page as readable as any directory
  bool gnuplot = gnuplotAvailable();
  bool drawnAll = true;
  std::string html = "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>" + escape(title_) +
                     "</title>\n<style>body{font-family:sans-serif;max-width:70em;margin:2em auto}"
                     "pre{background:#f4f4f4;padding:.5em;overflow-x:auto;font-size:.8em}img{max-width:100%}"
                     ".verdict{font-size:1.2em;padding:.4em .6em;border-left:.4em solid #888}"
                     ".verdict.pass{border-color:#2a2}.verdict.fail{border-color:#c22}</style></head>"
                     "<body>\n<h1>" +
                     escape(title_) + "</h1>\n";
  if (!verdict_.empty()) {
    const char* cls = outcome_ == Outcome::Pass ? "pass" : outcome_ == Outcome::Fail ? "fail" : "measured";
    const char* word = outcome_ == Outcome::Pass ? "PASS: " : outcome_ == Outcome::Fail ? "FAIL: " : "";
    html += std::string("<p class=\"verdict ") + cls + "\">" +
            (*word ? std::string("<strong>") + word + "</strong>" : "") + escape(verdict_) + "</p>\n";
  }
  try {
    for (const Item& it : items_) {
      switch (it.kind) {
        case Item::Heading:
          html += "<h2>" + escape(it.a) + "</h2>\n";
          break;
        case Item::Paragraph:
          html += "<p>" + escape(it.a) + "</p>\n";
          break;
        case Item::Pre:
          html += "<pre>" + escape(it.a) + "</pre>\n";
          break;
        case Item::Data:
          writeFile(tmp / it.a, it.b);
          html += "<p>data: <a href=\"" + escape(it.a) + "\">" + escape(it.a) + "</a></p>\n";
          break;
        case Item::Image:
          it.write((tmp / it.a).string());
          html += "<figure><img src=\"" + escape(it.a) + "\" alt=\"" + escape(it.c) + "\"><figcaption>" + escape(it.c) +
                  "</figcaption></figure>\n";
          break;
        case Item::Plot: {
          std::string script = "set terminal svg size 800,560 dynamic enhanced font 'sans,12'\nset output '" + it.a +
                               ".svg'\n" + it.b + "\n";
          writeFile(tmp / (it.a + ".gp"), script);
          bool drawn = gnuplot && runGnuplot(tmp, it.a + ".gp") && fs::file_size(tmp / (it.a + ".svg"), ec) > 0;
          drawnAll = drawnAll && drawn;
          if (drawn)
            html += "<figure><img src=\"" + escape(it.a) + ".svg\" alt=\"" + escape(it.c) + "\"><figcaption>" +
                    escape(it.c) + "</figcaption></figure>\n";
          else
            html += "<p>[plot " + escape(it.a) + " not drawn: run <code>gnuplot " + escape(it.a) + ".gp</code> here] " +
                    escape(it.c) + "</p>\n";
          break;
        }
      }
    }
    html += "</body></html>\n";
    writeFile(tmp / "index.html", html);
    fs::remove_all(dir, ec);
    fs::rename(tmp, dir, ec);
    if (ec) throw Error(kExitCantCreat, "cannot create " + dir.string() + ": " + ec.message());
  } catch (...) {
    fs::remove_all(tmp, ec);
    throw;
  }
  std::string line = "report: " + (dir / "index.html").string();
  if (!gnuplot)
    line += " (plots not drawn: gnuplot not found; apt-get install gnuplot-nox, then run `gnuplot NAME.gp` in " +
            dir.string() + ", or rerun)";
  else if (!drawnAll)
    line += " (some plots failed to draw; their gnuplot scripts are in " + dir.string() + ")";
  return line + "\n";
}

}  // namespace brdfbake
