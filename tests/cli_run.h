// What the tests that run the brdfbake binary share: run it with arguments (stdout and stderr
// together, the exit status), a scratch directory per test process, a file's bytes, a directory's
// file count, a report page's verdict line.
// BRDFBAKE_EXE is the binary's path (tests/CMakeLists.txt defines it per test target).
#pragma once
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace brdfbake::testing_cli {

struct CmdResult {
  int code;
  std::string out;  // stdout and stderr
};

// A shell command line's output (stdout and stderr together) and exit status.
inline CmdResult shell(const std::string& line) {
  const std::string cmd = line + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  std::string out;
  std::array<char, 4096> buf;
  size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) out.append(buf.data(), n);
  int status = pclose(p);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

// brdfbake with `args`. `cwd`: the directory to run in ("" = the test's); `env`: assignments put
// before the command.
inline CmdResult run(const std::string& args, const std::string& cwd = "", const std::string& env = "") {
  return shell((cwd.empty() ? "" : "cd '" + cwd + "' && ") + env + " '" BRDFBAKE_EXE "' " + args);
}

// TempDir/brdfbake_<prefix>_<name>_<pid>, emptied; created unless `create` is false (tests that
// check a failing run creates nothing). ctest runs each test in its own process, maybe in parallel.
inline std::filesystem::path freshDir(const std::string& prefix, const std::string& name, bool create = true) {
  std::filesystem::path d =
      std::filesystem::path(testing::TempDir()) / ("brdfbake_" + prefix + "_" + name + "_" + std::to_string(getpid()));
  std::filesystem::remove_all(d);
  if (create) std::filesystem::create_directories(d);
  return d;
}

// The regular files under d (0 when d does not exist).
inline size_t countFiles(const std::filesystem::path& d) {
  if (!std::filesystem::exists(d)) return 0;
  size_t n = 0;
  for (auto& e : std::filesystem::recursive_directory_iterator(d)) n += e.is_regular_file();
  return n;
}

// A report page's first line under its title: the verdict.
inline std::string verdictLine(const std::string& html) {
  const size_t h1 = html.find("</h1>\n");
  if (h1 == std::string::npos) return "(no title)";
  const size_t at = h1 + 6;
  return html.substr(at, html.find('\n', at) - at);
}

inline std::string bytes(const std::filesystem::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

}  // namespace brdfbake::testing_cli
