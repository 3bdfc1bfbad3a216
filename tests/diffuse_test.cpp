// Diffuse models (kernels/brdf/diffuse.h) and their directional-albedo estimator
// (kernels/integrate/diffuse_albedo.h): on the host in double and float, on the device through
// KernelRunner::diffuseAlbedo, against hand-derived closed forms and the independent adaptive
// reference (host/reference/diffuse_reference.cpp); the errata of the seed at interior points.
// The device tests need an OpenCL device (selectDevice throws otherwise).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "tables/error_model.h"
#include "cl/device.h"
#include "cl/runner.h"
#include "common/brdf_host.h"
#include "reference/diffuse_reference.h"

namespace {
using namespace brdfbake;
using reference::diffuseName;
constexpr double kPi = 3.14159265358979323846;
// float arithmetic, as the bake claims it (tables/error_model.h diffuseFloatModel)
double allowance(int model, double value) { return floatArithmeticError(std::fabs(value), diffuseFloatModel(model)); }
constexpr double kClaim = 1e-5;  // the largest bound the estimator may claim where E is finite

KernelRunner& runner() {
  static std::unique_ptr<KernelRunner> r;
  if (!r) r = std::make_unique<KernelRunner>(selectDevice("").device);
  return *r;
}

double rel(double got, double want) { return std::fabs(got - want) / std::max(1.0, std::fabs(want)); }
// Each model's parameter range (lambert ignores it).
double paramHi(int model) {
  return model == DIFFUSE_OREN_NAYAR || model == DIFFUSE_OREN_NAYAR_AS_PRINTED ? kPi / 2 : 1.0;
}
// Where the true albedo is +inf: oren-nayar-as-printed at mu = 0 (sigma > 0), shirley-as-printed at F0 = 1.
bool infiniteAt(int model, double p, double mu) {
  return (model == DIFFUSE_OREN_NAYAR_AS_PRINTED && mu == 0 && p > 0) ||
         (model == DIFFUSE_SHIRLEY_AS_PRINTED && p >= 1);
}
// The kernel's grid coordinate (kernels/bake.cl grid_coord) in float, lo = 0.
float gridCoord(int i, int n, float hi, bool node) {
  float t = node ? (n > 1 ? float(i) / float(n - 1) : 0.0f) : (float(i) + 0.5f) / float(n);
  return hi * t;
}
const double kMus[] = {0.0, 1e-6, 1e-3, 0.05, 0.3, 0.5, 0.8, 1.0};

// The shared formulas (from cosines, sines and cos phi) against the reference's own (from vectors),
// and reciprocity, at directions spread over the hemisphere.
TEST(Diffuse, PointwiseMatchesVectorFormulasAndIsReciprocal) {
  const double ths[] = {0.0, 0.3, 0.9, 1.4, 1.5707};
  const double phs[] = {0.0, 0.7, 1.5707963, 2.2, 3.1};
  for (int model = 0; model < DIFFUSE_COUNT; ++model)
    for (double p : {0.0, 0.3, 0.9}) {
      for (double ti : ths)
        for (double to : ths)
          for (double ph : phs) {
            double i[3] = {std::sin(ti) * std::cos(ph), std::sin(ti) * std::sin(ph), std::cos(ti)};
            double o[3] = {std::sin(to), 0.0, std::cos(to)};
            double want = reference::diffuseBrdf(model, p, i, o);
            double got =
                brdf64::diffuse_f(model, p, std::cos(ti), std::sin(ti), std::cos(to), std::sin(to), std::cos(ph));
            double back =
                brdf64::diffuse_f(model, p, std::cos(to), std::sin(to), std::cos(ti), std::sin(ti), std::cos(ph));
            EXPECT_LE(rel(got, want), 1e-12)
                << diffuseName(model) << " p " << p << " theta_i " << ti << " theta_o " << to << " phi " << ph;
            EXPECT_LE(rel(back, got), 1e-12) << diffuseName(model) << " reciprocity p " << p << " theta_i " << ti
                                             << " theta_o " << to << " phi " << ph;
          }
    }
}

TEST(Diffuse, HostEstimatorMatchesClosedForms) {
  for (int model : {DIFFUSE_LAMBERT, DIFFUSE_SHIRLEY, DIFFUSE_ASHIKHMIN_SHIRLEY, DIFFUSE_SHIRLEY_AS_PRINTED,
                    DIFFUSE_OREN_NAYAR, DIFFUSE_OREN_NAYAR_AS_PRINTED})
    for (double p : {0.0, 0.04, 0.5, 0.9, 1.2, kPi / 2}) {
      if (p > paramHi(model) || (model == DIFFUSE_SHIRLEY_AS_PRINTED && p >= 1)) continue;
      for (double mu : kMus) {
        if (infiniteAt(model, p, mu)) continue;
        double exact = reference::diffuseAlbedoClosedForm(model, p, mu);
        double err = -1;
        double got = brdf64::diffuse_albedo(model, p, mu, &err);
        EXPECT_LE(rel(got, exact), 1e-9) << diffuseName(model) << " p " << p << " mu " << mu;
        EXPECT_LE(std::fabs(got - exact), err + 1e-12 * std::max(1.0, exact))
            << diffuseName(model) << " p " << p << " mu " << mu;
        EXPECT_LE(err, 1e-6 * std::max(1.0, exact)) << diffuseName(model) << " p " << p << " mu " << mu;
        float errf = -1;
        float gotf = brdf32::diffuse_albedo(model, float(p), float(mu), &errf);
        EXPECT_LE(rel(gotf, exact), double(errf) / std::max(1.0, exact) + allowance(model, exact))
            << "float " << diffuseName(model) << " p " << p << " mu " << mu;
        // the independent quadrature against the same closed form
        double q = reference::diffuseAlbedo(model, p, mu);
        EXPECT_LE(rel(q, exact), 1e-9) << "reference " << diffuseName(model) << " p " << p << " mu " << mu;
      }
    }
  // Lambert: 1 everywhere, grazing included
  for (double mu : kMus) {
    double err;
    EXPECT_NEAR(brdf64::diffuse_albedo(DIFFUSE_LAMBERT, 0.0, mu, &err), 1.0, 1e-12) << "lambert mu " << mu;
  }
  // Burley at grazing: m + 2 (m^2 - m)/42 + 11 r^2/504, m = 1/2 + r
  for (double r : {0.0, 0.25, 0.5, 1.0}) {
    double err, exact = reference::diffuseAlbedoClosedForm(DIFFUSE_BURLEY, r, 0.0);
    EXPECT_LE(rel(brdf64::diffuse_albedo(DIFFUSE_BURLEY, r, 0.0, &err), exact), 1e-9) << "burley r " << r;
    EXPECT_LE(rel(reference::diffuseAlbedo(DIFFUSE_BURLEY, r, 0.0), exact), 1e-9) << "reference burley r " << r;
  }
  EXPECT_NEAR(reference::diffuseAlbedoClosedForm(DIFFUSE_BURLEY, 1.0, 0.0), 785.0 / 504.0, 1e-15);
  EXPECT_NEAR(reference::diffuseAlbedoClosedForm(DIFFUSE_BURLEY, 0.0, 0.0), 41.0 / 84.0, 1e-15);
}

// Every model against the adaptive reference at the edges: mu = 0, 1e-6, sigma = pi/2, r = 1 (host,
// double and float; the float path is the device's code in one lane).
TEST(Diffuse, HostEstimatorMatchesReferenceAtTheEdges) {
  for (int model = 0; model < DIFFUSE_COUNT; ++model)
    for (double p : {0.0, 0.04, 0.5, 1.0, kPi / 2}) {
      if (p > paramHi(model)) continue;
      for (double mu : kMus) {
        if (infiniteAt(model, p, mu)) continue;
        double want = reference::diffuseAlbedo(model, p, mu);
        double err;
        double got = brdf64::diffuse_albedo(model, p, mu, &err);
        EXPECT_LE(rel(got, want), 1e-9) << diffuseName(model) << " p " << p << " mu " << mu;
        EXPECT_LE(err / std::max(1.0, std::fabs(got)), 1e-8) << diffuseName(model) << " p " << p << " mu " << mu;
        float pf = float(p), muf = float(mu), errf;
        float gotf = brdf32::diffuse_albedo(model, pf, muf, &errf);
        double wantf = reference::diffuseAlbedo(model, pf, muf);
        EXPECT_TRUE(std::isfinite(gotf) && std::isfinite(errf)) << diffuseName(model) << " p " << p << " mu " << mu;
        EXPECT_LE(rel(gotf, wantf), errf / std::max(1.0, std::fabs(double(gotf))) + allowance(model, gotf))
            << "float " << diffuseName(model) << " p " << p << " mu " << mu;
      }
    }
}

// mu = 0 is the limit from inside for every model whose albedo is finite there.
TEST(Diffuse, GrazingIsTheLimitFromInside) {
  for (int model = 0; model < DIFFUSE_COUNT; ++model) {
    if (model == DIFFUSE_OREN_NAYAR_AS_PRINTED) continue;
    for (double p : {0.0, 0.3, 1.0, kPi / 2}) {
      if (p > paramHi(model) || infiniteAt(model, p, 0)) continue;
      double e0, e1;
      double v0 = brdf64::diffuse_albedo(model, p, 0.0, &e0), v1 = brdf64::diffuse_albedo(model, p, 1e-9, &e1);
      EXPECT_LE(rel(v0, v1), 1e-8) << diffuseName(model) << " p " << p;
      EXPECT_LE(rel(v0, reference::diffuseAlbedo(model, p, 1e-9)), 1e-8) << diffuseName(model) << " p " << p;
    }
  }
}

// Where the true albedo is +inf, the estimator stays finite and says its bound is huge.
TEST(Diffuse, DivergentErrataAreFiniteWithHugeBounds) {
  for (double p : {0.1, 1.0, kPi / 2}) {
    double err;
    double v = brdf64::diffuse_albedo(DIFFUSE_OREN_NAYAR_AS_PRINTED, p, 0.0, &err);
    EXPECT_TRUE(std::isfinite(v) && std::isfinite(err)) << "oren-nayar-as-printed sigma " << p;
    EXPECT_GT(v, 1e20);
    EXPECT_GE(err / v, 1e6);
    float ef;
    float vf = brdf32::diffuse_albedo(DIFFUSE_OREN_NAYAR_AS_PRINTED, float(p), 0.0f, &ef);
    EXPECT_TRUE(std::isfinite(vf) && std::isfinite(ef)) << "float oren-nayar-as-printed sigma " << p;
    EXPECT_GE(ef / vf, 1e6f);
  }
  double err;
  double v = brdf64::diffuse_albedo(DIFFUSE_SHIRLEY_AS_PRINTED, 1.0, 0.5, &err);
  EXPECT_TRUE(std::isfinite(v) && v > 1e20 && err / v >= 1e6) << "shirley-as-printed F0 = 1: " << v << " +- " << err;
  // sigma = 0: B = 0, the as-printed form is Lambert, finite at grazing
  EXPECT_NEAR(brdf64::diffuse_albedo(DIFFUSE_OREN_NAYAR_AS_PRINTED, 0.0, 0.0, &err), 1.0, 1e-12);
  EXPECT_LE(err, 1e-12);
}

struct Stats {
  double maxErr = 0, maxBound = 0, maxE = -1e300;
};

// The kernel against the reference on one grid; returns the figures for the report.
Stats checkGrid(int model, int nx, int ny, bool node, double pHi) {
  KernelTable t = runner().diffuseAlbedo(model, nx, ny, 0.0f, float(pHi), node);
  Stats s;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      size_t x = size_t(j) * nx + i;
      double mu = gridCoord(i, nx, 1.0f, node), p = gridCoord(j, ny, float(pHi), node);
      double e = t.planes[0][x], b = t.err[x];
      std::string at =
          diffuseName(model) + (node ? " node" : " centre") + " mu " + std::to_string(mu) + " p " + std::to_string(p);
      EXPECT_TRUE(std::isfinite(e) && std::isfinite(b)) << at;
      EXPECT_GE(b, 0.0) << at;
      if (!std::isfinite(e) || !std::isfinite(b)) continue;
      if (infiniteAt(model, p, mu)) {
        if (mu > 0) {
          EXPECT_GT(e, 1e20) << at;
        }
        EXPECT_GE(b, 1e6) << at << ": the true value is +inf, the relative bound must be huge";
        continue;
      }
      double want = reference::diffuseAlbedo(model, p, mu);
      double r = rel(e, want);
      EXPECT_LE(r, b + allowance(model, e)) << at << ": kernel " << e << " reference " << want << " bound " << b;
      EXPECT_LE(b, kClaim) << at;
      s.maxErr = std::max(s.maxErr, r);
      s.maxBound = std::max(s.maxBound, b);
      s.maxE = std::max(s.maxE, e);
    }
  return s;
}

