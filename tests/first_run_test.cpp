// The first run: program binaries kept and loaded (host/cl/program_cache.h) and never when stale
// or foreign, `devices` naming them, --timings' stages, the progress line on a terminal (a
// pseudo-terminal here) and nowhere else.
#include <gtest/gtest.h>
#include <pty.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "cli_run.h"

namespace fs = std::filesystem;
using namespace brdfbake::testing_cli;

namespace {

// Without the programs the build prepared: every test starts from a cache of its own.
const std::string kNoPrepared = "BRDFBAKE_PREPARED_PROGRAMS=off ";

// A bake of the default pair's albedo with a fresh PoCL cache and the program cache `programs`.
CmdResult bakeWith(const fs::path& d, const std::string& programs, const std::string& out,
                   const std::string& more = "") {
  return run("bake --table albedo --size 8 -o '" + (d / out).string() + "' " + more, d.string(),
             kNoPrepared + "POCL_CACHE_DIR='" + (d / ("pocl-" + out)).string() + "' BRDFBAKE_PROGRAM_CACHE='" +
                 programs + "'");
}

std::vector<fs::path> entries(const fs::path& dir) {
  std::vector<fs::path> v;
  if (fs::exists(dir))
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().extension() == ".clbin") v.push_back(e.path());
  return v;
}

// Runs brdfbake on a pseudo-terminal (stdout and stderr both on it); returns what it printed.
std::string runOnTerminal(const std::vector<std::string>& args, const fs::path& cwd, const std::string& poclCache) {
  int master = -1;
  pid_t pid = ::forkpty(&master, nullptr, nullptr, nullptr);
  if (pid == 0) {
    if (::chdir(cwd.c_str()) != 0) _exit(127);
    ::setenv("POCL_CACHE_DIR", poclCache.c_str(), 1);
    std::vector<char*> argv = {const_cast<char*>(BRDFBAKE_EXE)};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(BRDFBAKE_EXE, argv.data());
    _exit(127);
  }
  std::string out;
  char buf[4096];
  for (ssize_t n; (n = ::read(master, buf, sizeof buf)) > 0;) out.append(buf, static_cast<size_t>(n));  // EIO at exit
  ::close(master);
  int status = 0;
  ::waitpid(pid, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << out;
  return out;
}

}  // namespace

// A source build keeps its binary; the next bake, even with a fresh PoCL cache, loads it and writes
// the same bytes; with the cache off it compiles again, same bytes.
TEST(FirstRun, ASourceBuildKeepsItsBinaryAndTheNextBakeLoadsIt) {
  const fs::path d = freshDir("firstrun", "keep");
  const std::string programs = (d / "programs").string();
  CmdResult r = bakeWith(d, programs, "a");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("1 program compiled (its binary is kept: the next bake loads it)"), std::string::npos) << r.out;
  ASSERT_EQ(entries(programs).size(), 1u);
  r = bakeWith(d, programs, "b", "--timings");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("(1 program loaded from its kept binary)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("program  ggx + smith-correlated: loaded " + entries(programs)[0].string()), std::string::npos)
      << r.out;
  r = bakeWith(d, "off", "c");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("1 program compiled"), std::string::npos) << r.out;
  const std::string table = "albedo_ggx_smith-correlated.exr";
  EXPECT_EQ(bytes(d / "a" / table), bytes(d / "b" / table)) << "a loaded binary computes other bits";
  EXPECT_EQ(bytes(d / "a" / table), bytes(d / "c" / table));
}

// An entry is used only when its identity (platform, device, driver, options, source) matches byte
// for byte and its checksum holds: stale, foreign, torn and non-file entries are compiled around.
TEST(FirstRun, StaleForeignOrTornEntriesAreNeverLoaded) {
  const fs::path d = freshDir("firstrun", "stale");
  const std::string programs = (d / "programs").string();
  ASSERT_EQ(bakeWith(d, programs, "seed").code, 0);
  ASSERT_EQ(entries(programs).size(), 1u);
  const fs::path entry = entries(programs)[0];
  const std::string good = bytes(entry);
  struct Case {
    std::string name;
    std::string bytes;
  };
  std::string stale = good, foreign = good, torn = good;
  size_t src = stale.find("#line");  // the program's source, inside the stored identity
  ASSERT_NE(src, std::string::npos);
  stale[src + 1] = 'X';  // other sources, same length: a stale entry
  size_t dev = foreign.find("device: ");
  ASSERT_NE(dev, std::string::npos);
  foreign[dev + 8] ^= 0x20;        // another device's name
  torn[torn.size() - 20] ^= 0x01;  // a flipped bit in the binary: the checksum fails
  for (const Case& c : {Case{"stale", stale}, Case{"foreign", foreign}, Case{"torn", torn},
                        Case{"truncated", good.substr(0, good.size() / 2)}}) {
    std::ofstream(entry, std::ios::binary | std::ios::trunc) << c.bytes;
    CmdResult r = bakeWith(d, programs, c.name, "--timings");
    ASSERT_EQ(r.code, 0) << c.name << "\n" << r.out;
    EXPECT_NE(r.out.find("1 program compiled"), std::string::npos) << c.name << ": loaded\n" << r.out;
    EXPECT_NE(bytes(entry), c.bytes) << c.name << ": the compile did not replace the entry";
  }
  CmdResult again = bakeWith(d, programs, "again");
  EXPECT_NE(again.out.find("1 program loaded from its kept binary"), std::string::npos) << again.out;
  // a FIFO in an entry's place is passed over, not opened for a blocking read
  fs::remove(entry);
  ASSERT_EQ(::mkfifo(entry.c_str(), 0600), 0);
  CmdResult r = run("bake --table albedo --size 8 -o fifo", d.string(),
                    "timeout 60 env " + kNoPrepared + "POCL_CACHE_DIR='" + (d / "pocl-fifo").string() +
                        "' BRDFBAKE_PROGRAM_CACHE='" + programs + "'");
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("1 program compiled"), std::string::npos) << r.out;
}

