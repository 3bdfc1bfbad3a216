// The anisotropic Ashikhmin-Shirley BRDF and its factorised textures (seed 001,
// kernels/brdf/anisotropic.h, host/tables/ashikhmin/ashikhmin_textures.cpp, shaders/ashikhmin_shirley.glsl):
// Tex2's u -> 1 limit, the corrected Fresnel, the direct formula against an independent form, the
// shader's recombination from the baked textures against the direct formula, and the CLI.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <glm/glm.hpp>
#include <string>

#include "cli_run.h"
#include "doc_figures.h"
#include "tables/ashikhmin/ashikhmin_textures.h"
#include "common/brdf_host.h"
#include "formats/exr/table_file.h"
#include "materials/multiscatter.h"

namespace {
using namespace brdfbake;
namespace fs = std::filesystem;
constexpr double kPi = 3.14159265358979323846;

// The seed's u^(v^2/(1-u^2)) in long double, 1 - u^2 factored so that it is exact (1 - u is);
// at u = 1 (float's 1 - 1e-8 and above) the limit.
long double tex2Reference(double u, double v) {
  long double U = u, V = v;
  return U == 1 ? std::exp(-V * V / 2) : std::pow(U, V * V / ((1 - U) * (1 + U)));
}

// The seed's sample code (main.cpp, gs), scale 1: the formula switched at u > 1 - 1/256.
double tex2Seed(double u, double v) {
  return u > 1.0 - 1.0 / 256 ? std::exp(-v * v / 2) : std::pow(u, v * v / (1 - u * u));
}

const double kV[] = {0.25, 1.0, 2.0, 3.0, 5.0};

TEST(AshikhminTex2, ApproachesTheLimitStablyAsUTendsToOne) {
  for (double v : kV) {
    const double limit = std::exp(-v * v / 2);
    EXPECT_EQ(brdf64::as_tex2(1.0, v), limit) << "v " << v;
    for (int k = 1; k <= 12; ++k) {
      double u = 1 - std::pow(10.0, -k);
      long double ref = tex2Reference(u, v);
      double got = brdf64::as_tex2(u, v);
      EXPECT_LE(std::fabs(got - ref) / ref, 1e-14) << "v " << v << " u = 1 - 1e-" << k;
      // Tex2 = exp(v^2 log(u)/(1-u^2)), log(u)/(1-u^2) = -1/2 - d/2 + O(d^2) for d = 1 - u
      EXPECT_LE(std::fabs(got - limit), v * v * (1 - u) * limit) << "v " << v << " u = 1 - 1e-" << k;
      // and in float, where the naive power has 1 - u^2 = 0 from u > 1 - 3e-8
      float u32 = static_cast<float>(u);
      float got32 = brdf32::as_tex2(u32, static_cast<float>(v));
      EXPECT_LE(std::fabs(got32 - tex2Reference(u32, static_cast<float>(v))) / ref, 2e-6)
          << "float, v " << v << " k " << k;
      EXPECT_TRUE(std::isfinite(got32));
    }
  }
}

TEST(AshikhminTex2, HasNoStepWhereTheSeedSwitchesFormulas) {
  const double u0 = 1.0 - 1.0 / 256;
  for (double v : kV) {
    double below = std::nextafter(u0, 0.0), above = std::nextafter(u0, 2.0);
    double stepOurs = std::fabs(brdf64::as_tex2(above, v) - brdf64::as_tex2(below, v));
    double stepSeed = std::fabs(tex2Seed(above, v) - tex2Seed(below, v));
    EXPECT_LE(stepOurs, 1e-14) << "v " << v;
    // the seed's step is v^2/512 Tex2 to first order: 6e-6 (v = 0.25) to 1.8e-7 (v = 5)
    EXPECT_GE(stepSeed, 0.5 * v * v / 512 * std::exp(-v * v / 2)) << "v " << v;
  }
  // nondecreasing in u (log(u)/(1-u^2) increases to -1/2) all the way to u = 1: no step anywhere
  for (double v : kV) {
    double prev = brdf64::as_tex2(0.5, v);
    for (int k = 2; k <= 60; ++k) {
      double u = 1 - std::ldexp(1.0, -k), x = brdf64::as_tex2(u, v);
      EXPECT_GE(x, prev) << "v " << v << " u = 1 - 2^-" << k;
      prev = x;
    }
    EXPECT_GE(brdf64::as_tex2(1.0, v), prev);
  }
}

TEST(AshikhminTex2, EdgesAreFinite) {
  EXPECT_EQ(brdf64::as_tex2(0.0, 0.0), 1.0);  // 0^0, the limit along v = 0
  EXPECT_EQ(brdf64::as_tex2(0.0, 1.0), 0.0);
  EXPECT_EQ(brdf32::as_tex2(0.0f, 0.0f), 1.0f);
  EXPECT_NEAR(brdf64::as_tex2(0.25, 2.0), static_cast<double>(tex2Reference(0.25, 2.0)), 1e-16);
}

// Erratum (MODELS.md, seed 001): F = Rs + (1-Rs)(1-n)^5, not Rs + (1-Rs)(1-n^5); they agree at
// n = 0 and n = 1, so the check is at n = 0.5.
TEST(AshikhminTex1, FresnelIsSchlicksAtAnInteriorPoint) {
  const double u = 0.5, v = 0.75;
  for (double rs : {0.04, 0.5, 0.9}) {
    double f = brdf64::as_tex1(rs, u, v) * u * v;
    EXPECT_NEAR(f, rs + (1 - rs) / 32, 1e-15) << "Rs " << rs;
    EXPECT_GT(std::fabs(f - (rs + (1 - rs) * (1 - 1.0 / 32))), 0.9 * (1 - rs)) << "Rs " << rs;
    // the table's split: Tex1 = Rs R + G
    EXPECT_NEAR(rs * brdf64::as_tex1_rs(u, v) + brdf64::as_tex1_one(u, v), brdf64::as_tex1(rs, u, v), 1e-15);
  }
}

// The direct formula against the paper's angle form, evaluated independently in long double.
TEST(AshikhminSpecular, MatchesThePapersAngleFormAndIsReciprocal) {
  const double nu = 100, nv = 10, rs = 0.3;
  for (double ti : {0.1, 0.6, 1.2})
    for (double to : {0.2, 0.9, 1.5})
      for (double dphi : {0.0, 0.7, 2.5}) {
        long double i[3] = {std::sin(ti), 0, std::cos(ti)};
        long double o[3] = {std::sin(to) * std::cos(dphi + 0.3), std::sin(to) * std::sin(dphi + 0.3), std::cos(to)};
        long double h[3], len = 0;
        for (int k = 0; k < 3; ++k) len += (h[k] = i[k] + o[k]) * (i[k] + o[k]);
        for (long double& x : h) x /= std::sqrt(len);
        long double phi = std::atan2(h[1], h[0]), c = std::cos(phi), s = std::sin(phi);
        long double hk = h[0] * o[0] + h[1] * o[1] + h[2] * o[2];
        long double F = rs + (1 - rs) * std::pow(1 - hk, 5.0L);
        long double ref = std::sqrt((nu + 1) * (nv + 1)) / (8 * kPi) * std::pow(h[2], nu * c * c + nv * s * s) * F /
                          (hk * std::max(i[2], o[2]));
        double got = brdf64::as_specular(nu, nv, rs, i[0], i[1], i[2], o[0], o[1], o[2]);
        double swapped = brdf64::as_specular(nu, nv, rs, o[0], o[1], o[2], i[0], i[1], i[2]);
        EXPECT_LE(std::fabs(got - ref), 1e-12 * ref) << ti << " " << to << " " << dphi;
        EXPECT_LE(std::fabs(got - swapped), 1e-13 * got);
      }
}

// ---- the shader, compiled here, reading the baked textures through GL's bilinear filter ------
namespace glsl {
using namespace glm;
const materials::Texture* tex[3] = {nullptr, nullptr, nullptr};
#include "../shaders/ashikhmin_shirley.glsl"
float asTex0(float nl, float nv) { return tex[0]->sample(nl, nv).x; }
vec2 asTex1(float hl, float m) {  // the upper-node grid: texel i at (i+1)/n
  float s = 0.5f / static_cast<float>(tex[1]->width);
  return tex[1]->sample(hl - s, m - s);
}
float asTex2(float nh, float t) { return tex[2]->sample(nh, t).x; }
}  // namespace glsl

materials::Texture textureOf(const TableImage& img) {
  materials::Texture t;
  t.width = img.width;
  t.height = img.height;
  t.nodeGrid = img.strings.at("brdf.grid") == "node";
  t.texels.resize(img.planes[0].size());
  for (size_t k = 0; k < t.texels.size(); ++k) t.texels[k] = glm::vec2(img.planes[0][k], img.planes[1][k]);
  return t;
}

struct Errors {
  double maxRel = 0, rmsRel = 0, maxPeak = 0, maxDiffuse = 0;
};

// Specular recombined from n x n textures against as_specular, lights on a grid uniform in solid
// angle (cos theta_i, phi_i), views at theta_o = 0, 30, 60, 80 degrees, azimuths 0 and 35 degrees.
// maxRel, rmsRel: |f_tex - f|/f where f >= 1e-3 of the view's peak; maxPeak: |f_tex - f| over the
// view's peak, everywhere; maxDiffuse: the diffuse term's |error| over its peak, everywhere.
Errors recombination(int n, double nu, double nv, double rs) {
  TableImage img[3];
  materials::Texture t[3];
  for (int k = 0; k < 3; ++k) {
    img[k] = ashikhminTexture(k, n, false);
    t[k] = textureOf(img[k]);
    glsl::tex[k] = &t[k];
  }
  Errors e;
  double sum = 0;
  long count = 0;
  const int nc = 256, nphi = 512;
  std::vector<double> f(nc * nphi), g(nc * nphi);
  for (double to : {0.0, 30.0, 60.0, 80.0})
    for (double po : {0.0, 35.0}) {
      double so = std::sin(to * kPi / 180),
             o[3] = {so * std::cos(po * kPi / 180), so * std::sin(po * kPi / 180), std::cos(to * kPi / 180)};
      double peak = 0, dpeak = 0, dworst = 0;
      for (int a = 0; a < nc; ++a)
        for (int b = 0; b < nphi; ++b) {
          double ci = (a + 0.5) / nc, si = std::sqrt(1 - ci * ci), p = 2 * kPi * (b + 0.5) / nphi;
          double i[3] = {si * std::cos(p), si * std::sin(p), ci};
          size_t k = static_cast<size_t>(a) * nphi + b;
          f[k] = brdf64::as_specular(nu, nv, rs, i[0], i[1], i[2], o[0], o[1], o[2]);
          glm::vec3 L(i[0], i[1], i[2]), V(o[0], o[1], o[2]);
          g[k] = glsl::ashikhminSpecular(glm::vec3(0, 0, 1), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), L, V,
                                         static_cast<float>(nu), static_cast<float>(nv), static_cast<float>(rs));
          peak = std::max(peak, f[k]);
          double d = brdf64::diffuse_ashikhmin_shirley(rs, ci, o[2]);
          double dt = glsl::ashikhminDiffuse(static_cast<float>(ci), static_cast<float>(o[2]), static_cast<float>(rs));
          dpeak = std::max(dpeak, d);
          dworst = std::max(dworst, std::fabs(dt - d));
        }
      e.maxDiffuse = std::max(e.maxDiffuse, dworst / dpeak);
      for (size_t k = 0; k < f.size(); ++k) {
        e.maxPeak = std::max(e.maxPeak, std::fabs(g[k] - f[k]) / peak);
        if (f[k] < 1e-3 * peak) continue;
        double r = std::fabs(g[k] - f[k]) / f[k];
        e.maxRel = std::max(e.maxRel, r);
        sum += r * r;
        ++count;
      }
    }
  e.rmsRel = std::sqrt(sum / count);
  return e;
}

