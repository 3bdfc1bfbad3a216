// One writer per output directory and a commit that lands whole (formats/commit_record.h): a second
// bake waits for the first (or exits 75 with --no-wait), two racing bakes end in one run's complete
// set, and a bake killed at any step of its commit is finished by the next one, leaving the
// directory byte-identical to an uninterrupted bake's and free of hidden files.
// Test hooks: BRDFBAKE_TEST_HOLD_BEFORE_COMMIT_MS (hold with every temporary written),
// BRDFBAKE_TEST_RENAME_DELAY_MS (pause between renames), BRDFBAKE_TEST_KILL_AT (SIGKILL at a step).
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <future>
#include <map>
#include <thread>

#include "cli_run.h"

namespace fs = std::filesystem;
using namespace brdfbake::testing_cli;

namespace {

// name -> bytes of every entry (hidden ones included)
std::map<std::string, std::string> contents(const fs::path& d) {
  std::map<std::string, std::string> m;
  for (const auto& e : fs::directory_iterator(d)) m[e.path().filename().string()] = bytes(e.path());
  return m;
}

std::vector<std::string> hidden(const fs::path& d) {
  std::vector<std::string> h;
  for (const auto& e : fs::directory_iterator(d))
    if (e.path().filename().string()[0] == '.') h.push_back(e.path().filename().string());
  return h;
}

// A PID no process has: a child's, reaped.
pid_t deadPid() {
  const pid_t c = ::fork();
  if (c == 0) ::_exit(0);
  ::waitpid(c, nullptr, 0);
  return c;
}

const char* const kSmall = "--table splitsum,albedo,albedo-avg,kp --size 8";
const char* const kOther = "--table splitsum,albedo,albedo-avg,kp --size 16";

}  // namespace

