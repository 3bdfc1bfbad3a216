// The LTC family (--table ltc): the distribution's identities, the default fit against the
// published 2016 GGX table (three.js's copy, Debian's libjs-three), the diffuse and sheen fits, the
// files, the command's errors and the quad light's render. Distances against the reference:
// ltc_distance_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "cli_run.h"
#include "common/brdf_host.h"
#include "common/models.h"
#include "doc_figures.h"
#include "formats/exr/table_file.h"
#include "ltc_test_util.h"
#include "tables/ltc/ltc_fit.h"
#include "test_device.h"

namespace fs = std::filesystem;
using namespace brdfbake;
using brdfbake::testing_device::runner;
using namespace brdfbake::testing_cli;
using brdfbake::testing_ltc::sphereIntegral;

namespace {

// The published 2016 fit as three.js ships it (LTC_MAT_1: 64 x 64 RGBA, x = roughness, y =
// sqrt(1 - mu)); Debian's libjs-three installs it. Empty when the file is missing.
const char* const kThreeLtc = "/usr/share/javascript/three/examples/jsm/lights/RectAreaLightUniformsLib.js";
std::vector<double> publishedLtcMat1() {
  std::ifstream in(kThreeLtc);
  if (!in) return {};
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string s = ss.str();
  const size_t at = s.find("LTC_MAT_1");
  if (at == std::string::npos) return {};
  const size_t open = s.find('[', at), close = s.find(']', open);
  std::string body = s.substr(open + 1, close - open - 1);
  body.erase(std::remove(body.begin(), body.end(), ' '), body.end());  // "- 4.5e-07" -> "-4.5e-07"
  std::vector<double> v;
  std::stringstream items(body);
  for (std::string item; std::getline(items, item, ',');)
    if (!item.empty()) v.push_back(std::stod(item));
  return v;
}

TEST(Ltc, DistributionIntegratesToOneAndItsStoredFormIsTheSame) {
  for (auto prm :
       {std::array<double, 4>{0, 0, 0, 0}, {-0.5, -0.2, 0.3, -0.7}, {-1.2, -0.9, -0.2, -1.2}, {0.3, 0.1, 0.8, 0.4}}) {
    const brdf64::Ltc l = brdf64::ltc_from_params(prm[0], prm[1], prm[2], prm[3]);
    const double total =
        sphereIntegral([&](double x, double y, double z) { return brdf64::ltc_D(l, x, y, z); }, 64, 512);
    EXPECT_NEAR(total, 1.0, 2e-5) << prm[0] << " " << prm[1] << " " << prm[2] << " " << prm[3];
    double s[4];
    brdf64::ltc_store(l, s);
    const brdf64::Ltc back = brdf64::ltc_from_stored(s[0], s[1], s[2], s[3]);
    for (int k = 0; k < 50; ++k) {
      const double th = 0.03 * k, ph = 0.7 * k;
      const double x = std::sin(th) * std::cos(ph), y = std::sin(th) * std::sin(ph), z = std::cos(th);
      EXPECT_NEAR(brdf64::ltc_D(back, x, y, z), brdf64::ltc_D(l, x, y, z), 1e-12 * (1 + brdf64::ltc_D(l, x, y, z)));
    }
    // sampling follows D: the mean of z over 4096 samples against the quadrature's
    double mz = 0;
    const int n = 4096;
    for (int k = 0; k < n; ++k) {
      double w[3];
      brdf64::ltc_sample(l, (k + 0.5) / n, brdf64::ltc_frac(k * 0.6180339887498949), w);
      mz += w[2] / n;
    }
    const double want =
        sphereIntegral([&](double x, double y, double z) { return z * brdf64::ltc_D(l, x, y, z); }, 64, 512);
    EXPECT_NEAR(mz, want, 2e-3);
  }
}

TEST(Ltc, TheCosineIsAtDistanceZeroFromLambert) {
  // Lambert's lobe is the clamped cosine: the identity LTC is at distance 0, and a tilted one is not
  const brdf64::LtcLobe L = brdf64::ltc_lobe(1, NDF_GGX, GAF_SMITH_CORRELATED, 0, 0.6, 0.5, 0, 0, 1.0);
  double below = 0;
  EXPECT_LT(brdf64::ltc_l1(&L, brdf64::ltc_from_params(0, 0, 0, 0), 256, 0.1, 0.2, &below), 1e-12);
  EXPECT_EQ(below, 0.0);
  const double tilted = 0.5 * brdf64::ltc_l1(&L, brdf64::ltc_from_params(0, 0, 0, 0.3), 256, 0.1, 0.2, &below);
  EXPECT_GT(tilted, 0.05);
  EXPECT_GT(below, 0.0);
}

// Distances this small are the same fit: the fit's objective (3 x 96 points, then 3 x 384) does not
// tell them apart (oren-nayar at sigma = 0 is Lambert: its fit ends at 2.3e-5 where the cosine
// measures 1.2e-5).
constexpr double kLtcFloor = 5e-5;

TEST(Ltc, DefaultFitIsNoFartherThanThePublished2016Table) {
  const std::vector<double> pub = publishedLtcMat1();
  ASSERT_EQ(pub.size(), 64u * 64u * 4u) << "the 2016 table (three.js's LTC_MAT_1) is read from " << kThreeLtc
                                        << ", which Debian's libjs-three installs (.ci/run)";
  const int n = 64;
  const LtcFit& f = defaultLtcFit();
  std::vector<float> store[4];
  for (int k = 0; k < 4; ++k) {
    store[k].resize(static_cast<size_t>(n) * n);
    for (size_t t = 0; t < store[k].size(); ++t) store[k][t] = static_cast<float>(pub[4 * t + k]);
  }
  const auto theirs = measureLtc(runner(), LtcLobeSpec{NDF_GGX, GAF_SMITH_CORRELATED}, n, store, f.e);
  double oursSum = 0, theirsSum = 0, oursMax = 0, theirsMax = 0;
  int over = 0, better = 0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const size_t t = static_cast<size_t>(y) * n + x;
      // no farther, up to the two estimates' errors (each three standard errors) and kLtcFloor
      const double slack = f.tvErr[t] + theirs[1][t] + kLtcFloor;
      EXPECT_LE(f.tv[t], theirs[0][t] + slack)
          << "r = " << ltcRoughness(x, n) << ", mu = " << ltcMu(y, n) << ": ours " << f.tv[t] << " +- " << f.tvErr[t]
          << ", 2016 " << theirs[0][t] << " +- " << theirs[1][t];
      over += f.tv[t] > theirs[0][t] + slack;
      better += f.tv[t] < theirs[0][t];
      oursSum += f.tv[t];
      theirsSum += theirs[0][t];
      oursMax = std::max<double>(oursMax, f.tv[t]);
      theirsMax = std::max<double>(theirsMax, theirs[0][t]);
    }
  EXPECT_LT(oursSum, theirsSum);
  // the same grid, channel order and normalisation as the 2016 table: where both fits are good
  // (distance under 0.02 for both, r >= 0.1) the stored entries agree to 0.05
  int compared = 0;
  for (size_t t = 0; t < f.tv.size(); ++t) {
    if (f.tv[t] > 0.02 || theirs[0][t] > 0.02 || ltcRoughness(static_cast<int>(t % n), n) < 0.1) continue;
    ++compared;
    for (int k = 0; k < 4; ++k)
      EXPECT_NEAR(f.store[k][t], pub[4 * t + k], 0.05 * std::max(1.0, std::fabs(pub[4 * t + k])))
          << "texel " << t % n << ", " << t / n << " entry " << k;
  }
  EXPECT_GT(compared, 1000);
  // BRDFBAKE_LTC_DUMP=FILE: both distances per texel, for docs/ltc.md's picture (tools/ltc_figure.sh)
  if (const char* dump = std::getenv("BRDFBAKE_LTC_DUMP")) {
    std::ofstream out(dump);
    out << "# x y r mu tv_brdfbake tv_2016\n";
    for (int y = 0; y < n; ++y) {
      for (int x = 0; x < n; ++x) {
        const size_t t = static_cast<size_t>(y) * n + x;
        out << x << " " << y << " " << ltcRoughness(x, n) << " " << ltcMu(y, n) << " " << f.tv[t] << " " << theirs[0][t]
            << "\n";
      }
      out << "\n";
    }
  }
  std::string said;  // docs/ltc.md's table quotes it
  testing_docs::say(
      said,
      "distance (TV) over %d texels: mean %.5f (2016: %.5f), max %.4f (2016: %.4f); closer at %d, over at "
      "%d\n",
      n * n, oursSum / (n * n), theirsSum / (n * n), oursMax, theirsMax, better, over);
  testing_docs::expectPagesQuote(said);
}