const double kCases[][3] = {{10, 10, 0.05}, {100, 10, 0.5}, {1000, 10, 0.5}, {10000, 100, 0.9}};

// Measured at the default size, 128 (README, "ashikhmin-shirley"; the largest of the four cases:
// max rel 1.74e-2, rms rel 3.71e-3, max/peak 2.67e-3, diffuse 3.8e-5); the thresholds sit ~1.5x
// above. Texel-centre grids, which clamp n.h and h.l at 1 - 0.5/n, fail them (measured: max/peak
// 6.9e-3 at 128, first order in 1/n), and fail the second-order check below.
TEST(AshikhminRecombination, ShaderFromTheTexturesMatchesTheDirectFormula) {
  Errors worst[3];  // per size, the worst of the four cases: the table docs/ashikhmin-shirley.md shows
  for (const auto& c : kCases) {
    Errors e[3];
    for (int k = 0; k < 3; ++k) {
      int n = 64 << k;
      e[k] = recombination(n, c[0], c[1], c[2]);
      worst[k].maxRel = std::max(worst[k].maxRel, e[k].maxRel);
      worst[k].rmsRel = std::max(worst[k].rmsRel, e[k].rmsRel);
      worst[k].maxPeak = std::max(worst[k].maxPeak, e[k].maxPeak);
      worst[k].maxDiffuse = std::max(worst[k].maxDiffuse, e[k].maxDiffuse);
      std::printf("n %4d  nu %6g nv %4g Rs %4g: max rel %.3e  rms rel %.3e  max/peak %.3e  diffuse max/peak %.3e\n", n,
                  c[0], c[1], c[2], e[k].maxRel, e[k].rmsRel, e[k].maxPeak, e[k].maxDiffuse);
    }
    const Errors& d = e[1];  // n = 128
    EXPECT_LE(d.maxRel, 2.5e-2) << c[0] << " " << c[1] << " " << c[2];
    EXPECT_LE(d.rmsRel, 5.5e-3) << c[0] << " " << c[1] << " " << c[2];
    EXPECT_LE(d.maxPeak, 4e-3) << c[0] << " " << c[1] << " " << c[2];
    EXPECT_LE(d.maxDiffuse, 1e-4) << c[0] << " " << c[1] << " " << c[2];
    // bilinear lookups of smooth tables on grids that hold the edges: second order in 1/n
    EXPECT_LE(e[2].maxPeak, e[1].maxPeak / 3);
    EXPECT_LE(e[2].rmsRel, e[1].rmsRel / 3);
  }
  std::string table = "| N | max rel | RMS rel | max / peak | diffuse max / peak |\n|---|---|---|---|---|\n";
  for (int k = 0; k < 3; ++k) {
    char row[160];
    std::snprintf(row, sizeof row, "| %d%s | %.1e | %.1e | %.1e | %.1e |\n", 64 << k, k == 1 ? " (default)" : "",
                  worst[k].maxRel, worst[k].rmsRel, worst[k].maxPeak, worst[k].maxDiffuse);
    table += row;
  }
  std::printf("%s", table.c_str());
  testing_docs::expectPagesQuote(table);
}

