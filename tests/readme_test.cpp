// The README's commands do what it says: every `./build/brdfbake ...` line in its shell blocks and
// prose runs (in a scratch directory, examples/ linked in), exits as shown (energy's VIOLATES: 1,
// else 0), prints the first line shown under a `$ ` command, and writes the files its comment
// names. Two recipes run with --size 4 appended, the same command on a smaller grid: at their
// default sizes they take 133 s (rough glass, 32x32x32) and 27 s (MERL) on 2 cores, more than
// the rest of the suite's CLI tests together.
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <set>
#include <fstream>
#include <regex>
#include <sstream>

#include "cli_run.h"
#include "doc_figures.h"

namespace fs = std::filesystem;
using namespace brdfbake::testing_cli;
using namespace brdfbake::testing_docs;

namespace {

struct ReadmeCommand {
  std::string args;     // after ./build/brdfbake
  std::string comment;  // after '#' on its line
  std::string shown;    // the first output line shown under a `$ ` command, or ""
};

std::vector<ReadmeCommand> readmeCommands() {
  std::ifstream in(BRDFBAKE_SOURCE_DIR "/README.md");
  std::vector<ReadmeCommand> cmds;
  std::string line;
  bool fenced = false, shell = false;
  const std::string exe = "./build/brdfbake";
  const std::regex inlineCmd("`\\./build/brdfbake ([^`]+)`");
  while (std::getline(in, line)) {
    if (line.rfind("```", 0) == 0) {
      fenced = !fenced;
      shell = fenced && line == "```sh";
      continue;
    }
    if (!fenced) {
      for (std::sregex_iterator it(line.begin(), line.end(), inlineCmd), end; it != end; ++it)
        cmds.push_back({(*it)[1].str(), "", ""});
      continue;
    }
    if (!shell) continue;
    std::string l = line;
    bool dollar = l.rfind("$ ", 0) == 0;
    if (dollar) l = l.substr(2);
    if (l.rfind(exe + " ", 0) == 0) {
      ReadmeCommand c;
      std::string rest = l.substr(exe.size() + 1);
      size_t hash = rest.find(" #");
      if (hash != std::string::npos) {
        c.comment = rest.substr(hash + 2);
        rest = rest.substr(0, hash);
      }
      while (!rest.empty() && rest.back() == ' ') rest.pop_back();
      c.args = rest;
      cmds.push_back(c);
    } else if (!cmds.empty() && !dollar && cmds.back().shown.empty() && !line.empty()) {
      // output shown under the previous `$ ` command
      cmds.back().shown = line;
    }
  }
  return cmds;
}

std::string firstLine(const std::string& s) { return s.substr(0, s.find('\n')); }

}  // namespace

TEST(Readme, CommandsRunAsShown) {
  const fs::path d = freshDir("readme", "commands");
  fs::create_directory_symlink(fs::path(BRDFBAKE_SOURCE_DIR) / "examples", d / "examples");
  std::vector<ReadmeCommand> cmds = readmeCommands();
  // the recipes: layout + shader, multiple scattering, plan, energy x2, MERL, glass, sheen
  ASSERT_GE(cmds.size(), 9u);
  bool merlSeen = false;
  for (const ReadmeCommand& c : cmds) {
    std::string args = c.args;
    if (args.find("--brdf merl:") != std::string::npos) {
      // the README's material file: an analytic material written in MERL's layout
      merlSeen = true;
      ASSERT_EQ(run("bake --table brdf3d --format merl -o merl-src", d.string()).code, 0);
      const std::string name = std::regex_replace(args, std::regex(".*--brdf merl:(\\S+).*"), "$1");
      fs::copy_file(d / "merl-src" / "brdf3d_ggx_smith-correlated.binary", d / name,
                    fs::copy_options::overwrite_existing);
    }
    if (args.find("dielectric") != std::string::npos || args.find("--brdf merl:") != std::string::npos)
      args += " --size 4";
    CmdResult r = run(args, d.string());
    const int expected = c.shown.rfind("VIOLATES", 0) == 0 ? 1 : 0;
    EXPECT_EQ(r.code, expected) << "README: brdfbake " << c.args << "\n" << r.out;
    if (!c.shown.empty()) {
      EXPECT_EQ(firstLine(r.out), c.shown) << "README: brdfbake " << c.args;
    }
    // files the comment names ("lut/splitsum_ggx_smith-correlated.ktx2, R16G16_SFLOAT")
    std::smatch m;
    if (std::regex_search(c.comment, m, std::regex("([\\w.-]+/[\\w.-]+\\.\\w+)"))) {
      EXPECT_TRUE(fs::exists(d / m[1].str())) << m[1] << " (README: brdfbake " << c.args << ")";
    }
    // what a bake writes lands where -o says, or in out/
    if (r.code == 0 && r.out.rfind("file ", 0) == 0) {
      std::istringstream lines(r.out);
      std::string header, row;
      std::getline(lines, header);
      while (std::getline(lines, row) && !row.empty() && row[0] != ' ' && row.find("brdfbake:") != 0)
        EXPECT_TRUE(fs::exists(d / row.substr(0, row.find(' ')))) << row << " (README: brdfbake " << c.args << ")";
    }
  }
  EXPECT_TRUE(merlSeen) << "the MERL recipe is not among the README's commands";
}