TEST(Commit, SecondWriterWaitsOrExits75) {
  const fs::path d = freshDir("commit", "lock");
  ASSERT_EQ(run(std::string(kOther) + " -o ref16", d.string()).code, 0);
  auto first = std::async(std::launch::async, [&] {
    return run(std::string(kSmall) + " -o o", d.string(), "BRDFBAKE_TEST_HOLD_BEFORE_COMMIT_MS=4000");
  });
  // the first holds the lock once its temporaries exist
  for (int i = 0; i < 200; ++i) {
    bool temps = fs::exists(d / "o") && !hidden(d / "o").empty();
    if (temps) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  CmdResult busy = run(std::string(kOther) + " -o o --no-wait", d.string());
  EXPECT_EQ(busy.code, 75) << busy.out;
  EXPECT_NE(busy.out.find("-o o: another bake is writing there (PID "), std::string::npos) << busy.out;
  EXPECT_NE(busy.out.find("--size 8 -o o)"), std::string::npos) << "names the holder's command: " << busy.out;
  CmdResult waited = run(std::string(kOther) + " -o o", d.string());
  EXPECT_EQ(waited.code, 0) << waited.out;
  EXPECT_NE(waited.out.find("brdfbake: waiting for o: another bake is writing there"), std::string::npos) << waited.out;
  EXPECT_EQ(first.get().code, 0);
  // the waiting bake committed last: its whole set, nothing of the first, no hidden files
  EXPECT_EQ(contents(d / "o"), contents(d / "ref16"));
}

TEST(Commit, RacingWritersEndInOneCompleteSet) {
  const fs::path d = freshDir("commit", "race");
  ASSERT_EQ(run(std::string(kSmall) + " -o ref8", d.string()).code, 0);
  ASSERT_EQ(run(std::string(kOther) + " -o ref16", d.string()).code, 0);
  // a pause between renames makes an unlocked interleaving certain
  const std::string env = "BRDFBAKE_TEST_RENAME_DELAY_MS=300";
  auto a = std::async(std::launch::async, [&] { return run(std::string(kSmall) + " -o o", d.string(), env); });
  auto b = std::async(std::launch::async, [&] { return run(std::string(kOther) + " -o o", d.string(), env); });
  EXPECT_EQ(a.get().code, 0);
  EXPECT_EQ(b.get().code, 0);
  const auto got = contents(d / "o");
  EXPECT_TRUE(got == contents(d / "ref8") || got == contents(d / "ref16")) << "a mix of two runs' files";
}

TEST(Commit, KilledCommitIsFinishedByTheNextBake) {
  const fs::path d = freshDir("commit", "kill");
  ASSERT_EQ(run(std::string(kSmall) + " -o ref", d.string()).code, 0);
  const auto ref = contents(d / "ref");
  ASSERT_EQ(ref.size(), 4u);
  for (const std::string step : {"record", "rename:1", "rename:2", "rename:3", "rename:4", "renamed"}) {
    fs::remove_all(d / "o");
    ASSERT_EQ(run(std::string(kOther) + " -o o", d.string()).code, 0);  // files to replace
    CmdResult killed = run(std::string(kSmall) + " -o o", d.string(), "BRDFBAKE_TEST_KILL_AT=" + step);
    EXPECT_NE(killed.code, 0) << step;
    EXPECT_FALSE(hidden(d / "o").empty()) << step << ": the kill left nothing to recover";
    CmdResult next = run(std::string(kSmall) + " -o o", d.string());
    EXPECT_EQ(next.code, 0) << step << "\n" << next.out;
    EXPECT_NE(next.out.find("finished the commit of a bake that was killed"), std::string::npos) << step << next.out;
    EXPECT_EQ(contents(d / "o"), ref) << step;
    EXPECT_TRUE(hidden(d / "o").empty()) << step;
  }
  // a kill before the record (temporaries only): swept, as they carry a PID that is gone
  fs::remove_all(d / "o");
  fs::create_directory(d / "o");
  const std::string gone = std::to_string(deadPid());
  for (const std::string& n :
       {".kp_ggx.exr.brdfbake-tmp-" + gone + "-AbC123", ".kp_ggx.exr.brdfbake-tmp-" + gone + "-AbC123.old"})
    std::ofstream(d / "o" / n) << "partial";
  std::ofstream(d / "o" / ".mine") << "not ours";
  ASSERT_EQ(run(std::string(kSmall) + " -o o", d.string()).code, 0);
  EXPECT_EQ(hidden(d / "o"), std::vector<std::string>{".mine"});
}

// A sweep removes only what it can prove its own: its marker with the PID of a process that is
// gone. Names that merely look like a temporary (a user's `.notes.tmp-123`, the marker without a
// PID) and a live process's temporary (a writer in progress) stay, byte for byte.
TEST(Commit, ASweepRemovesOnlyWhatIsProvablyOurs) {
  const fs::path d = freshDir("commit", "ownership");
  fs::create_directories(d / "o");
  const std::string gone = std::to_string(deadPid()), live = std::to_string(::getpid());
  const std::vector<std::string> keep = {".notes.tmp-123",
                                         ".notes.tmp-123.old",
                                         ".x.exr.brdfbake-tmp-AbC123",
                                         ".x.exr.brdfbake-tmp-" + live + "-AbC123",
                                         ".x.exr.brdfbake-tmp-" + gone + "-toolong1",
                                         ".brdfbake-tmp-" + gone + "-AbC123"};
  for (const std::string& n : keep) std::ofstream(d / "o" / n) << "keep " << n;
  std::ofstream(d / "o" / (".kp_ggx.exr.brdfbake-tmp-" + gone + "-Zz9Yy8")) << "a killed bake's";
  fs::create_directories(d / "o" / (".notes.brdfbake-tmp-" + gone + "-AbC123"));  // a directory, not a page's
  CmdResult r = run("bake --table kp -o o", d.string());
  ASSERT_EQ(r.code, 0) << r.out;
  std::vector<std::string> want = keep;
  want.push_back(".notes.brdfbake-tmp-" + gone + "-AbC123");
  std::vector<std::string> got = hidden(d / "o");
  std::sort(want.begin(), want.end());
  std::sort(got.begin(), got.end());
  EXPECT_EQ(got, want);
  for (const std::string& n : keep) EXPECT_EQ(bytes(d / "o" / n), "keep " + n);
}

// Where the file system has no hard links, the commit keeps its backups as copies: a rebake over
// an existing set lands as on any other file system.
TEST(Commit, NoHardLinksFallsBackToACopy) {
  const fs::path d = freshDir("commit", "nolinks");
  ASSERT_EQ(run(std::string(kOther) + " -o o", d.string()).code, 0);
  CmdResult r = run(std::string(kSmall) + " -o o", d.string(), "BRDFBAKE_TEST_NO_HARDLINKS=1");
  ASSERT_EQ(r.code, 0) << r.out;
  ASSERT_EQ(run(std::string(kSmall) + " -o ref", d.string()).code, 0);
  EXPECT_EQ(contents(d / "o"), contents(d / "ref"));
}

// A report killed while writing its page leaves a temporary directory beside it; the next bake
// there sweeps it (under the lock, as it sweeps a killed bake's files) instead of failing on it.
TEST(Commit, AKilledReportsTemporaryDirectoryIsSwept) {
  const fs::path d = freshDir("commit", "report");
  const fs::path page = d / "o" / (".verify.brdfbake-tmp-" + std::to_string(deadPid()) + "-AbC123");
  fs::create_directories(page);
  std::ofstream(page / "index.html") << "<html>";
  CmdResult r = run("bake --table kp -o o", d.string());
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_TRUE(hidden(d / "o").empty()) << r.out;
  EXPECT_TRUE(fs::exists(d / "o/kp_ggx.exr"));
}

// A killed bake's temporaries are swept by `bake SCENE --prune` even when every table is up to
// date and nothing else is written (under the directory's lock, as a bake sweeps them).
TEST(Commit, PruneSweepsAKilledBakesTemporaries) {
  const fs::path d = freshDir("commit", "prune");
  const std::string scene = (fs::path(BRDFBAKE_SOURCE_DIR) / "examples/scenes/forward-mobile.toml").string();
  CmdResult r = run("bake '" + scene + "' -o o", d.string());
  ASSERT_EQ(r.code, 0) << r.out;
  // a bake killed with every temporary written, before its commit record
  CmdResult killed = run("bake '" + scene + "' -o o --force", d.string(), "BRDFBAKE_TEST_KILL_AT=record");
  EXPECT_NE(killed.code, 0) << killed.out;
  ASSERT_FALSE(hidden(d / "o").empty()) << "the kill left no temporary";
  r = run("bake '" + scene + "' -o o", d.string());
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("nothing written"), std::string::npos) << r.out;
  EXPECT_FALSE(hidden(d / "o").empty()) << "a bake that writes nothing leaves the directory alone";
  r = run("bake '" + scene + "' -o o --prune", d.string());
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_TRUE(hidden(d / "o").empty()) << r.out;
}