// The whole-BRDF helper is the sum of the two terms times n.l.
TEST(AshikhminRecombination, WholeBrdfIsDiffusePlusSpecularTimesCosine) {
  TableImage img[3];
  materials::Texture t[3];
  for (int k = 0; k < 3; ++k) {
    img[k] = ashikhminTexture(k, 32, false);
    t[k] = textureOf(img[k]);
    glsl::tex[k] = &t[k];
  }
  glm::vec3 n(0, 0, 1), x(1, 0, 0), y(0, 1, 0), l = glm::normalize(glm::vec3(0.3f, 0.2f, 0.9f));
  glm::vec3 v = glm::normalize(glm::vec3(-0.4f, 0.1f, 0.8f)), rd(0.2f, 0.5f, 0.8f);
  glm::vec3 all = glsl::ashikhminShirley(n, x, y, l, v, 200.0f, 20.0f, 0.3f, rd);
  float s = glsl::ashikhminSpecular(n, x, y, l, v, 200.0f, 20.0f, 0.3f) * l.z;
  float d = glsl::ashikhminDiffuse(l.z, v.z, 0.3f) * l.z;
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(all[c], rd[c] * d + s, 1e-6f * all[c]);
  EXPECT_GT(s, 0.0f);
}

// ---- the command line -----------------------------------------------------------------------
using testing_cli::bytes;
using testing_cli::CmdResult;
using testing_cli::run;
fs::path freshDir(const std::string& name) { return testing_cli::freshDir("as", name, false); }