// docs/commands-reference.md is the help, byte for byte: `brdfbake help --markdown` makes both
// from one table (host/cli/commands.cpp, host/cli/option_table.cpp), so a changed option or default shows here until
// the page is regenerated (./build/brdfbake help --markdown > docs/commands-reference.md).
TEST(Docs, CommandsReferenceIsTheHelp) {
  CmdResult r = run("help --markdown");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(bytes(fs::path(BRDFBAKE_SOURCE_DIR) / "docs/commands-reference.md"), r.out)
      << "docs/commands-reference.md differs from the help: ./build/brdfbake help --markdown > "
         "docs/commands-reference.md";
}

// Every relative link and image in README.md and docs/*.md resolves from the page that holds it.
TEST(Docs, RelativeLinksResolve) {
  const fs::path root = BRDFBAKE_SOURCE_DIR;
  std::vector<fs::path> pages = {root / "README.md"};
  for (const auto& e : fs::directory_iterator(root / "docs"))
    if (e.path().extension() == ".md") pages.push_back(e.path());
  const std::regex link("\\]\\(([^)\\s]+)\\)");
  int checked = 0;
  for (const fs::path& page : pages) {
    const std::string text = bytes(page);
    for (std::sregex_iterator it(text.begin(), text.end(), link), end; it != end; ++it) {
      std::string target = (*it)[1].str();
      if (target.find("://") != std::string::npos || target.rfind("mailto:", 0) == 0 || target[0] == '#') continue;
      target = target.substr(0, target.find('#'));
      ++checked;
      EXPECT_TRUE(fs::exists(page.parent_path() / target))
          << page.filename() << ": " << (*it)[1] << " does not resolve";
    }
  }
  EXPECT_GT(checked, 10);
}

namespace {

// A directory the pages' commands run in, as a reader's would be after the README's first command:
// examples/ linked in and the default set baked into out/.
fs::path pagesDir(const std::string& name) {
  const fs::path d = freshDir("readme", name);
  fs::create_directory_symlink(fs::path(BRDFBAKE_SOURCE_DIR) / "examples", d / "examples");
  EXPECT_EQ(run("", d.string()).code, 0);
  return d;
}

// The brdfbake commands of a page's ```sh blocks, each as its arguments, read as a shell reads
// them: a line ending in "\" continues, "&&" separates commands, "time (...)" and a trailing
// "# comment" are not the command's; "brdfbake" or "./build/brdfbake", other programs left out.
std::vector<std::string> shCommands(const std::string& page) {
  std::vector<std::string> out;
  std::istringstream in(page);
  bool sh = false, inBlock = false;
  std::string joined;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("```", 0) == 0) {
      sh = !inBlock && line == "```sh";
      inBlock = !inBlock;
      continue;
    }
    if (!inBlock || !sh) continue;
    if (!line.empty() && line.back() == '\\') {
      joined += line.substr(0, line.size() - 1) + " ";
      continue;
    }
    std::string command = joined + line;
    joined.clear();
    const size_t hash = command.find(" #");
    if (hash != std::string::npos) command.resize(hash);
    for (size_t at = 0; at <= command.size();) {
      const size_t amp = std::min(command.find("&&", at), command.size());
      std::string part = command.substr(at, amp - at);
      at = amp + 2;
      part.erase(0, part.find_first_not_of(" ("));
      if (part.rfind("time ", 0) == 0) part.erase(0, part.find_first_not_of(" (", 5));
      while (!part.empty() && (part.back() == ' ' || part.back() == ')')) part.pop_back();
      const std::string exe = part.rfind("./build/brdfbake", 0) == 0 ? "./build/brdfbake" : "brdfbake";
      if (part.rfind(exe, 0) != 0 || (part.size() > exe.size() && part[exe.size()] != ' ')) continue;
      out.push_back(part.substr(std::min(part.size(), exe.size() + 1)));
    }
  }
  return out;
}

}  // namespace

// Every example the help shows runs as shown and exits 0, from a directory holding what they
// name: examples/ linked in, the default set and a brdf3d table baked into out/.
TEST(Docs, EveryHelpExampleRuns) {
  const fs::path d = pagesDir("examples");
  ASSERT_EQ(run("bake --table brdf3d --size 8 -o out", d.string()).code, 0);
  int ran = 0;
  for (const std::string& args : shCommands(run("help --markdown").out)) {
    CmdResult r = run(args, d.string());
    EXPECT_EQ(r.code, 0) << "brdfbake " << args << "\n" << r.out.substr(r.out.size() > 3000 ? r.out.size() - 3000 : 0);
    ++ran;
  }
  EXPECT_GE(ran, 15);
}