// The engines' files: the .mjs module's `data` is the EXR's texels in three.js's LTC_MAT_1 order
// (RGBA, x fastest), the same floats.
TEST(Ltc, FilesAreInTheEnginesLayout) {
  const fs::path dir = freshDir("ltc", "layout");
  CmdResult r = run("bake --table ltc --size 8 --format exr,header -o '" + dir.string() + "'");
  ASSERT_EQ(r.code, 0) << r.out;
  const TableImage img = readTableExr((dir / "ltc1_ggx_smith-correlated.exr").string());
  std::ifstream in(dir / "ltc1_ggx_smith-correlated.mjs");
  ASSERT_TRUE(in.good());
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string js = ss.str();
  const size_t open = js.find("Float32Array.from([");
  ASSERT_NE(open, std::string::npos) << js.substr(0, 400);
  std::stringstream items(js.substr(open + 20, js.find("])", open) - open - 20));
  std::vector<float> data;
  for (std::string item; std::getline(items, item, ',');)
    if (item.find_first_of("0123456789") != std::string::npos) data.push_back(std::stof(item));
  ASSERT_EQ(data.size(), 8u * 8u * 4u);
  for (size_t t = 0; t < 64; ++t)
    for (int k = 0; k < 4; ++k) EXPECT_EQ(data[4 * t + k], img.planes[k][t]) << t << " " << k;
}

