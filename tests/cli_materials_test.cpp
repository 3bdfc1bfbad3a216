// The brdfbake command on whole materials: Fresnel and diffuse tables, the Fresnel average over eta,
// the energy gate and its page, bad material input.
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