// docs/library.md shows examples/library/bake_lut.cpp as it is (from its first #include): the page's
// code is the example the consumer test builds and runs.
TEST(Docs, LibraryPageShowsTheExample) {
  const std::string page = bytes(fs::path(BRDFBAKE_SOURCE_DIR) / "docs/library.md");
  const std::string file = bytes(fs::path(BRDFBAKE_SOURCE_DIR) / "examples/library/bake_lut.cpp");
  const size_t open = page.find("```cpp\n");
  ASSERT_NE(open, std::string::npos);
  const size_t start = open + 7, end = page.find("```\n", start);
  EXPECT_EQ(page.substr(start, end - start), file.substr(file.find("#include")))
      << "docs/library.md's code differs from examples/library/bake_lut.cpp";
}

// Every `$ brdfbake ARGS` a page in docs/ shows runs, from a directory holding what it names, and
// prints the lines shown under it (up to the next `$ ` line or the block's end), in order: the first
// is the output's first line (its standard output, or the error line when there is none), each
// next one the output's next line, and a shown line "..." skips output lines up to the one that
// matches the line after it (shownLineMatches). The figures a page quotes from a command are the
// command's.
TEST(Docs, ShownCommandsPrintWhatThePagesShow) {
  const fs::path d = pagesDir("shown");
  ASSERT_EQ(run("bake --table brdf3d -o out", d.string()).code, 0);
  int shown = 0, lines = 0;
  for (const auto& e : fs::directory_iterator(fs::path(BRDFBAKE_SOURCE_DIR) / "docs")) {
    if (e.path().extension() != ".md") continue;
    std::istringstream in(bytes(e.path()));
    std::vector<std::string> page;
    for (std::string l; std::getline(in, l);) page.push_back(l);
    for (size_t i = 0; i + 1 < page.size(); ++i) {
      if (page[i].rfind("$ brdfbake ", 0) != 0) continue;
      ++shown;
      const std::string args = page[i].substr(11);
      std::vector<std::string> want;
      for (size_t k = i + 1; k < page.size() && page[k].rfind("$ ", 0) != 0 && page[k].rfind("```", 0) != 0; ++k)
        want.push_back(page[k]);
      // what the page shows: standard output, or the error lines when there is none
      const std::string cmd = "cd '" + d.string() + "' && '" BRDFBAKE_EXE "' " + args + " 2>stderr.txt";
      FILE* p = popen(cmd.c_str(), "r");
      std::string out;
      char buf[4096];
      for (size_t n; (n = fread(buf, 1, sizeof buf, p)) > 0;) out.append(buf, n);
      pclose(p);
      std::istringstream os(out.empty() ? bytes(d / "stderr.txt") : out);
      std::vector<std::string> got;
      for (std::string l; std::getline(os, l);) got.push_back(l);
      size_t at = 0;
      for (size_t w = 0; w < want.size(); ++w) {
        ++lines;
        if (want[w] == "...") {
          // skip to the output line that matches the next shown line
          if (w + 1 == want.size()) break;
          while (at < got.size() && !shownLineMatches(want[w + 1], got[at])) ++at;
          continue;
        }
        const std::string line = at < got.size() ? got[at] : "(no more output)";
        EXPECT_TRUE(shownLineMatches(want[w], line))
            << e.path().filename() << ": " << page[i] << "\n  shown: " << want[w] << "\n  got:   " << line;
        ++at;
      }
    }
  }
  EXPECT_GE(shown, 8);
  std::printf("%d shown commands, %d shown lines checked\n", shown, lines);
}

namespace {

// "" when `name` (Suite.Name, as gtest names it) is a test of this build whose body calls
// expectPagesQuote, so that it checks the figures and tables the pages tie to it; else what is wrong.
std::string testThatChecksThePages(const std::string& name) {
  static const std::string listed = shell("ctest --test-dir '" BRDFBAKE_BINARY_DIR "' -N").out;
  const size_t dot = name.find('.');
  if (dot == std::string::npos) return name + " is not a Suite.Name";
  const std::string suite = name.substr(0, dot), test = name.substr(dot + 1);
  // ctest lists a disabled test without its DISABLED_ prefix
  const std::string listedAs = suite + "." + (test.rfind("DISABLED_", 0) == 0 ? test.substr(9) : test);
  if (!std::regex_search(listed, std::regex(": " + listedAs + "(\\n| )")))
    return name + " is no test of this build (ctest -N)";
  // a parameterised test, Instantiation/Suite.Test/Parameter, is written TEST_P(Suite, Test) (a plain
  // suite has no '/': find gives npos, and npos + 1 is 0)
  const std::string sourceSuite = suite.substr(suite.find('/') + 1), sourceTest = test.substr(0, test.find('/'));
  const std::regex head("\\nTEST(_F|_P)?\\(" + sourceSuite + ", " + sourceTest + "\\)");
  for (const auto& e : fs::recursive_directory_iterator(fs::path(BRDFBAKE_SOURCE_DIR) / "tests")) {
    if (e.path().extension() != ".cpp") continue;
    const std::string text = bytes(e.path());
    std::smatch m;
    if (!std::regex_search(text, m, head)) continue;
    const size_t start = m.position(0) + m.length(0), next = text.find("\nTEST", start);
    return text.substr(start, next - start).find("expectPagesQuote(") != std::string::npos
               ? ""
               : name + " (" + e.path().filename().string() +
                     ") does not call expectPagesQuote: nothing checks the page";
  }
  return name + ": no TEST(" + sourceSuite + ", " + sourceTest + ") under tests/";
}

}  // namespace