TEST(AshikhminCli, BakeWritesTheThreeTexturesWithTheirMetadata) {
  fs::path dir = freshDir("bake");
  CmdResult r = run("bake --table ashikhmin-shirley --size 33 -o '" + dir.string() + "'");
  ASSERT_EQ(r.code, 0) << r.out;
  const char* grids[3] = {"node", "upper-node", "node"};
  for (int t = 0; t < 3; ++t) {
    TableImage img = readTableExr((dir / ("as_tex" + std::to_string(t) + ".exr")).string());
    EXPECT_EQ(img.width, 33);
    EXPECT_EQ(img.strings.at("brdf.table"), "ashikhmin-shirley");
    EXPECT_EQ(img.strings.at("brdf.texture"), "tex" + std::to_string(t));
    EXPECT_EQ(img.strings.at("brdf.grid"), grids[t]);
    EXPECT_FALSE(img.strings.at("brdf.formula").empty());
    EXPECT_LE(img.floats.at("brdf.error"), 1e-7f);  // FLOAT rounding of closed forms
    EXPECT_EQ(img.v2f.at("brdf.u.range"), std::make_pair(0.0f, 1.0f));
    for (const auto& p : img.planes)
      for (float x : p) ASSERT_TRUE(std::isfinite(x));
  }
  TableImage t2 = readTableExr((dir / "as_tex2.exr").string());
  EXPECT_EQ(t2.strings.at("brdf.axes"), "n.h,t");
  EXPECT_EQ(t2.floats.at("brdf.scale"), 10.0f);
  EXPECT_EQ(t2.floats.at("brdf.offset"), 0.5f);
  EXPECT_EQ(t2.v2f.at("brdf.v.range"), std::make_pair(-5.0f, 5.0f));
  // node grid, odd size: the last column is u = 1 (the limit), the middle row v = 0 (Tex2 = 1)
  for (int j = 0; j < 33; ++j) {
    double v = 10.0 * (j / 32.0 - 0.5);
    EXPECT_FLOAT_EQ(t2.planes[0][j * 33 + 32], static_cast<float>(std::exp(-v * v / 2))) << j;
  }
  EXPECT_EQ(t2.planes[0][16 * 33 + 5], 1.0f);
  TableImage t1 = readTableExr((dir / "as_tex1.exr").string());
  // upper-node: texel (i, j) at ((i+1)/n, (j+1)/n); (n-1, n-1) is u = v = 1: R = 1, G = 0, B = 1
  EXPECT_EQ(t1.planes[0][33 * 33 - 1], 1.0f);
  EXPECT_EQ(t1.planes[1][33 * 33 - 1], 0.0f);
  EXPECT_FLOAT_EQ(t1.planes[2][0], 33.0f * 33.0f);
  fs::remove_all(dir);
}

