// Multiple-scattering energy compensation (shaders/multiscatter.glsl, compiled on the host by
// host/materials/multiscatter.cpp) against the white furnace: with F = 1 a compensated lobe must
// reflect all the energy, E_ss(mu, r) + int f_ms (n.i) dw_i = 1. The tables are baked here as
// brdfbake bakes them (albedo 32x32, albedo-avg 32, splitsum 128x128, texel-centre grids), the
// lookups sample them as a GL sampler does, and E_ss is the true single-scattering albedo on a
// finer node grid (the device kernel, within 1e-5 of the reference: tests/tables/microfacet/accuracy_test.cpp).
// Needs an OpenCL device, as accuracy_test.cpp does. docs/multiple-scattering.md reports the figures.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <ostream>

#include "cl/device.h"
#include "cl/runner.h"
#include "common/models.h"
#include "doc_figures.h"
#include "materials/multiscatter.h"
#include "reference/reference.h"

namespace {
using namespace brdfbake;
using materials::MsEnergy;
using materials::MsTables;
using testing_docs::sci;

KernelRunner& runner() {
  static std::unique_ptr<KernelRunner> r;
  if (!r) r = std::make_unique<KernelRunner>(selectDevice("").device);
  return *r;
}

constexpr int kNdfGgx = 0, kNdfBeckmann = 1, kGafSmith = 9, kGafSmithCorrelated = 10;

// The fine grid: a node grid mu, r = i/100 (between the 32-texel tables' centres as often as on them).
constexpr int kFine = 101;
// Where the white furnace is asserted: r >= 0.05, mu >= 0.02 (see docs/multiple-scattering.md).
constexpr int kMinR = 5, kMinMu = 2;

// The tables a renderer binds: n x n albedo, n albedo-avg (the splitsum 128 x 128 always).
MsTables bakeTables(int ndf, int gaf, int n, bool node) {
  MsTables t;
  t.e = materials::textureFrom(runner().hemisphere(ndf, gaf, n, n, node), node, 2);
  t.eavg = materials::textureFrom(runner().albedoAvg(ndf, gaf, n, node), node, 0);
  t.ab = materials::textureFrom(runner().hemisphere(ndf, gaf, 128, 128, node), node, 0, 1);
  return t;
}

struct Baked {
  MsTables tables;   // the default: 32 x 32 albedo, 32 albedo-avg, texel-centre grid
  MsTables fine256;  // 256 x 256 albedo, 256 albedo-avg, node grid (read through the remap)
  KernelTable fine;  // A, B, E on the node grid kFine x kFine: the true single scattering
};

const Baked& baked(int ndf, int gaf) {
  static std::map<std::pair<int, int>, Baked> cache;
  auto it = cache.find({ndf, gaf});
  if (it != cache.end()) return it->second;
  Baked b;
  b.tables = bakeTables(ndf, gaf, 32, false);
  b.fine256 = bakeTables(ndf, gaf, 256, true);
  b.fine = runner().hemisphere(ndf, gaf, kFine, kFine, true);
  return cache.emplace(std::make_pair(ndf, gaf), std::move(b)).first->second;
}

std::string pairName(int ndf, int gaf) { return ndfNames()[ndf] + "+" + gafNames()[gaf]; }

struct Worst {
  double value = 0, mu = 0, r = 0;
  void see(double v, double m, double rr) {
    if (std::fabs(v) > std::fabs(value)) value = v, mu = m, r = rr;
  }
};

// Kulla-Conty at F = 1 over the fine grid from (minMu, minR) on: the largest albedo - 1, with
// albedo = E_ss(mu, r) (true) + int f_ms (n.i) dw_i (shader, tables).
Worst kullaContyFurnace(const Baked& b, const MsTables& tables, int minMu, int minR) {
  Worst w;
  for (int k = minR; k < kFine; ++k)
    for (int j = minMu; j < kFine; ++j) {
      const double mu = j / 100.0, r = k / 100.0;
      const double ess = b.fine.planes[2][static_cast<size_t>(k) * kFine + j];
      w.see(ess + materials::evaluate(tables, mu, r, 1.0).kullaConty - 1, mu, r);
    }
  return w;
}

struct Pinned {
  int ndf, gaf;
  double default32;  // measured max |albedo - 1|, 32 x 32 texel-centre tables, r >= 0.05, mu >= 0.02
  // measured max |added energy - Kulla-Conty's| over that grid (256 node tables): Fdez-Aguera, Filament
  double fdez05, fil05, fdez004, fil004;  // at F0 = 0.5 and F0 = 0.04
};
// Measured on PoCL (docs/multiple-scattering.md). The figure is the interpolation error of the
// 32 x 32 E table (bilinear E against the true E_ss); pinned to 10%.
const Pinned kPinned[] = {{kNdfGgx, kGafSmithCorrelated, 2.03e-2, 2.52e-2, 6.06e-2, 5.75e-3, 2.59e-3},
                          {kNdfBeckmann, kGafSmith, 3.39e-2, 2.76e-2, 1.64e-2, 5.10e-3, 2.27e-3},
                          {kNdfGgx, kGafSmith, 2.10e-2, 2.06e-2, 6.69e-2, 6.11e-3, 2.78e-3}};

void PrintTo(const Pinned& p, std::ostream* os) { *os << pairName(p.ndf, p.gaf); }

class MsPair : public ::testing::TestWithParam<Pinned> {};

// The brief's claim, |albedo - 1| <= 1e-3 for r >= 0.05 and mu >= 0.02, holds once the albedo
// table resolves E: 256 x 256 on the node grid. The default 32 x 32 texel-centre tables leave a
// few percent (pinned), from bilinear E near grazing at small r and the clamp beyond the last
// texel centre at r, mu > 1 - 1/64; the compensation adds back what the lookup says is missing.
TEST_P(MsPair, KullaContyWhiteFurnace) {
  const Pinned& p = GetParam();
  const Baked& b = baked(p.ndf, p.gaf);
  Worst fine = kullaContyFurnace(b, b.fine256, kMinMu, kMinR);
  Worst def = kullaContyFurnace(b, b.tables, kMinMu, kMinR);
  Worst all = kullaContyFurnace(b, b.fine256, 0, 0);
  std::printf(
      "%s Kulla-Conty F=1, max |albedo - 1| for r >= 0.05, mu >= 0.02: 256 node %.2e (mu=%.2f r=%.2f), "
      "32 texel-centre %.2e (mu=%.2f r=%.2f); 256 node down to mu = 0, r = 0: %.2e (mu=%.2f r=%.2f)\n",
      pairName(p.ndf, p.gaf).c_str(), std::fabs(fine.value), fine.mu, fine.r, std::fabs(def.value), def.mu, def.r,
      std::fabs(all.value), all.mu, all.r);
  EXPECT_LE(std::fabs(fine.value), 1e-3) << "at mu=" << fine.mu << " r=" << fine.r;
  EXPECT_NEAR(std::fabs(def.value), p.default32, 0.1 * p.default32) << "at mu=" << def.mu << " r=" << def.r;
}

// The compensation does what it should, not just "something near 1": at (mu = 0.5, r = 1) the
// uncompensated albedo is well below 1, the lobe adds back 1 - E, and E itself is the reference's.
TEST_P(MsPair, CompensationAddsTheMissingEnergy) {
  const Pinned& p = GetParam();
  const Baked& b = baked(p.ndf, p.gaf);
  const double eRef = reference::albedo(p.ndf, p.gaf, 1.0, 0.5).e();
  const double ess = b.fine.planes[2][100 * kFine + 50];
  EXPECT_NEAR(ess, eRef, 1e-5);
  EXPECT_LT(ess, 0.95) << "uncompensated albedo should lose > 5% at r = 1";
  const double added = materials::evaluate(b.fine256, 0.5, 1.0, 1.0).kullaConty;
  std::printf("%s at mu=0.5 r=1: E = %.6f, 1 - E = %.6f, Kulla-Conty adds %.6f\n", pairName(p.ndf, p.gaf).c_str(), eRef,
              1 - eRef, added);
  EXPECT_NEAR(added, 1 - eRef, 1e-3);
}

// Fresnel: the energy each method adds to single scattering, Kulla-Conty's coloured lobe
// (albedo of f_ms times F_avg^2 E_avg / (1 - F_avg (1 - E_avg))) against Fdez-Aguera's F_ms E_ms
// and Filament's (F0 A + B)(energyCompensation - 1), from the 256 node tables (whose F = 1 furnace
// is within 6e-4, so the differences are the formulas'). At F0 = 1 Fdez-Aguera's total
// F_ss E_ss + F_ms E_ms is 1 by construction, and Filament's (A + B)/(A + B) too.
TEST_P(MsPair, FresnelCompensationsCompared) {
  const Pinned& p = GetParam();
  const Baked& b = baked(p.ndf, p.gaf);
  for (double f0 : {1.0, 0.5, 0.04}) {
    Worst fdez, fil, kcMax;
    double fdezFurnace = 0, filFurnace = 0;
    for (int k = kMinR; k < kFine; ++k)
      for (int j = kMinMu; j < kFine; ++j) {
        const double mu = j / 100.0, r = k / 100.0;
        MsEnergy m = materials::evaluate(b.fine256, mu, r, f0);
        const double filMs = m.fdezSingle * (m.filament - 1);
        fdez.see(m.fdezMultiple - m.kullaConty, mu, r);
        fil.see(filMs - m.kullaConty, mu, r);
        kcMax.see(m.kullaConty, mu, r);
        fdezFurnace = std::max(fdezFurnace, std::fabs(m.fdezSingle + m.fdezMultiple - 1));
        filFurnace = std::max(filFurnace, std::fabs(m.fdezSingle * m.filament - 1));
      }
    // the whole albedo at one point: true single scattering (F0 A + B) + what each adds
    const size_t at = 100 * kFine + 50;  // mu = 0.5, r = 1
    const double ss = f0 * b.fine.planes[0][at] + b.fine.planes[1][at];
    MsEnergy m = materials::evaluate(b.fine256, 0.5, 1.0, f0);
    std::printf(
        "%s F0=%.2f: Kulla-Conty adds up to %.4f (mu=%.2f r=%.2f); Fdez-Aguera - Kulla-Conty %+.2e "
        "(mu=%.2f r=%.2f); Filament - Kulla-Conty %+.2e (mu=%.2f r=%.2f); albedo at mu=0.5 r=1: single %.4f, "
        "Kulla-Conty %.4f, Fdez-Aguera %.4f, Filament %.4f\n",
        pairName(p.ndf, p.gaf).c_str(), f0, kcMax.value, kcMax.mu, kcMax.r, fdez.value, fdez.mu, fdez.r, fil.value,
        fil.mu, fil.r, ss, ss + m.kullaConty, ss + m.fdezMultiple, ss * m.filament);
    if (f0 == 1.0) {
      EXPECT_LE(fdezFurnace, 1e-6);
      EXPECT_LE(filFurnace, 1e-6);
      // the same energy as Kulla-Conty's at F = 1, up to the tables' interpolation (1 - E from the
      // 128 node splitsum against the 256 node albedo: 2.5e-3 for ggx, 3.9e-3 for beckmann at mu = 0.02)
      EXPECT_LE(std::fabs(fdez.value), 5e-3);
      EXPECT_LE(std::fabs(fil.value), 5e-3);
    } else {
      const double wantFdez = f0 == 0.5 ? p.fdez05 : p.fdez004, wantFil = f0 == 0.5 ? p.fil05 : p.fil004;
      EXPECT_NEAR(std::fabs(fdez.value), wantFdez, 0.1 * wantFdez + 1e-5) << "F0 " << f0;
      EXPECT_NEAR(std::fabs(fil.value), wantFil, 0.1 * wantFil + 1e-5) << "F0 " << f0;
    }
  }
}

// The table-size sweep docs/multiple-scattering.md shows, a row per size: max |albedo - 1| over
// r >= 0.05, mu >= 0.02 with n x n albedo and n albedo-avg tables, texel-centre / node, for each
// pinned pair; and 128 node tables over r >= 0.25. The test prints the rows and checks the page's.
// The finer tables must do better: each size's node tables beat its texel-centre ones from 64 on,
// and 256 node tables meet the goal of 1e-3 (KullaContyWhiteFurnace holds it alone).
TEST(Multiscatter, TableSizeSweep) {
  std::string table =
      "| tables (albedo n x n, albedo-avg n) | ggx + smith-correlated | beckmann + smith | ggx + smith |\n"
      "|---|---|---|---|\n";
  std::string rough = "| 128, node, r >= 0.25 only |";
  for (int n : {32, 64, 128, 256}) {
    std::string row = "| " + std::to_string(n) + ", texel-centre / node |";
    for (const Pinned& p : kPinned) {
      const Baked& b = baked(p.ndf, p.gaf);
      double worst[2];
      for (bool node : {false, true}) {
        const MsTables t = bakeTables(p.ndf, p.gaf, n, node);
        worst[node] = std::fabs(kullaContyFurnace(b, t, kMinMu, kMinR).value);
        if (n == 128 && node) rough += " " + sci(std::fabs(kullaContyFurnace(b, t, kMinMu, 25).value), 2) + " |";
      }
      row += " " + sci(worst[0], 2) + " / " + sci(worst[1], 2) + " |";
      if (n >= 64) {
        EXPECT_LT(worst[1], worst[0]) << pairName(p.ndf, p.gaf) << " " << n;
      }
      if (n == 256) {
        EXPECT_LE(worst[1], 1e-3) << pairName(p.ndf, p.gaf);
      }
    }
    table += row + "\n";
  }
  table += rough + "\n";
  std::printf("%s", table.c_str());
  testing_docs::expectPagesQuote(table);
}

// Sensitivity: the other pair's average albedo in place of this one's breaks the furnace.
TEST(Multiscatter, WrongAverageAlbedoTableFails) {
  const Baked& ggx = baked(kNdfGgx, kGafSmithCorrelated);
  const Baked& beck = baked(kNdfBeckmann, kGafSmith);
  MsTables mixed = ggx.tables;
  mixed.eavg = beck.tables.eavg;
  Worst w = kullaContyFurnace(ggx, mixed, kMinMu, kMinR);
  std::printf("ggx E with beckmann+smith E_avg: max |albedo - 1| = %.3e\n", std::fabs(w.value));
  EXPECT_GT(std::fabs(w.value), 1e-2);
}

// No NaN or Inf anywhere, the r -> 0 corner (1 - E_avg -> 0) and mu = 0 included, and a table
// that is flat at 1 (the 0/0 case exactly) or above 1 gives no compensation.
TEST(Multiscatter, NoNaNAtTheEdges) {
  const Baked& b = baked(kNdfGgx, kGafSmithCorrelated);
  for (double r : {0.0, 1e-6, 1e-3, 0.01, 0.02, 1.0})
    for (double mu : {0.0, 1e-6, 0.01, 0.5, 1.0})
      for (double f0 : {0.0, 0.04, 1.0}) {
        MsEnergy m = materials::evaluate(b.tables, mu, r, f0);
        for (double v : {m.kullaConty, m.fdezSingle, m.fdezMultiple, m.filament})
          EXPECT_TRUE(std::isfinite(v)) << "mu=" << mu << " r=" << r << " f0=" << f0;
      }
  for (float level : {1.0f, 1.0000001f, 1.2f}) {
    MsTables flat;
    flat.e = {4, 4, std::vector<glm::vec2>(16, glm::vec2(level, 0))};
    flat.eavg = {4, 1, std::vector<glm::vec2>(4, glm::vec2(level, 0))};
    flat.ab = {4, 4, std::vector<glm::vec2>(16, glm::vec2(0.5f * level, 0.5f * level))};
    MsEnergy m = materials::evaluate(flat, 0.3, 0.0, 1.0);
    EXPECT_EQ(m.kullaConty, 0.0) << level;
    EXPECT_EQ(m.fdezMultiple, 0.0) << level;
    EXPECT_TRUE(std::isfinite(m.filament)) << level;
  }
}

INSTANTIATE_TEST_SUITE_P(Pairs, MsPair, ::testing::ValuesIn(kPinned), [](const auto& info) {
  std::string s = pairName(info.param.ndf, info.param.gaf);
  for (char& c : s)
    if (c == '-' || c == '+') c = '_';
  return s;
});

}  // namespace