// A figure the prose of a page in docs/ quotes from a command carries that command in a comment
// after it (invisible where the page is read):
//   <!-- figure 1.2e-7 after "the bake's rule (device, float)" #3 from: brdfbake convergence ... -->
// The figure stands, as written, in the lines above the comment back to the paragraph's start, and
// the command, run from a directory holding what the pages name (as the shown commands are), prints
// it: on a line of its output (standard output and error) the #N-th number after the words (the
// first without #N) is the figure, to the digits it is written with and within 2% (the figures
// rounding may move between CPUs' vector widths). "; brdfbake " runs several commands in turn, the
// last one's output checked. A command exits 0, or 1 where its verdict is that a check failed (energy
// on a material that does not conserve: the figure is its excess). So prose that drifts from its
// comment, or a command whose output drifts from both, fails here.
// Two more sources, for figures that no brdfbake command prints:
//   from: brdfbake-bench ARGS    the benchmark in this build (exit 0), a quick run of it
//   from: ctest -R NAME -V       one test's printout in this build: NAME the test's whole name,
//                                a quick test, and it must pass
// A table whose every body row is a line a command prints carries <!-- rows from: COMMAND --> under
// it (the same sources); its rows are compared as shown lines are (shownLineMatches).
// Each of these runs inside this test. A figure or table from a run of minutes is tied to the test
// that prints it with "in: Suite.Name" (tests/doc_figures.h): that test checks the page against its
// own printout when it runs, and Docs.InNotesNameTestsThatCheckThePages checks that the note names a
// test of this build whose body calls expectPagesQuote.
TEST(Docs, QuotedFiguresAreWhatTheirCommandsPrint) {
  const fs::path d = pagesDir("figures");
  const std::regex& note = figureNote();
  const std::regex started("^ {0,3}<!-- (figure|rows) ");
  int figures = 0, rows = 0, selfChecked = 0;
  std::map<std::string, CmdResult> ran;  // a command quoted for several figures runs once
  // a command's output, run once: exit 0, or 1 where a brdfbake verdict is a check that failed; a
  // test or the benchmark exits 0 (-2: not one test passed)
  auto output = [&](const std::string& command) -> const CmdResult& {
    if (ran.count(command)) return ran[command];
    CmdResult r{0, ""};
    if (command.rfind("ctest ", 0) == 0) {
      // the test by its whole name (a parameterised one's ctest name goes on with "  # GetParam() = ..."):
      // exactly one runs, and it passes
      const std::string name = command.substr(9, command.size() - 9 - 3);
      r = shell("ctest --test-dir '" BRDFBAKE_BINARY_DIR "' -R '^" + name + "( |$)' -V");
      if (r.code == 0 && r.out.find("100% tests passed, 0 tests failed out of 1\n") == std::string::npos) r.code = -2;
    } else if (command.rfind("brdfbake-bench ", 0) == 0) {
      r = shell("cd '" + d.string() + "' && '" BRDFBAKE_BINARY_DIR "/brdfbake-bench' " + command.substr(15));
    } else {
      // "; brdfbake " runs commands in turn
      const std::string args = command.size() > 9 ? command.substr(9) : "", then = "; brdfbake ";
      for (size_t at = 0;;) {
        const size_t next = args.find(then, at);
        r = run(args.substr(at, next == std::string::npos ? std::string::npos : next - at), d.string());
        if ((r.code != 0 && r.code != 1) || next == std::string::npos) break;
        at = next + then.size();
      }
      if (r.code == 1) r.code = 0;
    }
    return ran[command] = r;
  };
  for (const fs::path& path : pages()) {
    if (path.filename() == "README.md") continue;
    const std::vector<std::string> page = lines(bytes(path));
    for (size_t i = 0; i < page.size(); ++i) {
      std::smatch m;
      const std::string at = path.filename().string() + ":" + std::to_string(i + 1);
      if (std::regex_search(page[i], m, rowsNote())) {
        if (m[1].matched) {
          ++selfChecked;  // Docs.InNotesNameTestsThatCheckThePages checks the test it names
          continue;
        }
        const std::string command = m[2].str();
        const CmdResult& r = output(command);
        EXPECT_EQ(r.code, 0) << at << ": " << command << " exits " << r.code << "\n"
                             << r.out.substr(r.out.size() > 3000 ? r.out.size() - 3000 : 0);
        for (const std::string& row : tableRowsAbove(page, i)) {
          ++rows;
          EXPECT_TRUE(printsRow(r.out, row))
              << at << ": " << command << " prints no line that is the row\n  " << row << "\n"
              << r.out.substr(0, 3000);
        }
        continue;
      }
      if (!std::regex_search(page[i], m, note)) {
        // a comment that means to quote a figure and is not in the form would be skipped unseen
        EXPECT_FALSE(std::regex_search(page[i], started))
            << at << ": not the form <!-- figure X after \"WORDS\" [#N] from: brdfbake ARGS --> (or from: "
            << "brdfbake-bench ARGS, from: ctest -R NAME -V, in: Suite.Name) nor <!-- rows in: Suite.Name --> (or "
            << "from: COMMAND)";
        continue;
      }
      if (m[5].matched) {
        ++selfChecked;  // as above
        continue;
      }
      ++figures;
      const std::string figure = m[1].str(), words = m[2].str(), command = m[4].str();
      const int nth = m[3].matched ? std::atoi(m[3].str().c_str()) : 1;
      const std::string where = at + ": " + figure;
      // the prose above quotes it as written
      bool quoted = false;
      for (size_t k = i; k-- > 0 && !page[k].empty();) quoted |= page[k].find(figure) != std::string::npos;
      EXPECT_TRUE(quoted) << where << ": not in the paragraph above its comment";
      const CmdResult& r = output(command);
      EXPECT_EQ(r.code, 0) << where << ": " << command << " exits " << r.code << " (-2: not one test passed)\n"
                           << r.out.substr(r.out.size() > 3000 ? r.out.size() - 3000 : 0);
      EXPECT_TRUE(printsFigure(r.out, figure, words, nth))
          << where << ": " << command << " prints it nowhere as number " << nth << " after \"" << words << "\"\n"
          << r.out.substr(0, 3000);
    }
  }
  EXPECT_GE(figures, 20);
  std::printf(
      "%d quoted figures and %d table rows checked against their commands; %d notes tie figures and tables "
      "to the tests that check them\n",
      figures, rows, selfChecked);
}