TEST(DiffuseKernel, MatchesReferenceOnNodeAndCentreGrids) {
  for (int model = 0; model < DIFFUSE_COUNT; ++model) {
    double hi = paramHi(model);
    Stats a = checkGrid(model, 9, 9, true, hi);
    Stats b = checkGrid(model, 8, 8, false, hi);
    std::printf("%-22s p in [0, %.4f]: max |kernel - ref|/max(1,ref) %.2e, max claimed bound %.2e, max E %.6f\n",
                diffuseName(model).c_str(), hi, std::max(a.maxErr, b.maxErr), std::max(a.maxBound, b.maxBound),
                std::max(a.maxE, b.maxE));
  }
}

TEST(DiffuseKernel, ClosedFormsOnTheDevice) {
  for (int model : {DIFFUSE_LAMBERT, DIFFUSE_SHIRLEY, DIFFUSE_ASHIKHMIN_SHIRLEY}) {
    const int n = 9;
    KernelTable t = runner().diffuseAlbedo(model, n, n, 0.0f, 1.0f, true);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        double mu = gridCoord(i, n, 1.0f, true), p = gridCoord(j, n, 1.0f, true);
        double exact = reference::diffuseAlbedoClosedForm(model, p, mu);
        EXPECT_LE(rel(t.planes[0][j * n + i], exact), 1e-6) << diffuseName(model) << " mu " << mu << " F0 " << p;
      }
  }
}

