// The brdfbake command's evidence: verify, stress and convergence, their pages and verdicts.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
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