// Every "in: Suite.Name" of a figure or rows note names a test of this build whose body calls
// expectPagesQuote (testThatChecksThePages), so that the figures it ties are checked when that test
// runs: the sweeps' names included, which the README's test command leaves out. A rows note stands
// right under its table.
TEST(Docs, InNotesNameTestsThatCheckThePages) {
  int notes = 0;
  std::set<std::string> tests;
  for (const fs::path& path : pages()) {
    const std::vector<std::string> page = lines(bytes(path));
    for (size_t i = 0; i < page.size(); ++i) {
      std::smatch m;
      const std::string at = path.filename().string() + ":" + std::to_string(i + 1);
      std::string name;
      if (std::regex_search(page[i], m, rowsNote())) {
        EXPECT_TRUE(i > 0 && page[i - 1].rfind("|", 0) == 0) << at << ": a rows note is not right under a table";
        if (m[1].matched) name = m[1].str();
      } else if (std::regex_search(page[i], m, figureNote()) && m[5].matched) {
        name = m[5].str();
      }
      if (name.empty()) continue;
      ++notes;
      tests.insert(name);
      EXPECT_EQ(testThatChecksThePages(name), "") << at;
    }
  }
  EXPECT_GE(notes, 50);
  std::printf("%d notes tie figures and tables to %zu tests that check the pages themselves\n", notes, tests.size());
}

// Every brdfbake command in a page's ```sh blocks (docs/*.md but the help's own page, whose examples
// Docs.EveryHelpExampleRuns runs) is one a reader can run as written. A bake, whatever it costs
// (rough glass, every LTC pair), is run with --dry-run: its options are checked as the bake checks
// them and its plan forms, exit 0. Any other command runs as shown. Both from a directory holding
// what the pages name, as the shown commands do. Lines ending in "\" continue; "time (...)",
// "&&" and a trailing "# comment" are read as a shell reads them.
TEST(Docs, EveryPageExampleRuns) {
  const fs::path d = pagesDir("pages");
  int bakes = 0, others = 0;
  for (const auto& e : fs::directory_iterator(fs::path(BRDFBAKE_SOURCE_DIR) / "docs")) {
    if (e.path().extension() != ".md" || e.path().filename() == "commands-reference.md") continue;
    for (const std::string& args : shCommands(bytes(e.path()))) {
      std::istringstream words(args);
      std::string first, second;
      words >> first >> second;
      const bool scene = second.find(".toml") != std::string::npos || second.find(".gl") != std::string::npos;
      const bool bake = first.empty() || first[0] == '-' || (first == "bake" && !scene);
      CmdResult r = run(bake ? args + " --dry-run" : args, d.string());
      (bake ? bakes : others) += 1;
      EXPECT_EQ(r.code, 0) << e.path().filename() << ": brdfbake " << args << (bake ? " (as a dry run)" : "") << "\n"
                           << r.out.substr(r.out.size() > 3000 ? r.out.size() - 3000 : 0);
      if (bake) {
        EXPECT_NE(r.out.find("dry run: "), std::string::npos) << args << "\n" << r.out;
      }
    }
  }
  EXPECT_GE(bakes, 10);
  EXPECT_GE(others, 1);
  std::printf("%d bakes planned (--dry-run), %d other commands run\n", bakes, others);
}

