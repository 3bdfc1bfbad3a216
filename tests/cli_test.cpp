// The brdfbake command as a user runs it: default bake, files read back, bad input, exit codes.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <map>
#include <thread>
#include <vector>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "browser_check.h"
#include "cli_run.h"
#include "common/brdf_host.h"
#include "formats/exr/table_file.h"
#include "reference/reference.h"

namespace fs = std::filesystem;
namespace {
// A report page's first line under its title: the verdict.
std::string verdictLine(const std::string& html) {
  const size_t h1 = html.find("</h1>\n");
  if (h1 == std::string::npos) return "(no title)";
  const size_t at = h1 + 6;
  return html.substr(at, html.find('\n', at) - at);
}

using brdfbake::testing_cli::bytes;
using brdfbake::testing_cli::CmdResult;
using brdfbake::testing_cli::run;
fs::path freshDir(const std::string& name) { return brdfbake::testing_cli::freshDir("cli", name); }

size_t countFiles(const fs::path& d) {
  if (!fs::exists(d)) return 0;
  size_t n = 0;
  for (auto& e : fs::recursive_directory_iterator(d)) n += e.is_regular_file();
  return n;
}

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
    // every default-size table claims at most 1e-5 (tests/accuracy_test.cpp checks it is honest)
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
  CmdResult r{0, ""};
  {
    std::string cmd = "unshare -m sh '" + (d / "t.sh").string() + "' 2>&1";
    FILE* p = popen(cmd.c_str(), "r");
    std::array<char, 4096> buf;
    size_t n;
    while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) r.out.append(buf.data(), n);
    int status = pclose(p);
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
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

namespace {

// --- whole materials: Fresnel, diffuse, the energy gate ------------------------------------------

TEST(CliMaterials, FresnelTablesRecordTheModelAndRgbParameters) {
  fs::path d = freshDir("fresnel");
  CmdResult r = run("--fresnel conductor --eta 0.18,0.42,1.37 --k 3.42,2.35,1.77 --size 8 -o " + (d / "o").string());
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(countFiles(d / "o"), 2u) << "albedo and albedo-avg only: kp has no Fresnel";
  brdfbake::TableImage t = brdfbake::readTableExr(
      (d / "o/albedo_ggx_smith-correlated_conductor-eta0.18_0.42_1.37-k3.42_2.35_1.77.exr").string());
  EXPECT_EQ(t.strings["brdf.fresnel"], "conductor");
  EXPECT_EQ(t.strings["brdf.fresnel.eta"], "0.18,0.42,1.37");
  EXPECT_EQ(t.strings["brdf.fresnel.k"], "3.42,2.35,1.77");
  EXPECT_EQ(t.strings["brdf.channels"].rfind("R,G,B=E_F", 0), 0u) << t.strings["brdf.channels"];
  // F_avg per channel, the gold of the parameters: a conductor reflects most in red
  EXPECT_EQ(std::count(t.strings["brdf.fresnel.avg"].begin(), t.strings["brdf.fresnel.avg"].end(), ','), 2);
  // texel (x=7, y=0): mu = 15/16, r = 1/16, near-mirror near-normal: F(mu) of each channel
  for (int c = 0; c < 3; ++c) {
    double eta[] = {0.18, 0.42, 1.37}, k[] = {3.42, 2.35, 1.77};
    double f = brdfbake::reference::fresnel({FRESNEL_CONDUCTOR, eta[c], k[c]}, 15.0 / 16);
    EXPECT_NEAR(t.planes[c][7], f, 0.01) << "channel " << c;
    EXPECT_LT(t.planes[c][7], 1.0f);
  }
  EXPECT_GT(t.planes[0][7], t.planes[2][7]);
}

TEST(CliMaterials, F82SplitSumHasAThirdChannelAndDiffuseSplitSumHoldsBurley) {
  fs::path d = freshDir("f82");
  CmdResult r = run("--table splitsum --fresnel f82-tint --size 16 -o " + (d / "o").string());
  ASSERT_EQ(r.code, 0) << r.out;
  brdfbake::TableImage t = brdfbake::readTableExr((d / "o/splitsum_ggx_smith-correlated_f82-tint.exr").string());
  EXPECT_EQ(t.strings["brdf.channels"].rfind("R=A,G=B,B=C", 0), 0u) << t.strings["brdf.channels"];
  for (float c : t.planes[2]) {
    EXPECT_GE(c, 0.0f);
    EXPECT_LT(c, 0.2f);  // int f o.h (1 - o.h)^6 <= max of x (1-x)^6 = 0.0567 over the albedo
  }
  r = run("--table splitsum --diffuse burley --size 16 -o " + (d / "b").string());
  ASSERT_EQ(r.code, 0) << r.out;
  brdfbake::TableImage b = brdfbake::readTableExr((d / "b/splitsum_ggx_smith-correlated_burley.exr").string());
  EXPECT_EQ(b.strings["brdf.channels"].rfind("R=A,G=B,B=E_d", 0), 0u);
  // Burley's albedo at the smooth end (F_D90 = 1/2 at r = 0) is (1 - (1 - mu)^5/2)(1 - 1/42):
  // texel (x=15, y=0), r = 1/32 close to it
  EXPECT_NEAR(b.planes[2][15], (1 - std::pow(1 - 31.0 / 32, 5) / 2) * (41.0 / 42), 0.005);
}

TEST(CliMaterials, FresnelAverageTableOverEta) {
  fs::path d = freshDir("favg");
  CmdResult r = run("--table fresnel-avg --fresnel dielectric --grid node --size 16 -o " + (d / "o").string());
  ASSERT_EQ(r.code, 0) << r.out;
  brdfbake::TableImage t = brdfbake::readTableExr((d / "o/fresnel-avg_dielectric.exr").string());
  EXPECT_EQ(t.strings["brdf.axes"], "eta");
  EXPECT_EQ(t.v2f["brdf.eta.range"], std::make_pair(0.25f, 4.0f));
  EXPECT_EQ(t.strings.count("brdf.fresnel.eta"), 0u) << "the table runs over eta";
  for (int i = 0; i < 16; ++i) {
    double eta = 0.25 + 3.75 * i / 15;
    EXPECT_NEAR(t.planes[0][i], brdfbake::reference::fresnelAvg({FRESNEL_DIELECTRIC, eta, 0}), 2e-7) << "eta " << eta;
  }
  EXPECT_NEAR(t.planes[0][3], 0.0, 1e-7) << "eta = 1: no interface, no reflection";
  r = run("--table fresnel-avg --fresnel schlick -o " + (d / "s").string());
  EXPECT_EQ(r.code, 64);
  EXPECT_NE(r.out.find("--table fresnel-avg runs over eta"), std::string::npos) << r.out;
}

TEST(CliMaterials, DiffuseAlbedoTables) {
  fs::path d = freshDir("diffuse");
  CmdResult r = run("--diffuse lambert --size 8 -o " + (d / "l").string());
  ASSERT_EQ(r.code, 0) << r.out;
  brdfbake::TableImage t = brdfbake::readTableExr((d / "l/albedo_lambert.exr").string());
  for (float v : t.planes[0]) EXPECT_NEAR(v, 1.0f, 1e-6);
  EXPECT_EQ(t.strings["brdf.diffuse"], "lambert");
  EXPECT_EQ(t.strings.count("brdf.ndf"), 0u);
  r = run("--diffuse oren-nayar --grid node --size 5 -o " + (d / "o").string());
  ASSERT_EQ(r.code, 0) << r.out;
  t = brdfbake::readTableExr((d / "o/albedo_oren-nayar.exr").string());
  EXPECT_EQ(t.strings["brdf.axes"], "mu,sigma");
  EXPECT_NEAR(t.v2f["brdf.sigma.range"].second, 1.5707963f, 1e-6);
  // mu = 0, sigma = pi/2 (texel (0, 4)): A + B/2
  double s2 = 1.5707963 * 1.5707963, A = 1 - 0.5 * s2 / (s2 + 0.33), B = 0.45 * s2 / (s2 + 0.09);
  EXPECT_NEAR(t.planes[0][20], A + B / 2, 1e-5);
  r = run("info " + (d / "o/albedo_oren-nayar.exr").string());
  EXPECT_EQ(r.out.find("warning"), std::string::npos) << "sigma = 0, pi/8 .. : nodes miss the 1.015 bump";
  r = run("--diffuse burley --size 8 -o " + (d / "b").string());
  ASSERT_EQ(r.code, 0) << r.out;
  r = run("info " + (d / "b/albedo_burley.exr").string());
  EXPECT_NE(r.out.find("warning: E exceeds 1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("burley diffuse model"), std::string::npos) << r.out;
}

// Rough glass in the energy gate: E_R + E_T of the microfacet BSDF at the material's eta.
TEST(CliMaterials, EnergyGateChecksRoughGlass) {
  for (const char* eta : {"1.5", "0.6667"}) {
    CmdResult r = run(std::string("energy --fresnel dielectric --eta ") + eta + " --transmission --size 9");
    EXPECT_EQ(r.code, 0) << r.out;
    EXPECT_NE(r.out.find("conserves: ggx+smith-correlated, rough glass (transmission)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("E_R         E_T"), std::string::npos) << r.out;
  }
  CmdResult r = run("energy --fresnel dielectric --transmission --gaf schlick-ggx");
  EXPECT_EQ(r.code, 64) << r.out;
  EXPECT_NE(r.out.find("--transmission: the rough dielectric takes --ndf ggx or beckmann"), std::string::npos) << r.out;
  r = run("energy --fresnel schlick --transmission");
  EXPECT_EQ(r.code, 64) << r.out;
  EXPECT_NE(r.out.find("--transmission: rough glass takes --fresnel dielectric"), std::string::npos) << r.out;
}

// energy's page: the verdict and the worst points, and the pair's white furnace rendered on GL
// with the glass row (rough glass is what it checks here), every image loading in Chromium.
TEST(CliMaterials, EnergyWritesItsPageWithTheFurnace) {
  fs::path d = freshDir("energypage");
  CmdResult r = run("energy --fresnel dielectric --eta 1.5 --transmission --size 5 -o " + d.string());
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("report: " + (d / "energy/index.html").string()), std::string::npos) << r.out;
  const std::string html = bytes(d / "energy/index.html");
  EXPECT_EQ(verdictLine(html), "<p class=\"verdict pass\"><strong>PASS: </strong>all 1 material(s) conserve energy</p>")
      << html;
  EXPECT_NE(html.find("\nglass               no"), std::string::npos) << html;
  EXPECT_NE(html.find("every measured pixel within its bound"), std::string::npos) << html;
  EXPECT_NE(bytes(d / "energy/energy.csv")
                .find("material,mu,r,param,channel,lobe1,lobe2,total,bound\n\"ggx+smith-correlated, rough glass"),
            std::string::npos);
  EXPECT_EQ(bytes(d / "energy/render_ggx_smith-correlated.png").substr(1, 3), "PNG");
  brdfbake::testing_browser::expectPageWorks(d / "energy/index.html", fs::path(d.string() + "-browser"), 1);
  // without -o the gate writes nothing
  fs::path quiet = freshDir("energynopage");
  fs::create_directories(quiet);
  r = run("energy --size 5", quiet.string());
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(r.out.find("report:"), std::string::npos) << r.out;
  EXPECT_TRUE(fs::is_empty(quiet));
}

TEST(CliMaterials, EnergyGateExitStatuses) {
  // conserving: the diffuse lobe gets what the specular left
  CmdResult r = run("energy --fresnel dielectric --diffuse lambert --coupling albedo-scaling --size 9");
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(r.out.rfind("conserves: ggx+smith-correlated, fresnel dielectric eta=1.5, diffuse lambert", 0), 0u)
      << r.out;
  // Burley's diffuse summed with a specular lobe: E_d(0, r=1) = 785/504, plus the specular
  r = run("energy --fresnel schlick --diffuse burley --size 9");
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_EQ(r.out.rfind("VIOLATES: ", 0), 0u) << r.out;
  EXPECT_NE(r.out.find("diffuse burley alone: largest albedo 1.55754 at mu=0 r=1, above 1 by 0.558"), std::string::npos)
      << "Burley's maximum, 785/504:\n"
      << r.out;
  // the errata: Shirley's 1 - F0 as a divisor violates by far more than the corrected form's
  // 1.3e-3 (the corrected Shirley is exact only for the mirror: see the README)
  r = run("energy --fresnel schlick --f0 0.5 --diffuse shirley-as-printed --size 9");
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find("total albedo 2.5 "), std::string::npos) << r.out;
  r = run("energy --fresnel schlick --f0 0.5 --diffuse shirley --coupling albedo-scaling --size 9");
  EXPECT_EQ(r.code, 0) << r.out;
  r = run("energy --fresnel dielectric --diffuse oren-nayar-as-printed --sigma 1 --coupling albedo-scaling --size 9");
  EXPECT_EQ(r.code, 1) << r.out;
  r = run("energy --fresnel dielectric --diffuse oren-nayar --sigma 1 --coupling albedo-scaling --size 9");
  EXPECT_EQ(r.code, 0) << r.out;
  // a specular lobe alone: blinn-phong borrowing Beckmann's Lambda exceeds 1
  r = run("energy --ndf blinn-phong --gaf smith --size 9");
  EXPECT_EQ(r.code, 1) << r.out;
  // sheen: its albedo is infinite at mu = 0, so the check samples texel centres (as verify does)
  r = run("energy --ndf charlie --gaf charlie-smith --size 9");
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(r.out.rfind("conserves: charlie+charlie-smith, fresnel one", 0), 0u) << r.out;
  EXPECT_NE(r.out.find("at mu=0.05556 r=0.05556"), std::string::npos) << "the first texel centre of 9:\n" << r.out;
}

TEST(CliMaterials, BadMaterialInputNamesTheFlagAndWritesNothing) {
  fs::path d = freshDir("badmat");
  const std::pair<const char*, const char*> cases[] = {
      {"--fresnel schlick --f0 1.5", "--f0 must be in [0, 1], got 1.5"},
      {"--fresnel dielectric --eta 0", "--eta must be in (0, 100], got 0"},
      {"--fresnel dielectric --eta -1", "--eta must be in (0, 100], got -1"},
      {"--fresnel conductor --eta 1 --k -2", "--k must be in [0, 100], got -2"},
      {"--fresnel conductor --eta 1", "--fresnel conductor needs --eta and --k"},
      {"--fresnel schlick --eta 1.5", "--eta: --fresnel schlick takes --f0 only"},
      {"--fresnel dielectric --f82 0.5", "--f82: --fresnel dielectric takes --eta only"},
      {"--f0 0.04", "need --fresnel MODEL"},
      {"--fresnel schlick --f0 0.1,0.2", "--f0 must be one number or three comma-separated (R,G,B), got 2 values"},
      {"--fresnel glass", "--fresnel: unknown Fresnel model 'glass'; valid: one, schlick,"},
      {"--fresnel dielectric --table kp", "--table kp is the NDF's normalisation, which has no Fresnel"},
      {"--fresnel conductor --eta 1 --k 1 --table splitsum", "--table splitsum is Schlick's split"},
      {"--diffuse chalk", "--diffuse: unknown diffuse model 'chalk'"},
      {"--diffuse shirley --table splitsum", "--table splitsum takes --diffuse burley only"},
      {"--diffuse burley --table albedo-avg", "--table albedo-avg has no diffuse form"},
      {"energy --diffuse lambert --sigma 0.3", "--sigma: only --diffuse oren-nayar"},
      {"energy --diffuse oren-nayar --sigma 2", "--sigma must be one angle in [0, 1.5708]"},
      {"energy --coupling product", "--coupling must be sum or albedo-scaling, got 'product'"},
      {"energy --table albedo", "--table: not an energy option"},
      {"--sigma 0.3", "--sigma: only --diffuse oren-nayar and oren-nayar-as-printed take it"},
  };
  for (auto [args, msg] : cases) {
    CmdResult r = run(std::string(args) + " -o " + (d / "o").string());
    if (std::string(args).rfind("energy", 0) == 0) r = run(args);
    EXPECT_EQ(r.code, 64) << args << "\n" << r.out;
    EXPECT_NE(r.out.find(msg), std::string::npos) << args << "\n" << r.out;
  }
  EXPECT_FALSE(fs::exists(d / "o"));
}

}  // namespace

namespace {

// --- evidence: verify ----------------------------------------------------------------------------

TEST(CliEvidence, VerifyPassesTheDefaultPairAndWritesItsPage) {
  fs::path d = freshDir("verify");
  CmdResult r = run("verify --size 9 -o " + d.string());
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("pass  ggx+smith-correlated: white furnace ok; weak furnace ok; k_p normalisation ok; "
                       "reciprocity ok; dielectric energy ok"),
            std::string::npos)
      << r.out;
  for (const char* f :
       {"index.html", "verify.csv", "furnace_ggx_smith-correlated.svg", "loss_ggx_smith-correlated.svg"}) {
    ASSERT_TRUE(fs::exists(d / "verify" / f)) << f;
    EXPECT_GT(fs::file_size(d / "verify" / f), 200u) << f;
  }
  std::string html = bytes(d / "verify/index.html");
  EXPECT_NE(html.find("<img src=\"furnace_ggx_smith-correlated.svg\""), std::string::npos);
  EXPECT_NE(bytes(d / "verify/furnace_ggx_smith-correlated.svg").find("<svg"), std::string::npos);
  // the white furnace rendered on GL from the pair's tables, with its measurement
  EXPECT_NE(html.find("<img src=\"render_ggx_smith-correlated.png\""), std::string::npos);
  EXPECT_EQ(bytes(d / "verify/render_ggx_smith-correlated.png").substr(1, 3), "PNG");
  EXPECT_NE(html.find("every measured pixel within its bound"), std::string::npos) << html;
  EXPECT_NE(html.find("\nglass               no"), std::string::npos) << html;
  brdfbake::testing_browser::expectPageWorks(d / "verify/index.html", fs::path(d.string() + "-browser"), 3);
  EXPECT_EQ(countFiles(d), 9u) << "the page, its CSV, two data files, scripts, plots and the render; no temporaries";
  // the page opens with its summary; a passing pair's heat map has no failure legend, and its
  // colour scale marks E = 1
  EXPECT_EQ(verdictLine(html), "<p class=\"verdict pass\"><strong>PASS: </strong>all 1 pair(s) pass every check</p>")
      << html;
  const std::string gp = bytes(d / "verify/furnace_ggx_smith-correlated.gp");
  EXPECT_EQ(gp.find("E > 1 + bound"), std::string::npos) << gp;
  EXPECT_NE(gp.find("set cbtics add ('E = 1' 1)"), std::string::npos) << gp;
}

// Without EGL the verdict and the page stand; the page says why there is no render and what to install.
TEST(CliEvidence, VerifyWithoutEglWritesItsPageAndSaysWhy) {
  fs::path d = freshDir("verifynoegl");
  CmdResult r = run("verify --size 5 -o " + d.string(), "", "BRDFBAKE_EGL_LIBRARY=/nonexistent/libEGL.so.1");
  ASSERT_EQ(r.code, 0) << r.out;
  const std::string html = bytes(d / "verify/index.html");
  EXPECT_NE(
      html.find("Furnace render: not drawn, no OpenGL ES device: render: no EGL library (/nonexistent/libEGL.so.1): "
                "install Mesa's EGL"),
      std::string::npos)
      << html;
  EXPECT_FALSE(fs::exists(d / "verify/render_ggx_smith-correlated.png"));
}

TEST(CliEvidence, VerifyFlagsBrokenModels) {
  fs::path d = freshDir("verifybad");
  CmdResult r = run("verify --ndf blinn-phong,ggx --gaf smith,none --size 9 -o " + d.string());
  EXPECT_EQ(r.code, 1) << r.out;
  // blinn-phong borrowing Beckmann's Lambda: the albedo exceeds 1, the weak furnace is off by 0.71
  EXPECT_NE(r.out.find("FAIL  blinn-phong+smith: white furnace FAILS (max E = 1.3445"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("weak furnace FAILS (max |W(mu)/mu - 1| = 0.7076"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("FAIL  ggx+none: white furnace FAILS"), std::string::npos) << r.out;
  // a failing pair's map marks the texels over their bound; the summary counts the failures
  EXPECT_NE(bytes(d / "verify/furnace_blinn-phong_smith.gp").find("E > 1 + bound"), std::string::npos);
  const std::string html = bytes(d / "verify/index.html");
  EXPECT_EQ(verdictLine(html),
            "<p class=\"verdict fail\"><strong>FAIL: </strong>3 of 4 pair(s) fail a check (below)</p>")
      << html;
  EXPECT_NE(r.out.find("pass  ggx+smith:"), std::string::npos) << r.out;
}

TEST(CliEvidence, WithoutGnuplotTheDataStillLandsAndTheLineSaysHow) {
  fs::path d = freshDir("verifynoplot");
  CmdResult r = run("verify --size 5 -o " + d.string(), "", "BRDFBAKE_GNUPLOT=/nonexistent/gnuplot");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("plots not drawn: gnuplot not found; apt-get install gnuplot-nox"), std::string::npos) << r.out;
  EXPECT_TRUE(fs::exists(d / "verify/furnace_ggx_smith-correlated.dat"));
  EXPECT_TRUE(fs::exists(d / "verify/furnace_ggx_smith-correlated.gp"));
  EXPECT_FALSE(fs::exists(d / "verify/furnace_ggx_smith-correlated.svg"));
}

// stress is clean on the shipped models: every point finite, within its bound, limits met.
TEST(CliEvidence, StressIsCleanAndWritesItsPage) {
  fs::path d = freshDir("stress");
  CmdResult r = run("stress -o " + d.string());
  ASSERT_EQ(r.code, 0) << r.out;
  // each family's stress points: 96 microfacet, 5 F_avg, 6 Ashikhmin-Shirley, 10 brdf3d, 12 rough glass
  EXPECT_NE(r.out.find("all 153 points pass: finite, within their bounds, limits met"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Tex2(1, v) = exp(-v^2/2) (met)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("brdf3d grazing, r 0.01"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("E_T -> (1 + L) G_T(L, L) as eta -> 1 (met)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("F_avg -> 1 as eta -> 0 (total internal reflection) (met)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("blinn-phong exponent 1e+12"), std::string::npos);
  EXPECT_NE(r.out.find("dielectric eta 1.0001"), std::string::npos);
  EXPECT_NE(r.out.find("stiff corner, dielectric eta 1.000001"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("oren-nayar sigma 1.571"), std::string::npos);
  for (const char* f : {"index.html", "stress.csv", "stress.svg"}) {
    ASSERT_TRUE(fs::exists(d / "stress" / f)) << f;
    EXPECT_GT(fs::file_size(d / "stress" / f), 200u) << f;
  }
  // and the default pair's white furnace rendered on GL, measured
  EXPECT_TRUE(fs::exists(d / "stress/render_ggx_smith-correlated.png"));
  const std::string html = bytes(d / "stress/index.html");
  EXPECT_NE(html.find("every measured pixel within its bound"), std::string::npos);
  // the verdict first; the plot's legend below the data, with no failure entry when nothing fails
  EXPECT_EQ(verdictLine(html),
            "<p class=\"verdict pass\"><strong>PASS: </strong>all 153 points pass: finite, within their bounds, limits "
            "met</p>")
      << html;
  const std::string gp = bytes(d / "stress/stress.gp");
  EXPECT_NE(gp.find("set key outside"), std::string::npos) << gp;
  EXPECT_EQ(gp.find("failing point"), std::string::npos) << gp;
  brdfbake::testing_browser::expectPageWorks(d / "stress/index.html", fs::path(d.string() + "-browser"), 2);
  r = run("stress --ndf ggx");
  EXPECT_EQ(r.code, 64) << r.out;
  EXPECT_NE(r.out.find("--ndf: not a stress option"), std::string::npos) << r.out;
}

// convergence: the quadrature reaches 1e-5 at its first rung, Monte Carlo does not at 65536
// samples; the double quadrature agrees with the reference (two methods) far below 1e-7.
TEST(CliEvidence, ConvergenceShowsEachMethodAgainstTheReference) {
  fs::path d = freshDir("conv");
  CmdResult r = run("convergence --size 4 -o " + d.string());
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_TRUE(fs::exists(d / "convergence/render_ggx_smith-correlated.png"));
  EXPECT_EQ(verdictLine(bytes(d / "convergence/index.html"))
                .rfind("<p class=\"verdict measured\">quadrature (device, float): true error ", 0),
            0u)
      << bytes(d / "convergence/index.html");
  brdfbake::testing_browser::expectPageWorks(d / "convergence/index.html", fs::path(d.string() + "-browser"), 2);
  for (const char* m :
       {"quadrature (device, float)  ", "quadrature (host, double)  ", "Monte Carlo (Hammersley, float)  "})
    EXPECT_NE(r.out.find(m), std::string::npos) << m << "\n" << r.out;
  std::string out = r.out.substr(r.out.find("time to 1e-7"));  // the summary rows
  size_t q = out.find("\nquadrature (device, float)   ");
  ASSERT_NE(q, std::string::npos) << out;
  std::string row = out.substr(q + 1, out.find('\n', q + 1) - q - 1);
  EXPECT_NE(row.find("<= "), std::string::npos) << "the default budget reaches 1e-3 and 1e-5 at once: " << row;
  size_t m = out.find("\nMonte Carlo (Hammersley, float)   ");
  ASSERT_NE(m, std::string::npos);
  std::string mrow = out.substr(m + 1, out.find('\n', m + 1) - m - 1);
  EXPECT_NE(mrow.find("not reached     not reached"), std::string::npos) << mrow;
  EXPECT_TRUE(fs::exists(d / "convergence/convergence.svg"));
  EXPECT_TRUE(fs::exists(d / "convergence/convergence.csv"));
  r = run("convergence --ndf ggx,beckmann");
  EXPECT_EQ(r.code, 64) << r.out;
  EXPECT_NE(r.out.find("convergence measures one pair"), std::string::npos) << r.out;
  r = run("convergence --size 0");
  EXPECT_EQ(r.code, 64) << r.out;
  // a ladder that is empty or absurd
  for (auto [args, msg] :
       {std::pair{"--samples ''", "--samples must be a comma-separated, increasing list"},
        {"--samples 64,16", "--samples must be increasing (a ladder of budgets), got 16 after 64"},
        {"--levels 0,9", "--levels must be a comma-separated, increasing list of integers in 0..5, got '9'"},
        {"--samples 0", "in 1..4194304, got '0'"}}) {
    r = run(std::string("convergence ") + args);
    EXPECT_EQ(r.code, 64) << args << "\n" << r.out;
    EXPECT_NE(r.out.find(msg), std::string::npos) << args << "\n" << r.out;
  }
  r = run("convergence --size 3 --levels 0,1 --samples 64,1024 -o " + d.string());
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(r.out.find("level 2"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("1024 samples"), std::string::npos) << r.out;
}

// convergence --table KIND: every table kind has a ladder against its independent reference, the
// bake's own rule claims at least its true error, and a finer rung of a rule errs less than the
// coarsest.
struct ConvRow {
  std::string method;
  double estimate, error;
};
std::vector<ConvRow> convRows(const std::string& out) {
  std::vector<ConvRow> rows;
  std::istringstream in(out.substr(out.find("\nmethod ") + 1));
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line) && line.rfind("method ", 0) != 0) {
    std::istringstream ls(line);
    std::vector<std::string> w;
    for (std::string x; ls >> x;) w.push_back(x);
    if (w.size() < 4) continue;
    ConvRow r{line.substr(0, 40), std::stod(w[w.size() - 2]), std::stod(w[w.size() - 1])};
    r.method.erase(r.method.find_last_not_of(' ') + 1);
    rows.push_back(r);
  }
  return rows;
}

TEST(CliEvidence, ConvergenceForEveryTableKind) {
  fs::path d = freshDir("conv_kinds");
  ASSERT_EQ(run("bake --table brdf3d --format merl --roughness 0.3 -o " + (d / "m").string()).code, 0);
  const std::string merl = "--brdf merl:" + (d / "m/brdf3d_ggx_smith-correlated.binary").string();
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--table splitsum --size 3 --levels 0,2 --samples 64", "splitsum of ggx+smith-correlated"},
      {"--table albedo --fresnel conductor --eta 0.2 --k 3 --size 3 --levels 0,2 --samples 64", "albedo of ggx"},
      {"--table albedo-avg --ndf beckmann --gaf smith --size 2 --levels 0,3", "albedo-avg of beckmann+smith"},
      {"--table kp --ndf gaussian --size 4 --levels 0,1,2", "kp of gaussian"},
      {"--table fresnel-avg --fresnel dielectric --size 4 --levels 0,1,2", "fresnel-avg of dielectric"},
      {"--table ashikhmin-shirley --levels 0,1,2", "ashikhmin-shirley"},
      {"--table brdf3d --levels 0,1,2", "brdf3d of ggx+smith-correlated"},
      // the default etas, 1/1.5 among them: (mu 0.75, r 0.75) sits next to its critical cosine 0.745
      {"--table dielectric --ndf ggx --gaf smith --size 2 --levels 0,1", "dielectric (E_R and E_T)"},
      {"--table dielectric-avg --ndf beckmann --gaf smith --size 1 --eta-range 0.7,1.5 --levels 0", "dielectric-avg"},
      {merl + " --table albedo --size 1 --levels 0,1", "albedo of merl:"},
      {"--table ltc --size 3", "ltc of ggx_smith-correlated"},
      {"--table ltc --diffuse burley --size 3", "ltc of burley"}};
  for (const auto& [args, title] : cases) {
    CmdResult r = run("convergence " + args + " -o " + (d / "c").string());
    ASSERT_EQ(r.code, 0) << args << "\n" << r.out;
    EXPECT_NE(r.out.find(title), std::string::npos) << args << "\n" << r.out;
    EXPECT_NE(r.out.find("reference"), std::string::npos) << args << "\n" << r.out;
    std::vector<ConvRow> rows = convRows(r.out);
    ASSERT_GE(rows.size(), 2u) << args << "\n" << r.out;
    for (const ConvRow& row : rows) {
      EXPECT_TRUE(std::isfinite(row.error) && std::isfinite(row.estimate)) << args << ": " << row.method;
      // the bake's own rule (or budget) claims its error
      if (row.method.find("the bake") != std::string::npos || row.method.find("distance estimate") == 0 ||
          row.method == "quadrature (device, float)" || row.method == "quadrature (device)") {
        EXPECT_LE(row.error, row.estimate * 1.0001 + 1e-12) << args << ": " << row.method << "\n" << r.out;
      }
    }
    // each method's finest rung errs no more than its coarsest (beyond the float floor's jitter)
    std::map<std::string, std::pair<double, double>> span;  // first and last error per method
    for (const ConvRow& row : rows) {
      auto it = span.find(row.method);
      if (it == span.end())
        span[row.method] = {row.error, -1};
      else
        it->second.second = row.error;
    }
    for (const auto& [m, fl] : span)
      if (fl.second >= 0) {
        EXPECT_LE(fl.second, 1.5 * fl.first + 1e-9) << args << ": " << m << "\n" << r.out;
      }
    EXPECT_TRUE(fs::exists(d / "c/convergence/convergence.svg")) << args;
  }
  CmdResult r = run("convergence --table splitsum,albedo");
  EXPECT_EQ(r.code, 64) << r.out;
  EXPECT_NE(r.out.find("--table: convergence measures one table kind at a time"), std::string::npos) << r.out;
  r = run("convergence --table dielectric --ndf blinn-phong");
  EXPECT_EQ(r.code, 64) << r.out;
  EXPECT_NE(r.out.find("takes --ndf ggx or beckmann"), std::string::npos) << r.out;
  r = run("convergence --table ltc --ndf ggx,beckmann");
  EXPECT_EQ(r.code, 64) << r.out;
  EXPECT_NE(r.out.find("convergence measures one lobe: give one --ndf and one --gaf, or one --diffuse"),
            std::string::npos)
      << r.out;
  r = run("convergence --table ltc --size 33");
  EXPECT_EQ(r.code, 64) << r.out;
  EXPECT_NE(r.out.find("--size for convergence of ltc must be in 2..32"), std::string::npos) << r.out;
}

TEST(CliEvidence, VerifyRejectsTableOptions) {
  CmdResult r = run("verify --table albedo");
  EXPECT_EQ(r.code, 64) << r.out;
  EXPECT_NE(r.out.find("--table: not a verify option"), std::string::npos) << r.out;
  r = run("verify --size 1");
  EXPECT_EQ(r.code, 64) << r.out;
}

}  // namespace