// The diffuse models and the sheen lobe: every texel's fit is finite and no farther from its lobe
// than the clamped cosine (M = identity, what a renderer without the table uses), up to the two
// estimates' errors; the largest distances are printed.
TEST(Ltc, DiffuseAndSheenFitsBeatTheCosine) {
  const int n = 16;
  std::vector<float> cosine[4];
  for (int k = 0; k < 4; ++k) cosine[k].assign(static_cast<size_t>(n) * n, k == 0 || k == 3 ? 1.0f : 0.0f);
  // the table docs/ltc.md shows: each lobe's largest distance where E >= 1e-6 at 16 x 16
  std::string table = "| lobe | largest distance (E >= 1e-6) | the clamped cosine's |\n|---|---|---|\n";
  for (LtcLobeSpec lobe : {LtcLobeSpec{-1, -1, DIFFUSE_BURLEY}, LtcLobeSpec{-1, -1, DIFFUSE_OREN_NAYAR},
                           LtcLobeSpec{NDF_CHARLIE, GAF_CHARLIE_SMITH}}) {
    const LtcFit f = fitLtc(runner(), lobe, n);
    const auto base = measureLtc(runner(), lobe, n, cosine, f.e);
    double worst = 0, worstBase = 0;
    for (size_t t = 0; t < f.tv.size(); ++t) {
      ASSERT_TRUE(std::isfinite(f.tv[t]) && std::isfinite(f.store[0][t]) && std::isfinite(f.e[t])) << lobe.name();
      // a distance between two distributions is at most 1, up to its estimate's error
      EXPECT_LE(f.tv[t], 1.0 + f.tvErr[t] + kLtcFloor) << lobe.name();
      if (f.e[t] < kLtcNegligibleE) {
        EXPECT_EQ(f.tv[t], 1.0f);  // stated, not fitted
        continue;
      }
      EXPECT_LE(f.tv[t], base[0][t] + f.tvErr[t] + base[1][t] + kLtcFloor)
          << lobe.name() << " r = " << ltcRoughness(static_cast<int>(t % n), n)
          << ", mu = " << ltcMu(static_cast<int>(t / n), n);
      worst = std::max<double>(worst, f.tv[t]);
      worstBase = std::max<double>(worstBase, base[0][t]);
    }
    char row[160];
    std::snprintf(row, sizeof row, "| %s | %.4f | %.4f |\n", lobe.name().c_str(), worst, worstBase);
    table += row;
  }
  std::printf("%s", table.c_str());
  testing_docs::expectPagesQuote(table);
}