// The tests the pages and the README name exist in this build, so that a reader who runs one finds
// it: every `Suite.Name` whose suite is one of ours (a name such as Unity's
// `RenderTextureFormat.ARGB2101010` is not) is a test that ctest lists (a disabled one without its
// DISABLED_ prefix, as ctest names it), and every `ctest -R PATTERN` selects at least one test.
TEST(Docs, NamedTestsExist) {
  const CmdResult listed = shell("ctest --test-dir '" BRDFBAKE_BINARY_DIR "' -N");
  ASSERT_EQ(listed.code, 0) << listed.out;
  std::set<std::string> suites;
  {
    const std::regex test("Test +#\\d+: (?:\\w+/)?(\\w+)\\.");
    for (std::sregex_iterator it(listed.out.begin(), listed.out.end(), test), end; it != end; ++it)
      suites.insert((*it)[1].str());
  }
  ASSERT_GE(suites.size(), 20u) << listed.out.substr(0, 2000);
  const std::regex named("`(?:\\w+/)?([A-Z]\\w*)\\.([A-Z]\\w*)`");
  const std::regex pattern("ctest -R (?:'([^']+)'|\"([^\"]+)\"|([^\\s`'\"|)]+))");
  std::vector<fs::path> pages{fs::path(BRDFBAKE_SOURCE_DIR) / "README.md"};
  for (const auto& e : fs::directory_iterator(fs::path(BRDFBAKE_SOURCE_DIR) / "docs"))
    if (e.path().extension() == ".md") pages.push_back(e.path());
  int names = 0, patterns = 0;
  std::map<std::string, bool> selects;  // a pattern quoted on several pages runs once
  for (const fs::path& page : pages) {
    const std::string text = bytes(page);
    for (std::sregex_iterator it(text.begin(), text.end(), named), end; it != end; ++it) {
      const std::string suite = (*it)[1].str();
      if (!suites.count(suite)) continue;
      std::string name = (*it)[2].str();
      if (name.rfind("DISABLED_", 0) == 0) name = name.substr(9);
      ++names;
      EXPECT_NE(listed.out.find(suite + "." + name), std::string::npos)
          << page.filename() << ": `" << (*it)[0].str() << "` is no test of this build";
    }
    for (std::sregex_iterator it(text.begin(), text.end(), pattern), end; it != end; ++it) {
      const std::string p = (*it)[1].matched ? (*it)[1].str() : (*it)[2].matched ? (*it)[2].str() : (*it)[3].str();
      if (p.empty() || p == "NAME") continue;  // development.md's form names its placeholder
      ++patterns;
      if (!selects.count(p)) {
        const CmdResult r = shell("ctest --test-dir '" BRDFBAKE_BINARY_DIR "' -N -R '" + p + "'");
        selects[p] = r.code == 0 && r.out.find("Total Tests: 0\n") == std::string::npos;
      }
      EXPECT_TRUE(selects[p]) << page.filename() << ": ctest -R " << p << " selects no test";
    }
  }
  EXPECT_GE(names, 50);
  EXPECT_GE(patterns, 20);
  std::printf("%d test names and %d ctest -R patterns on the pages, each a test of this build\n", names, patterns);
}