TEST(AshikhminCli, BadRequestsExit64NamingTheFlagAndWriteNothing) {
  fs::path dir = freshDir("bad");
  const std::string o = " -o '" + dir.string() + "'";
  struct Bad {
    std::string args, message;
  } bad[] = {
      {"--size 1", "--size must be an integer in 2..8192 for --table ashikhmin-shirley, got 1"},
      {"--size 256 --half", "--size must be an integer in 2..255 for --table ashikhmin-shirley with --half"},
      {"--grid node", "--grid node: --table ashikhmin-shirley sets its own grids"},
      {"--size 0", "--size must be an integer in 1..8192, got 0"},
      {"--fresnel schlick", "bake it without --fresnel"},
      {"--diffuse lambert", "bake it without --diffuse"},
  };
  for (const Bad& b : bad) {
    CmdResult r = run("bake --table ashikhmin-shirley " + b.args + o);
    EXPECT_EQ(r.code, 64) << b.args << ": " << r.out;
    EXPECT_NE(r.out.find(b.message), std::string::npos) << b.args << ": " << r.out;
    EXPECT_FALSE(fs::exists(dir)) << b.args;
  }
  // the largest half size bakes, every value finite and within half's range
  CmdResult r = run("bake --table ashikhmin-shirley --size 255 --half" + o);
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_TRUE(tableExrIsHalf((dir / "as_tex1.exr").string()));
  fs::remove_all(dir);
}

}  // namespace
