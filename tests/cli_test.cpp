// The brdfbake command as a user runs it: the default bake, files read back, bad input, exit codes,
// interrupted and failing writes.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "browser_check.h"
#include "cli_run.h"
#include "common/brdf_host.h"
#include "formats/exr/table_file.h"
#include "reference/reference.h"

namespace fs = std::filesystem;
namespace {
using namespace brdfbake::testing_cli;
fs::path freshDir(const std::string& name) { return brdfbake::testing_cli::freshDir("cli", name); }

// One default bake shared by the tests that read its files.
const fs::path& defaultBake() {
  static fs::path dir;
  if (dir.empty()) {
    dir = freshDir("default");
    CmdResult r = run("", dir.string());
    EXPECT_EQ(r.code, 0) << r.out;
  }
  return dir;
}

TEST(Cli, DefaultBakeWritesTheFourTablesIntoOut) {
  fs::path out = defaultBake() / "out";
  for (const char* f : {"splitsum_ggx_smith-correlated.exr", "albedo_ggx_smith-correlated.exr",
                        "albedo-avg_ggx_smith-correlated.exr", "kp_ggx.exr"}) {
    ASSERT_TRUE(fs::exists(out / f)) << f;
    // every default-size table claims at most 1e-5 (tests/tables/microfacet/accuracy_test.cpp checks it is honest)
    float claim = brdfbake::readTableExr((out / f).string()).floats["brdf.error"];
    EXPECT_GT(claim, 0.0f) << f;
    EXPECT_LE(claim, 1e-5f) << f;
  }
  EXPECT_EQ(countFiles(out), 4u);  // no temporary files left
}

TEST(Cli, SplitSumFileReadsBackWithItsAttributes) {
  brdfbake::TableImage t = brdfbake::readTableExr((defaultBake() / "out/splitsum_ggx_smith-correlated.exr").string());
  EXPECT_EQ(t.width, 128);
  EXPECT_EQ(t.height, 128);
  EXPECT_EQ(t.channels, (std::vector<std::string>{"R", "G", "B"}));
  EXPECT_EQ(t.strings["brdf.schema"], "brdfbake/1");
  EXPECT_EQ(t.strings["brdf.table"], "splitsum");
  EXPECT_EQ(t.strings["brdf.ndf"], "ggx");
  EXPECT_EQ(t.strings["brdf.gaf"], "smith-correlated");
  EXPECT_EQ(t.strings["brdf.fresnel"], "schlick");
  EXPECT_EQ(t.strings["brdf.axes"], "mu,r");
  EXPECT_EQ(t.strings["brdf.grid"], "texel-center");
  EXPECT_EQ(t.strings["brdf.roughness"], "alpha=r^2");
  EXPECT_EQ(t.strings["brdf.channels"], "R=A,G=B,B=A+B");
  EXPECT_FALSE(t.strings["brdf.method"].empty());
  EXPECT_NE(t.strings["brdf.generator"].find("brdfbake"), std::string::npos);
  EXPECT_EQ(t.v2f["brdf.mu.range"], std::make_pair(0.0f, 1.0f));
  EXPECT_EQ(t.v2f["brdf.r.range"], std::make_pair(0.0f, 1.0f));
  ASSERT_EQ(t.floats.count("brdf.error"), 1u);
  EXPECT_GT(t.floats["brdf.error"], 0.0f);
  EXPECT_LE(t.floats["brdf.error"], 1e-5f) << "default accuracy goal";
  for (size_t k = 0; k < t.planes[0].size(); ++k) {
    float a = t.planes[0][k], b = t.planes[1][k], e = t.planes[2][k];
    ASSERT_TRUE(std::isfinite(a) && std::isfinite(b) && std::isfinite(e));
    EXPECT_NEAR(a + b, e, 3e-7);
    EXPECT_GE(a, 0.0f);
    EXPECT_GE(b, 0.0f);
    EXPECT_LE(e, 1.0f + 1e-5f);  // energy conservation
  }
  // texel (x=127, y=0): mu = 255/256, r = 1/256: a near-mirror at normal incidence reflects all
  EXPECT_NEAR(t.planes[2][127], 1.0, 1e-5);
}

TEST(Cli, OneDimensionalTablesAreNByOne) {
  for (const char* f : {"albedo-avg_ggx_smith-correlated.exr", "kp_ggx.exr"}) {
    brdfbake::TableImage t = brdfbake::readTableExr((defaultBake() / "out" / f).string());
    EXPECT_EQ(t.width, 32);
    EXPECT_EQ(t.height, 1);
    EXPECT_EQ(t.strings["brdf.axes"], "r");
    EXPECT_EQ(t.v2f.count("brdf.mu.range"), 0u);
  }
  brdfbake::TableImage kp = brdfbake::readTableExr((defaultBake() / "out/kp_ggx.exr").string());
  for (int j = 0; j < 32; ++j) {
    double r = (j + 0.5) / 32, a = r * r;
    EXPECT_NEAR(kp.planes[0][j], 3.14159265358979 * a * a, 1e-6 * std::max(1.0, a));
  }
}

TEST(Cli, SameInputSameBytes) {
  fs::path d = freshDir("determinism");
  ASSERT_EQ(run("bake --table albedo,kp --size 16 -o '" + (d / "a").string() + "'").code, 0);
  ASSERT_EQ(run("bake --table albedo,kp --size 16 -o '" + (d / "b").string() + "'").code, 0);
  for (const char* f : {"albedo_ggx_smith-correlated.exr", "kp_ggx.exr"})
    EXPECT_EQ(bytes(d / "a" / f), bytes(d / "b" / f)) << f;
}

TEST(Cli, ProductOfModelsAndHalfOutput) {
  fs::path d = freshDir("product");
  CmdResult r = run("bake --ndf beckmann,gaussian --gaf smith --gaf kelemen --table albedo --size 8 --half -o '" +
                    d.string() + "'");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(countFiles(d), 4u);
  std::string f = (d / "albedo_gaussian_kelemen.exr").string();
  EXPECT_TRUE(brdfbake::tableExrIsHalf(f));
  brdfbake::TableImage t = brdfbake::readTableExr(f);
  EXPECT_GE(t.floats["brdf.error"], 1e-4f) << "half quantisation must be part of the bound";
}

TEST(Cli, NodeGridSamplesTheEdges) {
  fs::path d = freshDir("node");
  ASSERT_EQ(run("bake --table albedo --grid node --size 5 -o '" + d.string() + "'").code, 0);
  brdfbake::TableImage t = brdfbake::readTableExr((d / "albedo_ggx_smith-correlated.exr").string());
  EXPECT_EQ(t.strings["brdf.grid"], "node");
  // r = 0 row: a perfect mirror, E = 1 at every mu > 0 (smith G = 1 there)
  for (int i = 1; i < 5; ++i) EXPECT_NEAR(t.planes[0][i], 1.0, 1e-6);
}

struct BadCase {
  const char* args;
  int code;
  const char* message;
};

TEST(Cli, BadInputGetsAClearErrorAndNothingIsWritten) {
  fs::path d = freshDir("bad");
  fs::path file = d / "a-file";
  std::ofstream(file) << "x";
  std::string o = " -o '" + (d / "out").string() + "'";
  const BadCase cases[] = {
      {"bake --ndf phong", 64, "--ndf: unknown NDF 'phong'; valid: ggx, beckmann, blinn-phong, gaussian"},
      {"bake --gaf smyth", 64, "valid: none, implicit, cook-torrance"},
      {"bake --table lookup", 64, "--table: unknown table 'lookup'; valid: splitsum, albedo, albedo-avg, kp"},
      {"bake --size 0", 64, "--size must be an integer in 1..8192, got 0"},
      {"bake --size -5", 64, "--size must be an integer in 1..8192, got -5"},
      {"--size=-5", 64, "--size must be an integer in 1..8192, got -5"},
      {"bake --size 32 --size 64", 64, "--size given twice; give it once"},
      {"--size=32 --size 64", 64, "--size given twice; give it once"},
      {"-o a --output b", 64, "--output given twice; give it once"},
      {"bake --size 8193", 64, "1..8192"},
      {"bake --size 12x", 64, "--size"},
      {"bake --grid corner", 64, "--grid must be texel-center or node, got 'corner'"},
      {"bake --gaf none --grid node --table albedo", 64, "infinite albedo at mu = 0"},
      {"bake --device no-such-device", 69, "--device: no OpenCL device or platform name contains 'no-such-device'"},
      {"frobnicate", 64, "unknown command 'frobnicate'"},
      {"bake --ndf", 64, "--ndf: missing value"},
  };
  for (const auto& c : cases) {
    CmdResult r = run(std::string(c.args) + o);
    EXPECT_EQ(r.code, c.code) << c.args << "\n" << r.out;
    EXPECT_NE(r.out.find(c.message), std::string::npos) << c.args << "\n" << r.out;
    EXPECT_FALSE(fs::exists(d / "out")) << c.args << ": a run that fails before it writes creates nothing";
  }
  // an output "directory" that is a file, and one below a file
  CmdResult r = run("bake --table kp -o '" + file.string() + "'");
  EXPECT_EQ(r.code, 73) << r.out;
  EXPECT_NE(r.out.find("not a directory"), std::string::npos) << r.out;
  r = run("bake --table kp -o '" + (file / "sub").string() + "'");
  EXPECT_EQ(r.code, 73) << r.out;
  EXPECT_NE(r.out.find("exists and is not a directory"), std::string::npos) << r.out;
  EXPECT_EQ(countFiles(d), 1u);
}

// Every regular file under d with its bytes: what "the output directory is as it was" compares.
std::map<std::string, std::string> snapshot(const fs::path& d) {
  std::map<std::string, std::string> m;
  if (!fs::exists(d)) return m;
  for (auto& e : fs::recursive_directory_iterator(d))
    if (e.is_regular_file()) m[fs::relative(e.path(), d).string()] = bytes(e.path());
  return m;
}

// Starts brdfbake with `args` (and an extra environment variable), returns its pid.
pid_t spawn(const std::vector<std::string>& args, const std::string& envName = "", const std::string& envValue = "") {
  pid_t pid = fork();
  if (pid == 0) {
    if (!envName.empty()) setenv(envName.c_str(), envValue.c_str(), 1);
    std::vector<char*> argv{const_cast<char*>(BRDFBAKE_EXE)};
    for (auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    freopen("/dev/null", "w", stdout);
    execv(BRDFBAKE_EXE, argv.data());
    _exit(127);
  }
  return pid;
}
int exitCode(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 1000 + WTERMSIG(status);
}

// A full disk: a 200 KiB tmpfs, mounted in a private mount namespace (needs root, as CI has). The
// earlier outputs and the small tables fit; the 128x128 float split-sum (~190 KB) does not, which
// the free-space check before the first write finds.
TEST(Cli, DiskFullMidBakeLeavesEarlierOutputsUntouched) {
  fs::path d = freshDir("full");
  fs::create_directories(d / "disk");
  std::string exe = BRDFBAKE_EXE, disk = (d / "disk").string(), rep = (d / "report").string();
  std::ofstream(d / "t.sh") << "set -u\n"
                               "mount -t tmpfs -o size=200k tmpfs '"
                            << disk
                            << "' || { echo 'cannot mount a tmpfs (root needed)'; exit 99; }\n"
                               "'"
                            << exe << "' --table kp,albedo,splitsum --size 8 -o '" << disk
                            << "/out' > /dev/null || exit 98\n"
                               "list() { (cd '"
                            << disk
                            << "' && find . -type f | sort | xargs sha256sum); }\n"
                               "list > '"
                            << rep
                            << ".before'\n"
                               "'"
                            << exe << "' --table kp,albedo,splitsum -o '" << disk << "/out'; echo $? > '" << rep
                            << ".rc'\n"
                               "list > '"
                            << rep
                            << ".after'\n"
                               "'"
                            << exe << "' --table kp,albedo,splitsum -o '" << disk << "/new/sub'; echo $? > '" << rep
                            << ".rc2'\n"
                               "test -e '"
                            << disk << "/new' && echo left > '" << rep
                            << ".new'\n"
                               "'"
                            << exe << "' --table brdf3d -o '" << disk << "/vol'; echo $? > '" << rep
                            << ".rc3'\n"
                               "exit 0\n";
  const CmdResult r = shell("unshare -m sh '" + (d / "t.sh").string() + "'");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(bytes(rep + ".rc"), "74\n") << r.out;
  // a 3D table short of space: the same code as the 2D tables'
  EXPECT_EQ(bytes(rep + ".rc3"), "74\n") << r.out;
  EXPECT_NE(r.out.find("not enough space for the brdf3d table(s) in " + disk + "/vol"), std::string::npos) << r.out;
  // refused before the first temporary: the set's bound (raw texels plus 64 KiB a file) exceeds the free space
  EXPECT_NE(r.out.find("-o " + disk + "/out: not enough space: the 3 file(s) may need up to"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("nothing was written"), std::string::npos) << r.out;
  const std::string before = bytes(rep + ".before");
  EXPECT_EQ(std::count(before.begin(), before.end(), '\n'), 3) << before;
  EXPECT_EQ(bytes(rep + ".after"), bytes(rep + ".before")) << "a failed bake changed the output directory";
  EXPECT_EQ(bytes(rep + ".rc2"), "74\n") << r.out;
  EXPECT_FALSE(fs::exists(rep + ".new")) << "a failed bake left the directory it created";
}

TEST(Cli, InterruptDuringComputeLeavesNothing) {
  fs::path d = freshDir("sigint");
  // a table that takes seconds to compute
  pid_t pid = spawn({"--table", "splitsum", "--size", "2048", "-o", (d / "out").string()});
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  kill(pid, SIGINT);
  EXPECT_EQ(exitCode(pid), 130);
  EXPECT_FALSE(fs::exists(d / "out"));
}

TEST(Cli, InterruptWhileWritingLeavesTheDirectoryAsItWas) {
  fs::path d = freshDir("sigterm");
  fs::path out = d / "out";
  CmdResult r = run("--table kp,albedo --size 8 -o '" + out.string() + "'");
  ASSERT_EQ(r.code, 0) << r.out;
  auto before = snapshot(d);
  // hold after the temporaries are written, before they are renamed; interrupt there
  pid_t pid =
      spawn({"--table", "kp,albedo,albedo-avg", "-o", out.string()}, "BRDFBAKE_TEST_HOLD_BEFORE_COMMIT_MS", "20000");
  bool temps = false;
  for (int k = 0; k < 600 && !temps; ++k) {  // until all three temporaries exist (at most 60 s)
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    int n = 0;
    for (const auto& e : fs::directory_iterator(out))
      n += e.path().filename().string().find(".brdfbake-tmp-") != std::string::npos;
    temps = n == 3;
  }
  EXPECT_TRUE(temps) << "the temporaries never appeared";
  kill(pid, SIGTERM);
  EXPECT_EQ(exitCode(pid), 143);
  EXPECT_EQ(snapshot(d), before) << "temporaries or partial outputs left behind";
}

TEST(Cli, GnuStyleOptionsParentsAndTopLevelOptions) {
  fs::path d = freshDir("gnu");
  // --opt=value, bake options without `bake`, -o with missing parents
  CmdResult r = run("--ndf=beckmann --table=kp --size=4 --output='" + (d / "a/b/c").string() + "'");
  ASSERT_EQ(r.code, 0) << r.out;
  brdfbake::TableImage t = brdfbake::readTableExr((d / "a/b/c/kp_beckmann.exr").string());
  EXPECT_EQ(t.width, 4);
  EXPECT_EQ(t.strings["brdf.ndf"], "beckmann");
  // the report's columns line up: every line has "table" at the same column
  r = run("bake --ndf blinn-phong --gaf schlick-ggx-direct --table albedo-avg,kp --size 4 -o '" + (d / "x").string() +
          "'");
  ASSERT_EQ(r.code, 0) << r.out;
  std::istringstream lines(r.out);
  std::string line;
  std::vector<size_t> col;
  while (std::getline(lines, line))
    if (line.rfind("  + ", 0) != 0) col.push_back(line.find_first_not_of(' ', line.find(' ')));
  ASSERT_EQ(col.size(), 3u) << r.out;
  // below the rows, the program build the user also waited for (the rows' seconds are kernel time)
  EXPECT_NE(r.out.find(" s making the OpenCL programs ready before the first table ("), std::string::npos) << r.out;
  EXPECT_EQ(col[0], col[1]) << r.out;
  EXPECT_EQ(col[1], col[2]) << r.out;
}

TEST(Cli, CacheDirHoldsTheCompiledKernels) {
  fs::path d = freshDir("cache");
  CmdResult r =
      run("--table kp --size 4 --cache-dir '" + (d / "cache").string() + "' -o '" + (d / "out").string() + "'");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_GT(countFiles(d / "cache"), 0u) << "PoCL did not use --cache-dir";
}

TEST(Cli, NoOpenClPlatformNamesThePackage) {
  fs::path d = freshDir("noplatform");
  CmdResult r =
      run("bake --table kp -o '" + (d / "out").string() + "'", "", "OCL_ICD_VENDORS=/nonexistent OCL_ICD_FILENAMES=");
  EXPECT_EQ(r.code, 69) << r.out;
  EXPECT_NE(r.out.find("pocl-opencl-icd"), std::string::npos) << r.out;
  EXPECT_EQ(countFiles(d), 0u);
  EXPECT_FALSE(fs::exists(d / "out"));
}

TEST(Cli, InfoHelpVersionDevices) {
  CmdResult r = run("info '" + (defaultBake() / "out/albedo_ggx_smith-correlated.exr").string() + "'");
  EXPECT_EQ(r.code, 0);
  for (const char* s : {"brdf.error (float)", "brdf.table (string): albedo", "brdf.mu.range (v2f): (0, 1)", "32x32"})
    EXPECT_NE(r.out.find(s), std::string::npos) << s << "\n" << r.out;
  r = run("info /nonexistent/x.exr");
  EXPECT_EQ(r.code, 66);
  EXPECT_NE(r.out.find("cannot read /nonexistent/x.exr"), std::string::npos);
  r = run("--help");
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("usage:"), std::string::npos);
  r = run("--version");
  EXPECT_EQ(r.code, 0);
  EXPECT_EQ(r.out.rfind("brdfbake ", 0), 0u);
  r = run("devices");
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("CPU"), std::string::npos) << r.out;
}

}  // namespace