// A cache that cannot be written costs a compile, never the bake.
TEST(FirstRun, AnUnwritableCacheIsNotAFailure) {
  const fs::path d = freshDir("firstrun", "unwritable");
  std::ofstream(d / "file") << "not a directory";
  CmdResult r = bakeWith(d, (d / "file" / "programs").string(), "a", "--timings");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("binary not stored: "), std::string::npos) << r.out;
  // and the summary says so, instead of promising that the next bake loads it
  EXPECT_NE(
      r.out.find("1 program compiled (its binary was not kept: --timings says why; the next bake compiles again)"),
      std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("the next bake loads"), std::string::npos) << r.out;
  EXPECT_TRUE(fs::exists(d / "a" / "albedo_ggx_smith-correlated.exr"));
}

// A store that was interrupted leaves its temporary; the next store sweeps it once its process is
// gone, and leaves a live process's (a store in progress) and names that only look like one.
TEST(FirstRun, InterruptedStoresAreSwept) {
  const fs::path d = freshDir("firstrun", "sweep");
  const fs::path programs = d / "programs";
  fs::create_directories(programs);
  const pid_t c = ::fork();
  if (c == 0) ::_exit(0);
  ::waitpid(c, nullptr, 0);
  const std::string gone = ".program.brdfbake-tmp-" + std::to_string(c) + "-AbC123";
  const std::string live = ".program.brdfbake-tmp-" + std::to_string(::getpid()) + "-AbC123";
  for (const std::string& n : {gone, live, std::string(".program.brdfbake-tmp-XyZ789")})
    std::ofstream(programs / n) << "torn";
  CmdResult r = bakeWith(d, programs.string(), "a");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_FALSE(fs::exists(programs / gone));
  EXPECT_TRUE(fs::exists(programs / live));
  EXPECT_TRUE(fs::exists(programs / ".program.brdfbake-tmp-XyZ789"));
  EXPECT_EQ(entries(programs).size(), 1u);
}

// `devices --prepare DIR` keeps the default set's and the shared program's binaries; `devices`
// names the programs ready for each device and where they are.
TEST(FirstRun, DevicesPreparesAndListsPrograms) {
  const fs::path d = freshDir("firstrun", "devices");
  const std::string env = kNoPrepared + "POCL_CACHE_DIR='" + (d / "pocl").string() + "' BRDFBAKE_PROGRAM_CACHE='" +
                          (d / "mine").string() + "'";
  CmdResult r = run("devices --prepare '" + (d / "prepared").string() + "'", "", env);
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("ggx + smith-correlated: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("every pair (the shared program): "), std::string::npos) << r.out;
  EXPECT_EQ(entries(d / "prepared").size(), 2u);
  EXPECT_EQ(entries(d / "mine").size(), 0u) << "--prepare writes only into its directory";
  // the user's cache is listed first; a bake fills it
  ASSERT_EQ(bakeWith(d, (d / "mine").string(), "a").code, 0);
  r = run("devices", "", env);
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("programs ready in " + (d / "mine").string() + ": 1 (ggx + smith-correlated)\n"),
            std::string::npos)
      << r.out;
  // an entry of other sources (one byte near the end of the program's source) is listed as stale
  ASSERT_EQ(entries(d / "mine").size(), 1u);
  const fs::path entry = entries(d / "mine")[0];
  std::string stale = bytes(entry);
  const size_t src = stale.rfind("#line");
  ASSERT_NE(src, std::string::npos);
  stale[src + 1] = 'X';
  std::ofstream(entry, std::ios::binary | std::ios::trunc) << stale;
  r = run("devices", "", env);
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("programs in " + (d / "mine").string() +
                       ": none ready, 1 stale (other sources or options: never loaded)"),
            std::string::npos)
      << r.out;
  r = run("devices --prepare", "", env);
  EXPECT_EQ(r.code, 64) << r.out;
  EXPECT_NE(r.out.find("--prepare: expected a directory"), std::string::npos) << r.out;
  r = run("devices --table albedo", "", env);
  EXPECT_EQ(r.code, 64) << r.out;
  EXPECT_NE(r.out.find("--table: not a devices option"), std::string::npos) << r.out;
}