// The figures a page quotes are tied to what prints them. On every page, every number written in
// e-notation ("2.63e-3", "1e-7", the form the pages give errors and bounds in) or with a decimal
// point ("0.43", "31.0383", a ratio "2.6x") outside code is one of:
//  - tied: the X of a figure note under its paragraph (<!-- figure X ... from: ... --> or "in:"),
//    or a cell of a table under a rows note (<!-- rows in: Suite.Name -->), which the tests above
//    and the tests named check;
//  - an input: listed in its paragraph's <!-- inputs: X Y ... --> note: a value the text names or
//    sets rather than measures (a model's constant, a run's parameter, the grid point where a
//    figure was found, a threshold the code sets, a version, a cited paper's figure);
//  - marked "~": a time, a rate or a size that varies from run to run (~0.43 s, ~3.6e7 texels/s),
//    as in shown lines, or an order of magnitude (~1e-8); in a range "~A to B" or "~A-B" the mark
//    covers B;
//  - measured elsewhere: listed in its paragraph's <!-- elsewhere: X Y ... --> note, a figure that
//    the paragraph's own words say how to measure on a machine the suite lacks (a GPU);
//  - measured once: listed in its paragraph's <!-- once: X Y ... --> note, a figure the paragraph
//    says how to measure that no test reruns (a run of hours, a tool, two builds compared);
//  - a ratio of two tied figures: <!-- ratio X = A / B --> under its paragraph, where A and B are
//    tied on the same page and A/B rounds to X at X's last digit, so X drifts with them.
// A note lists only figures its paragraph holds, and none that a figure note ties. Integers are not
// held: they are counts, sizes and indices far more often than measurements.
TEST(Docs, EveryFigureOnEveryPageIsTiedOrAnInput) {
  const std::regex number("[-+]?\\d+(?:\\.\\d+)?(?:[eE][-+]?\\d+)?");
  const std::regex listNote("^ {0,3}<!-- (inputs|elsewhere|once): ([^>]*) -->$");
  const std::regex inlineCode("`[^`]*`");  // built once: the loop below runs over every line of every page
  const std::regex ratioNote("^ {0,3}<!-- ratio (\\S+) = (\\S+) / (\\S+) -->$");
  std::map<std::string, int> counts;  // tied, inputs, varies, elsewhere, once, ratio
  for (const fs::path& path : pages()) {
    if (path.filename() == "README.md" || path.filename() == "commands-reference.md") continue;
    const std::string name = path.filename().string();
    const std::vector<std::string> page = lines(bytes(path));
    // what the page ties: its figure notes' figures and the numbers in tables under a rows note
    std::set<std::string> tiedOnPage;
    for (size_t k = 0, block = 0; k < page.size(); ++k) {
      std::smatch m;
      if (page[k].empty()) block = k + 1;
      if (std::regex_search(page[k], m, figureNote())) tiedOnPage.insert(m[1].str());
      if (std::regex_search(page[k], m, rowsNote()))
        for (size_t r = block; r < k; ++r)
          if (page[r].rfind("|", 0) == 0)
            for (std::sregex_iterator it(page[r].begin(), page[r].end(), number), stop; it != stop; ++it)
              tiedOnPage.insert(it->str());
    }
    bool fenced = false;
    for (size_t i = 0; i < page.size();) {
      if (page[i].rfind("```", 0) == 0) fenced = !fenced;
      if (fenced || page[i].empty() || page[i].rfind("```", 0) == 0) {
        ++i;
        continue;
      }
      // a paragraph (or a table) and the notes under it; one indented by four spaces is code
      size_t end = i;
      while (end < page.size() && !page[end].empty() && page[end].rfind("```", 0) != 0) ++end;
      if (page[i].rfind("    ", 0) == 0 && (i == 0 || page[i - 1].empty())) {
        i = end;
        continue;
      }
      std::set<std::string> noted;
      std::map<std::string, std::string> listed;  // figure -> its note (inputs, elsewhere, once)
      bool rows = false;
      for (size_t k = i; k < end; ++k) {
        std::smatch m;
        if (std::regex_search(page[k], m, figureNote())) noted.insert(m[1].str());
        if (std::regex_search(page[k], m, rowsNote())) rows = true;
        if (std::regex_search(page[k], m, listNote)) {
          std::istringstream ws(m[2].str());
          for (std::string w; ws >> w;) listed[w] = m[1].str();
        }
        if (std::regex_search(page[k], m, ratioNote)) {
          const std::string x = m[1].str(), a = m[2].str(), b = m[3].str();
          EXPECT_TRUE(tiedOnPage.count(a) && tiedOnPage.count(b))
              << name << ":" << k + 1 << ": the ratio " << x << " = " << a << " / " << b
              << " needs both figures tied on the page";
          const size_t dot = x.find('.');
          const int digits = dot == std::string::npos ? 0 : static_cast<int>(x.size() - dot - 1);
          EXPECT_LE(std::abs(std::stod(a) / std::stod(b) - std::stod(x)), 0.5 * std::pow(10.0, -digits) * (1 + 1e-9))
              << name << ":" << k + 1 << ": " << a << " / " << b << " = " << std::stod(a) / std::stod(b)
              << ", which does not round to " << x;
          listed[x] = "ratio";
        }
      }
      std::set<std::string> seen;
      for (size_t k = i; k < end; ++k) {
        if (page[k].find("<!--") != std::string::npos) continue;
        // outside inline code
        const std::string text = std::regex_replace(page[k], inlineCode, "``");
        size_t variesEnd = std::string::npos;  // where the last "~" figure on the line ends
        for (std::sregex_iterator it(text.begin(), text.end(), number), stop; it != stop; ++it) {
          size_t at = it->position(0);
          const size_t after = at + it->length(0);
          std::string figure = it->str();
          auto word = [&](size_t p) {
            return std::isalnum(static_cast<unsigned char>(text[p])) || text[p] == '_' || text[p] == '.';
          };
          // "2-3.4e-2" is a range: its "-" a dash, not a sign
          if ((figure[0] == '-' || figure[0] == '+') && at > 0 && word(at - 1)) {
            figure.erase(0, 1);
            ++at;
          }
          const bool eForm = figure.find_first_of("eE") != std::string::npos;
          const bool decimal = !eForm && figure.find('.') != std::string::npos;
          if (!eForm && !decimal) continue;  // an integer
          // a sentence's full stop after a figure is not part of it, nor a ratio's "x" ("2.6x")
          const bool fullStop = after + 1 >= text.size() || (text[after] == '.' && !word(after + 1));
          const bool ratio =
              decimal && after < text.size() && text[after] == 'x' && (after + 1 >= text.size() || !word(after + 1));
          if ((at > 0 && word(at - 1)) || (after < text.size() && word(after) && !fullStop && !ratio))
            continue;  // part of a name ("v1.2", "PoCL's 3.1-dev", "x86_64")
          if (figure[0] == '+') figure.erase(0, 1);
          seen.insert(figure);
          const bool isTied = (rows && page[k].rfind("|", 0) == 0) || noted.count(figure) || noted.count("-" + figure);
          const std::string between = variesEnd == std::string::npos ? "" : text.substr(variesEnd, at - variesEnd);
          if (isTied) {
            ++counts["tied"];
          } else if ((at > 0 && text[at - 1] == '~') || between == " to " || between == "-") {
            ++counts["varies"];
            variesEnd = after;
          } else if (listed.count(figure)) {
            ++counts[listed[figure]];
          } else {
            ADD_FAILURE()
                << name << ":" << k + 1 << ": " << figure
                << " is neither tied (a figure or rows note), marked ~, nor in its paragraph's "
                << "<!-- inputs: ... -->, <!-- once: ... -->, <!-- elsewhere: ... --> or a <!-- ratio ... --> note\n  "
                << page[k];
          }
        }
      }
      for (const auto& [f, kind] : listed) {
        EXPECT_TRUE(seen.count(f)) << name << ":" << i + 1 << ": the " << kind << " note lists " << f
                                   << ", which its paragraph does not hold";
        EXPECT_FALSE(noted.count(f)) << name << ":" << i + 1 << ": " << f << " is both tied and in the " << kind
                                     << " note";
      }
      i = end;
    }
  }
  std::printf(
      "every page: each figure in e-notation or with a decimal point tied (%d), a ratio of two tied (%d), an input "
      "(%d), marked ~ (%d), measured once (%d) or measured elsewhere (%d)\n",
      counts["tied"], counts["ratio"], counts["inputs"], counts["varies"], counts["once"], counts["elsewhere"]);
  EXPECT_GE(counts["tied"], 100);
}