// --dry-run checks a bake's options as the bake does and prints what it would write: each table's
// size, texels, estimated seconds, whether its file is new or would be replaced, and the file (both
// of an LTC's); it computes nothing and creates nothing, -o's directory included. A request the
// bake refuses is refused the same way (exit 64).
TEST(Cli, DryRunListsWhatABakeWouldWriteAndWritesNothing) {
  const fs::path d = freshDir("cli", "dryrun");
  CmdResult r = run("--dry-run -o '" + (d / "tables").string() + "'");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_FALSE(fs::exists(d / "tables"));
  EXPECT_NE(r.out.find("dry run: 4 table(s) into " + (d / "tables").string() + "/, about "), std::string::npos)
      << r.out;
  for (const char* f : {"splitsum_ggx_smith-correlated.exr", "albedo_ggx_smith-correlated.exr",
                        "albedo-avg_ggx_smith-correlated.exr", "kp_ggx.exr"})
    EXPECT_NE(r.out.find("new       " + (d / "tables" / f).string()), std::string::npos) << f << "\n" << r.out;
  // after the bake, the same files would be replaced
  ASSERT_EQ(run("-o '" + (d / "tables").string() + "'").code, 0);
  const size_t files = countFiles(d / "tables");
  r = run("--dry-run -o '" + (d / "tables").string() + "'");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(r.out.find("new "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("replaces  " + (d / "tables" / "kp_ggx.exr").string()), std::string::npos) << r.out;
  EXPECT_EQ(countFiles(d / "tables"), files);
  // an LTC writes two files, both named; its estimate is the fit's
  r = run("--table ltc --dry-run -o '" + (d / "ltc").string() + "'");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find((d / "ltc" / "ltc1_ggx_smith-correlated.exr").string() + ", " +
                       (d / "ltc" / "ltc2_ggx_smith-correlated.exr").string()),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("19.7  new"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(d / "ltc"));
  // refused as the bake refuses it
  r = run("--table kp --fresnel schlick --dry-run -o '" + (d / "x").string() + "'");
  EXPECT_EQ(r.code, 64) << r.out;
  EXPECT_NE(r.out.find("--table kp is the NDF's normalisation"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(d / "x"));
}