// --timings: the device, each program, each table, the write and the total, on stderr; the report
// on stdout is the same as without it.
TEST(FirstRun, TimingsNameEveryStage) {
  const fs::path d = freshDir("firstrun", "timings");
  const std::string cmd =
      "cd '" + d.string() + "' && '" BRDFBAKE_EXE "' bake --timings -o out >report.txt 2>timings.txt";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << bytes(d / "timings.txt");
  const std::string t = bytes(d / "timings.txt");
  CmdResult r{0, bytes(d / "report.txt")};
  const std::vector<std::string> stages = {"timings (wall seconds):",
                                           "device   ",
                                           " (platforms listed in ",
                                           "program  ggx + smith-correlated: ",
                                           "table    out/splitsum_ggx_smith-correlated.exr",
                                           "table    out/kp_ggx.exr",
                                           "write    4 file(s) into out/",
                                           "total    since the command started"};
  size_t at = 0;
  for (const std::string& s : stages) {
    size_t k = t.find(s, at);
    EXPECT_NE(k, std::string::npos) << "missing or out of order: " << s << "\n" << t;
    if (k != std::string::npos) at = k;
  }
  EXPECT_TRUE(std::regex_search(t, std::regex(R"(\n +[0-9]+\.[0-9]{3}  table    out/albedo_)"))) << t;
  EXPECT_EQ(r.out.find("timings"), std::string::npos) << "stdout holds the report only:\n" << r.out;
  EXPECT_NE(r.out.find("out/albedo-avg_ggx_smith-correlated.exr"), std::string::npos) << r.out;
}

// On a terminal a table that runs over a second draws a progress line (texels done, elapsed, time
// left) and erases it; with --quiet, or when stderr is not a terminal, nothing of it is printed.
TEST(FirstRun, ProgressLineOnATerminalOnly) {
  const fs::path d = freshDir("firstrun", "progress");
  const std::string cache = (d / "pocl").string();
  const std::vector<std::string> big = {"bake", "--table", "splitsum", "--size", "768"};
  std::vector<std::string> args = big;
  args.insert(args.end(), {"-o", "tty"});
  std::string out = runOnTerminal(args, d, cache);
  EXPECT_TRUE(std::regex_search(
      out,
      std::regex(
          R"(\r\x1b\[Ktty/splitsum_ggx_smith-correlated\.exr: +[0-9]+% \([0-9]+ of 589824 texels\), [0-9.]+ s, about [0-9]+ s left)")))
      << out;
  EXPECT_NE(out.find("\r\x1b[Kfile "), std::string::npos) << "the line is erased before the report:\n" << out;
  args = big;
  args.insert(args.end(), {"-o", "quiet", "--quiet"});
  out = runOnTerminal(args, d, cache);
  EXPECT_EQ(out.find('%'), std::string::npos) << out;
  EXPECT_EQ(out.find("\x1b["), std::string::npos) << out;
  CmdResult r = run("bake --table splitsum --size 768 -o pipe", d.string(), "POCL_CACHE_DIR='" + cache + "'");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(r.out.find('\r'), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("texels"), std::string::npos) << r.out;
  EXPECT_EQ(bytes(d / "tty/splitsum_ggx_smith-correlated.exr"), bytes(d / "pipe/splitsum_ggx_smith-correlated.exr"))
      << "the banded launches compute other bits";
  // --progress: into the pipe too, as whole lines without escapes
  r = run("bake --table splitsum --size 1536 --progress -o forced", d.string(), "POCL_CACHE_DIR='" + cache + "'");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(r.out.find("\x1b["), std::string::npos) << r.out;
  EXPECT_TRUE(std::regex_search(
      r.out,
      std::regex(
          R"((^|\n)brdfbake: forced/splitsum_ggx_smith-correlated\.exr: +[0-9]+% \([0-9]+ of 2359296 texels\))")))
      << r.out;
  // a measured material's tables report through the same observer: nothing into a pipe (its rules
  // had printed a line a second whatever stderr was)
  ASSERT_EQ(run("bake --table brdf3d --format merl -o merl", d.string(), "POCL_CACHE_DIR='" + cache + "'").code, 0);
  r = run("bake --brdf merl:merl/brdf3d_ggx_smith-correlated.binary --table albedo --size 8 -o measured", d.string(),
          "POCL_CACHE_DIR='" + cache + "'");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(r.out.find("texels"), std::string::npos) << r.out;
}