// `brdfbake-bench --bounds --tables` (docs/accuracy.md's charlie rows use it) measures the rows
// named, in the benchmark's order, and refuses a name it does not know with exit 64, naming the
// accepted ones.
TEST(Bench, BoundsTablesPicksTheRowsAndRefusesOthers) {
  const fs::path d = freshDir("readme", "bench-tables");
  const std::string bench =
      "cd '" + d.string() + "' && '" BRDFBAKE_BINARY_DIR "/brdfbake-bench' --bounds --size 8 --stride 4";
  const CmdResult r = shell(bench + " --pair ggx+smith-correlated --tables kp,splitsum");
  ASSERT_EQ(r.code, 0) << r.out;
  const std::regex row("^\\| (\\S+) \\| (\\S+) \\| \\d");  // a body row: its pair and table
  std::vector<std::string> rows;
  for (const std::string& l : lines(r.out))
    if (std::smatch m; std::regex_search(l, m, row)) rows.push_back(m[1].str() + " " + m[2].str());
  EXPECT_EQ(rows, (std::vector<std::string>{"ggx+smith-correlated splitsum", "ggx kp"})) << r.out;
  const CmdResult bad = shell(bench + " --tables splitsum,albdo");
  EXPECT_EQ(bad.code, 64) << bad.out;
  EXPECT_NE(bad.out.find("--tables: comma-separated, each of splitsum, albedo, albedo-avg, kp; got \"splitsum,albdo\""),
            std::string::npos)
      << bad.out;
}

// Every build-tree path a page or the README names (`./build/tests/brdfbake-gl-tests`,
// `build/brdfbake-bench`) is in this build, under build/ (the directory the README's commands make),
// so that a reader who runs it finds it.
TEST(Docs, NamedBuildPathsExist) {
  const std::regex path("(?:^|[\\s`'(])(?:\\./)?(build[\\w-]*)/([\\w./-]*[\\w-])");
  int named = 0;
  for (const fs::path& page : pages()) {
    const std::string text = bytes(page);
    for (std::sregex_iterator it(text.begin(), text.end(), path), end; it != end; ++it) {
      const std::string dir = (*it)[1].str(), rest = (*it)[2].str();
      ++named;
      EXPECT_EQ(dir, "build") << page.filename() << ": " << dir << "/" << rest << " is not under build/";
      // the binaries the default build makes (a generator built by its own --target is not one)
      if (rest.rfind("tests/brdfbake-", 0) == 0 || rest == "brdfbake" || rest == "brdfbake-bench") {
        EXPECT_TRUE(fs::exists(fs::path(BRDFBAKE_BINARY_DIR) / rest))
            << page.filename() << ": build/" << rest << " is not in this build";
      }
    }
  }
  EXPECT_GE(named, 20);
  std::printf("%d build-tree paths on the pages\n", named);
}