// Seed 000's Shirley divides by (1 - F0): at F0 = 0.5, mu = 0.5 its albedo is 1.9375; corrected 0.484375.
TEST(DiffuseKernel, ShirleyErratumIsCaught) {
  const int nx = 9, ny = 3;  // mu = i/8, F0 in {0, 0.5, 1}
  KernelTable fixed = runner().diffuseAlbedo(DIFFUSE_SHIRLEY, nx, ny, 0.0f, 1.0f, true);
  KernelTable printed = runner().diffuseAlbedo(DIFFUSE_SHIRLEY_AS_PRINTED, nx, ny, 0.0f, 1.0f, true);
  EXPECT_NEAR(printed.planes[0][1 * nx + 4], 1.9375, 1e-5) << "shirley-as-printed F0 0.5 mu 0.5";
  EXPECT_NEAR(fixed.planes[0][1 * nx + 4], 0.484375, 1e-5) << "shirley F0 0.5 mu 0.5";
  float maxFixed = *std::max_element(fixed.planes[0].begin(), fixed.planes[0].end());
  EXPECT_LE(maxFixed, 1.0f + 1e-6f) << "shirley must conserve energy";
  EXPECT_GT(printed.planes[0][1 * nx + 4], 1.5f) << "shirley-as-printed exceeds 1";
}