// The command: two files per lobe, RGBA each, read back; the header's largest distance is the
// largest of ltc2's B channel; bad sizes and options are refused with 64 naming them.
TEST(Ltc, BakeWritesBothFilesAndRefusesWhatItCannotFit) {
  const fs::path dir = freshDir("ltc", "bake");
  CmdResult r = run("bake --table ltc --size 8 --diffuse burley -o '" + dir.string() + "'");
  ASSERT_EQ(r.code, 0) << r.out;
  for (const std::string lobe : {"ggx_smith-correlated", "burley"}) {
    const TableImage m = readTableExr((dir / ("ltc1_" + lobe + ".exr")).string());
    const TableImage a = readTableExr((dir / ("ltc2_" + lobe + ".exr")).string());
    ASSERT_EQ(m.channels.size(), 4u);
    ASSERT_EQ(a.channels.size(), 4u);
    EXPECT_EQ(m.width, 8);
    EXPECT_EQ(a.strings.at("brdf.table"), "ltc");
    const float largest = *std::max_element(a.planes[2].begin(), a.planes[2].end());
    EXPECT_EQ(a.floats.at("ltc.distance.max"), largest) << lobe;
    EXPECT_EQ(m.floats.at("ltc.distance.max"), largest) << lobe;
    // at mu = 1 (y = 0) the lobe is symmetric: the stored matrix has no shear there
    for (int x = 0; x < 8; ++x) EXPECT_NEAR(m.planes[1][x], 0.0f, 0.05f) << lobe << " r = " << x / 7.0;
  }
  EXPECT_FALSE(fs::exists(dir / "ltc_ggx_smith-correlated.exr"));
  struct Bad {
    std::string args, says;
  };
  for (const Bad& b : {Bad{"--size 1", "--size 1: --table ltc takes 2 to 256"},
                       Bad{"--size 300", "--size 300: --table ltc takes 2 to 256"},
                       Bad{"--diffuse lambert", "--diffuse lambert: its LTC is the clamped cosine itself"},
                       Bad{"--fresnel schlick --f0 0.04", "--table ltc stores the magnitude"}}) {
    const fs::path bad = freshDir("ltc", "bad", false);
    CmdResult e = run("bake --table ltc " + b.args + " -o '" + bad.string() + "'");
    EXPECT_EQ(e.code, 64) << b.args << ": " << e.out;
    EXPECT_NE(e.out.find(b.says), std::string::npos) << e.out;
    EXPECT_FALSE(fs::exists(bad)) << b.args;
  }
}

// The lookup and polygon code on a real GL pipeline (Mesa's llvmpipe): every sphere pixel under the
// quad light within its bound of the exact integral (render/ltc_render.cpp), and the files land.
TEST(Ltc, QuadLightRenderStaysWithinItsBounds) {
  const fs::path dir = freshDir("ltc", "render", false);
  CmdResult r = run("render --light quad --cell 16 --columns 3 -o '" + dir.string() + "'");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find(" 0 of "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("largest deviation from the exact integral"), std::string::npos) << r.out;
  const TableImage img = readTableExr((dir / "ltc_quad.exr").string());
  ASSERT_EQ(img.planes.size(), 3u);
  double lit = 0;
  for (size_t k = 0; k < img.planes[0].size(); ++k) {
    EXPECT_LE(std::fabs(img.planes[0][k] - img.planes[1][k]), img.planes[2][k] + 1e-7) << k;
    lit = std::max<double>(lit, img.planes[1][k]);
  }
  EXPECT_GT(lit, 0.05);  // the light is seen
  EXPECT_TRUE(fs::exists(dir / "ltc_quad.png"));
  CmdResult bad = run("render --light qaud -o '" + dir.string() + "'");
  EXPECT_EQ(bad.code, 64);
  EXPECT_NE(bad.out.find("did you mean 'quad'"), std::string::npos) << bad.out;
}

}  // namespace

namespace brdfbake {

// The default pair's 64 x 64 fit, once for the tests that read it.
const LtcFit& defaultLtcFit() {
  static const LtcFit f = fitLtc(runner(), LtcLobeSpec{NDF_GGX, GAF_SMITH_CORRELATED}, 64);
  return f;
}

}  // namespace brdfbake