// The slides' Oren-Nayar (min and max swapped) grows like 2B/(3 pi mu) at grazing; the corrected
// model stays bounded by its grazing value A + B/2 (which exceeds 1 by up to ~1.5% for small sigma:
// the qualitative model does not conserve energy exactly).
TEST(DiffuseKernel, OrenNayarErratumIsCaught) {
  const int nx = 65, ny = 5;  // mu = i/64, sigma = j pi/8
  KernelTable fixed = runner().diffuseAlbedo(DIFFUSE_OREN_NAYAR, nx, ny, 0.0f, float(kPi / 2), true);
  KernelTable printed = runner().diffuseAlbedo(DIFFUSE_OREN_NAYAR_AS_PRINTED, nx, ny, 0.0f, float(kPi / 2), true);
  int j = ny - 1;  // sigma = pi/2
  double sigma = gridCoord(j, ny, float(kPi / 2), true);
  double p1 = printed.planes[0][j * nx + 1], p8 = printed.planes[0][j * nx + 8], p64 = printed.planes[0][j * nx + 64];
  std::printf(
      "oren-nayar-as-printed sigma pi/2: E(1) %.6f E(1/8) %.6f E(1/64) %.6f; oren-nayar E(1/64) %.6f E(0) %.6f\n", p64,
      p8, p1, fixed.planes[0][j * nx + 1], fixed.planes[0][j * nx]);
  EXPECT_GT(p1, 5.0) << "oren-nayar-as-printed at mu = 1/64";
  EXPECT_GT(p1, 4 * p8);
  EXPECT_NEAR(p1, reference::diffuseAlbedoClosedForm(DIFFUSE_OREN_NAYAR_AS_PRINTED, sigma, 1.0 / 64), 1e-5 * p1);
  for (int jj = 0; jj < ny; ++jj) {
    double s = gridCoord(jj, ny, float(kPi / 2), true);
    double a = 1 - 0.5 * s * s / (s * s + 0.33), b = 0.45 * s * s / (s * s + 0.09);
    for (int i = 0; i < nx; ++i)
      EXPECT_LE(fixed.planes[0][jj * nx + i], a + b / 2 + 2e-6) << "oren-nayar sigma " << s << " mu " << i / 64.0;
    EXPECT_NEAR(fixed.planes[0][jj * nx], a + b / 2, 2e-6) << "oren-nayar sigma " << s << " at grazing";
  }
  float maxFixed = *std::max_element(fixed.planes[0].begin(), fixed.planes[0].end());
  EXPECT_LE(maxFixed, 1.0155f) << "oren-nayar";
  // host, mu down to 1e-6 (the device code in float): E ~ 2B/(3 pi mu)
  float e6 = 0, e3 = 0, err;
  e6 = brdf32::diffuse_albedo(DIFFUSE_OREN_NAYAR_AS_PRINTED, float(kPi / 2), 1e-6f, &err);
  e3 = brdf32::diffuse_albedo(DIFFUSE_OREN_NAYAR_AS_PRINTED, float(kPi / 2), 1e-3f, &err);
  double c6 = reference::diffuseAlbedoClosedForm(DIFFUSE_OREN_NAYAR_AS_PRINTED, double(float(kPi / 2)), double(1e-6f));
  std::printf("oren-nayar-as-printed sigma pi/2: E(1e-3) %.3f E(1e-6) %.1f (closed form %.1f)\n", e3, e6, c6);
  EXPECT_LE(rel(e6, c6), 1e-5);
  EXPECT_GT(e6, 9e4);
}

// Burley 2012 at r = 1 is not energy conserving at grazing (F_D90 up to 2.5): the maximum over the
// 9x9 node grid on r in [0, 1] is at (mu 0, r 1), 785/504.
TEST(DiffuseKernel, BurleyExceedsOneAtGrazing) {
  const int n = 9;
  KernelTable t = runner().diffuseAlbedo(DIFFUSE_BURLEY, n, n, 0.0f, 1.0f, true);
  auto it = std::max_element(t.planes[0].begin(), t.planes[0].end());
  size_t at = size_t(it - t.planes[0].begin());
  EXPECT_EQ(at, size_t((n - 1) * n + 0)) << "burley: the maximum is at mu = 0, r = 1";
  EXPECT_NEAR(*it, 785.0 / 504.0, 2e-6) << "burley max";
  std::printf("burley max on the 9x9 node grid: %.7f at mu %g r %g (785/504 = %.7f)\n", *it,
              gridCoord(int(at % n), n, 1.0f, true), gridCoord(int(at / n), n, 1.0f, true), 785.0 / 504.0);
}

}  // namespace
