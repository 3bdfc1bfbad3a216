// A real graphics pipeline: a headless OpenGL ES 3.1 context through EGL on Mesa's software
// rasteriser (llvmpipe), the tables uploaded as float textures as a renderer would, the GLSL that
// `brdfbake shader` generates compiled into a compute shader, thousands of random points sampled
// through texture filtering (the hardware path) and texelFetch (the exact path), read back and
// compared (1) with a bilinear lookup of the same texels on the host, (2) with 8-bit filter weights
// emulated on the host (what NVIDIA's hardware documents), and (3) with the independent reference:
// the error must stay within what the file predicts, brdf.error + brdf.interp-error. No EGL or no
// GLES 3.1: the test fails (CI installs Mesa's EGL).
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <random>
#include <sstream>

#include "common/brdf3d_grid.h"
#include "tables/volume.h"
#include "common/models.h"
#include "formats/exr/table_file.h"
#include "reference/reference.h"
#include "doc_figures.h"
#include "gl_harness.h"
#include "shader/shader_gen.h"

namespace fs = std::filesystem;
namespace {
using namespace brdfbake;

using glharness::gl;
using testing_docs::expectPagesQuote;
using testing_docs::sci;

fs::path bakeDir() {
  static fs::path d = [] {
    fs::path dir = fs::path(testing::TempDir()) / ("brdfbake_gl_" + std::to_string(getpid()));
    fs::remove_all(dir);
    const std::string exe = std::string("'") + BRDFBAKE_EXE + "' ";
    for (std::string args :
         {"--size 24 --table splitsum,albedo,albedo-avg,kp -o '" + (dir / "tc").string() + "'",
          "--size 17 --grid node --table splitsum,albedo -o '" + (dir / "node").string() + "'",
          "--size 20 --half --table splitsum -o '" + (dir / "half").string() + "'",
          "--size 24 --mu-axis sqrt --table splitsum -o '" + (dir / "sqrt").string() + "'",
          "--size 17 --grid node --mu-axis sqrt -o '" + (dir / "sqrtnode").string() + "'",
          "--table brdf3d --size 20,18,9 --roughness 0.5 --value f-cos -o '" + (dir / "vol").string() + "'",
          "--table brdf3d --param rusinkiewicz --theta-h sqrt --grid node --size 16,14,10 --roughness 0.6 -o '" +
              (dir / "rus").string() + "'",
          "--table dielectric --size 6,5,4 --grid node --eta-range 0.6,1.8 -o '" + (dir / "glass").string() + "'",
          "--table dielectric --size 5 --eta-range 0.7,2 -o '" + (dir / "glasstc").string() + "'",
          "--table dielectric-avg --size 2 -o '" + (dir / "glassavg").string() + "'"})
      EXPECT_EQ(std::system((exe + args + " > /dev/null").c_str()), 0) << args;
    return dir;
  }();
  return d;
}

// The table as a texture: RGBA32F (RGBA16F for a HALF file: the same values), alpha 1.
glharness::Texels texels(const TableImage& t, bool half) {
  std::vector<float> px(static_cast<size_t>(t.width) * t.height * 4, 1.0f);
  for (size_t i = 0; i < px.size() / 4; ++i)
    for (size_t c = 0; c < 3 && c < t.planes.size(); ++c) px[i * 4 + c] = t.planes[c][i];
  glharness::Texels x;
  x.width = t.width;
  x.height = t.height;
  x.internalFormat = half ? GL_RGBA16F : GL_RGBA32F;
  x.assign(px);
  return x;
}

// Runs the generated lookups of `file` at `points` (x, y, z, unused): per point, the hardware
// lookup and the exact one, RGBA each.
std::vector<float> sampleOnGpu(const std::string& file, const TableImage& t, bool half,
                               const std::vector<float>& points, int dims) {
  std::string P = shaderPrefix(file);
  std::string call = dims == 1 ? "p.x" : dims == 2 ? "p.x, p.y" : "p.x, p.y, p.z";
  return glharness::runOnGpu(shaderForTable(file, t, ShaderLang::Glsl),
                             "  res[2 * i] = " + P + "_lookup(tab, " + call + ");\n  res[2 * i + 1] = " + P +
                                 "_lookupExact(tab, " + call + ");\n",
                             texels(t, half), points, 2);
}

double bilinear(const TableImage& t, int c, double px, double py, int bits = 0) {
  return glharness::bilinear(t.planes, t.width, t.height, c, px, py, bits);
}

struct Figures {
  double gpuExact = 0, gpuHardware = 0, weights8 = 0, reference = 0;
};

// A 2D/1D table: GPU against the host bilinear and against the reference at `n` random points.
Figures check2d(const std::string& file, int n, int refPoints) {
  TableImage t = readTableExr(file);
  bool half = tableExrIsHalf(file), node = t.strings["brdf.grid"] == "node";
  const bool sq =
      t.strings.count("brdf.mu.index") && t.strings.at("brdf.mu.index").rfind("sqrt", 0) == 0;  // --mu-axis sqrt
  int dims = t.height == 1 ? 1 : 2;
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<float> pts;
  for (int i = 0; i < n; ++i)
    pts.insert(pts.end(), {i < 4 ? float(i & 1) : u(rng), i < 4 ? float(i >> 1) : u(rng), 0, 0});
  std::vector<float> gpu = sampleOnGpu(file, t, half, pts, dims);
  Figures f;
  if (gpu.empty()) return f;
  const std::string table = t.strings["brdf.table"];
  int ndf = ndfId(t.strings["brdf.ndf"]), gaf = gafId(t.strings["brdf.gaf"]);
  for (int i = 0; i < n; ++i) {
    double x = pts[4 * i], y = pts[4 * i + 1], tx = sq ? std::sqrt(x) : x;
    double px = node ? tx * (t.width - 1) : tx * t.width - 0.5, py = dims == 1 ? 0
                                                                     : node    ? y * (t.height - 1)
                                                                               : y * t.height - 0.5;
    for (int c = 0; c < 3; ++c) {
      double host = bilinear(t, c, px, py), scale = std::max(1.0, std::fabs(host));
      f.gpuExact = std::max(f.gpuExact, std::fabs(gpu[8 * i + 4 + c] - host) / scale);
      f.gpuHardware = std::max(f.gpuHardware, std::fabs(gpu[8 * i + c] - host) / scale);
      f.weights8 = std::max(f.weights8, std::fabs(bilinear(t, c, px, py, 8) - host) / scale);
    }
    if (i >= refPoints) continue;
    // the independent reference (adaptive quadrature in double) against the exact GPU path
    double want[3];
    if (table == "splitsum" || table == "albedo") {
      reference::Moments m = reference::albedo(ndf, gaf, y, x);
      want[0] = table == "albedo" ? m.a + m.b : m.a;
      want[1] = table == "albedo" ? m.a + m.b : m.b;
      want[2] = m.a + m.b;
    } else if (table == "albedo-avg") {
      want[0] = want[1] = want[2] = reference::albedoAvg(ndf, gaf, x);
    } else {
      want[0] = want[1] = want[2] = reference::kp(ndf, x);
    }
    for (int c = 0; c < 3; ++c)
      f.reference = std::max(f.reference, std::fabs(gpu[8 * i + 4 + c] - want[c]) / std::max(1.0, std::fabs(want[c])));
  }
  return f;
}

TEST(GlPipeline, GeneratedGlslSamples2dTablesWithinTheirPredictedError) {
  ASSERT_TRUE(gl().problem.empty()) << "no usable OpenGL ES through EGL: " << gl().problem;
  fs::path d = bakeDir();
  // the table docs/shader-code.md shows
  std::ostringstream table;
  table
      << "| file | GPU exact vs host bilinear | GPU hardware vs host bilinear | 8-bit weights emulated | GPU exact vs "
         "reference (predicted) |\n|---|---|---|---|---|\n";
  for (std::string file : {"tc/splitsum_ggx_smith-correlated.exr", "tc/albedo_ggx_smith-correlated.exr",
                           "tc/albedo-avg_ggx_smith-correlated.exr", "tc/kp_ggx.exr",
                           "node/splitsum_ggx_smith-correlated.exr", "node/albedo_ggx_smith-correlated.exr",
                           "half/splitsum_ggx_smith-correlated.exr", "sqrt/splitsum_ggx_smith-correlated.exr",
                           "sqrtnode/splitsum_ggx_smith-correlated.exr", "sqrtnode/albedo_ggx_smith-correlated.exr"}) {
    std::string path = (d / file).string();
    TableImage h = readTableExrHeader(path);
    Figures f = check2d(path, 4000, 60);
    double predicted = h.floats["brdf.error"] + h.floats["brdf.interp-error"];
    table << "| `" << file << "` | " << sci(f.gpuExact, 1) << " | " << sci(f.gpuHardware, 1) << " | "
          << sci(f.weights8, 1) << " | " << sci(f.reference, 2) << " (" << sci(predicted, 2) << ") |\n";
    EXPECT_LT(f.gpuExact, 2e-6) << file;     // the same texels and weights, float arithmetic
    EXPECT_LT(f.gpuHardware, 2e-5) << file;  // llvmpipe filters with float weights
    // sqrt/ (texel centres in u = sqrt(mu)): its corner texel lies at mu = alpha, on the dip of E
    // towards the corner (0.892 where the corner's limit is 1), and the lookup clamps (0, 0) onto it:
    // 0.108 off, which an estimate from the texels cannot see; the bake's probes between texels do
    // (host/tables/interp_probe.h), and brdf.interp-error covers it on every grid.
    EXPECT_LE(f.reference, predicted) << file;
  }
  std::printf("%s", table.str().c_str());
  expectPagesQuote(table.str());
}

// 3D tables through the atlas: the generated lookups against the host's trilinear lookup of the
// same table, and against the exact BRDF within brdf.error + the interpolation error estimate.
TEST(GlPipeline, GeneratedGlslSamples3dAtlases) {
  ASSERT_TRUE(gl().problem.empty()) << "no usable OpenGL ES through EGL: " << gl().problem;
  fs::path d = bakeDir();
  // the table docs/shader-code.md shows
  std::ostringstream table;
  table << "| file | GPU exact vs host trilinear | GPU hardware vs host trilinear | GPU exact vs the BRDF (the file's "
           "estimate) |\n|---|---|---|---|\n";
  for (std::string file :
       {"vol/brdf3d_ggx_smith-correlated_angles.exr", "rus/brdf3d_ggx_smith-correlated_rusinkiewicz.exr"}) {
    std::string path = (d / file).string();
    TableImage t = readTableExr(path);
    int cols = 0, rows = 0;
    Brdf3dSpec s = specFromHeader(path, t, &cols, &rows);
    auto planes = volumeFromAtlas(t, s, cols);
    auto ax = s.axes();
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<float> pts;
    const int n = 3000;
    for (int i = 0; i < n; ++i)
      for (int a = 0; a < 4; ++a) pts.push_back(a < 3 ? static_cast<float>(ax[a].hi * u(rng)) : 0.0f);
    std::vector<float> gpu = sampleOnGpu(path, t, false, pts, 3);
    ASSERT_FALSE(gpu.empty());
    double exact = 0, hardware = 0;
    int badExact = 0, badHardware = 0;
    double truth = 0;
    for (int i = 0; i < n; ++i) {
      glm::dvec3 idx(texelIndex(s, 0, pts[4 * i]), texelIndex(s, 1, pts[4 * i + 1]), texelIndex(s, 2, pts[4 * i + 2]));
      double host = trilinear(s, planes[0], idx), scale = std::max(1.0, std::fabs(host));
      // the shader forms the texel index in float (a few ulps of the index): where f changes fast
      // from one texel to the next (towards the horizon) that moves the lookup by ~1e-5 of the
      // change across the cell; spread = the largest difference between the cell's eight texels
      double lo = 1e300, hi = -1e300;
      for (int k = 0; k < 8; ++k) {
        glm::dvec3 corner(std::min(std::floor(idx.x) + (k & 1), s.nx - 1.0),
                          std::min(std::floor(idx.y) + ((k >> 1) & 1), s.ny - 1.0),
                          std::min(std::floor(idx.z) + ((k >> 2) & 1), s.nz - 1.0));
        double v = trilinear(s, planes[0],
                             glm::clamp(corner, glm::dvec3(0.0), glm::dvec3(s.nx - 1.0, s.ny - 1.0, s.nz - 1.0)));
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
      // within float arithmetic (2e-6) plus 1e-5 of the cell's spread (the index in float)
      double dExact = std::fabs(gpu[8 * i + 4] - host), dHard = std::fabs(gpu[8 * i] - host);
      if (dExact > 2e-6 * scale + 1e-5 * (hi - lo)) ++badExact;
      if (dHard > 2e-5 * scale + 1e-5 * (hi - lo)) ++badHardware;
      exact = std::max(exact, dExact / scale);
      hardware = std::max(hardware, dHard / scale);
      // and the exact BRDF at the point: what the file says its resolution costs
      Directions dir = s.param == Brdf3dParam::Angles ? fromAngles(pts[4 * i], pts[4 * i + 1], pts[4 * i + 2])
                                                      : fromRusinkiewicz(pts[4 * i], pts[4 * i + 1], pts[4 * i + 2]);
      double f = hostBrdf(s, dir, 0);
      truth = std::max(truth, std::fabs(gpu[8 * i + 4] - f) / std::max(1.0, std::fabs(f)));
    }
    double predicted = t.floats["brdf.error"] + t.floats["brdf.interp-error"];
    char row[300];
    std::snprintf(row, sizeof row, "| `%s` (%dx%dx%d) | %s | %s | %.3g (%.3g) |\n", file.c_str(), s.nx, s.ny, s.nz,
                  sci(exact, 1).c_str(), sci(hardware, 1).c_str(), truth, predicted);
    table << row;
    EXPECT_LE(truth, 1.5 * predicted) << file;
    EXPECT_EQ(badExact, 0) << file << ": exact path off the host's trilinear lookup";
    EXPECT_EQ(badHardware, 0) << file << ": hardware path off the host's trilinear lookup";
  }
  std::printf("%s", table.str().c_str());
  expectPagesQuote(table.str());
}

// The rough-dielectric cube's generated lookups over (mu, r, eta): against the host's trilinear
// lookup of the atlas with the eta axis mapped as the file says (s = (eta - 1)/(eta + 1) between
// brdf.s.range's ends), etas beyond the range included (the edge slice); and at the smooth corner
// (mu = 1, r = 0, the first slice, eta 0.6) against Fresnel's F0 = ((eta - 1)/(eta + 1))^2, so a
// mapping wrong in the same way on both sides is caught too. The averages table's albedosAvg(r,
// eta) against the host's bilinear lookup at (r, s).
TEST(GlPipeline, GeneratedGlslSamplesTheDielectricTablesByEta) {
  ASSERT_TRUE(gl().problem.empty()) << "no usable OpenGL ES through EGL: " << gl().problem;
  fs::path d = bakeDir();
  for (std::string file :
       {"glass/dielectric_ggx_smith-correlated.exr", "glasstc/dielectric_ggx_smith-correlated.exr"}) {
    const std::string path = (d / file).string();
    TableImage t = readTableExr(path);
    int nx = 0, ny = 0, nz = 0, cols = 0, rows = 0;
    ASSERT_EQ(std::sscanf(t.strings["brdf.size"].c_str(), "%dx%dx%d", &nx, &ny, &nz), 3) << file;
    ASSERT_EQ(std::sscanf(t.strings["brdf.atlas"].c_str(), "%dx%d", &cols, &rows), 2) << file;
    const bool node = t.strings["brdf.grid"] == "node";
    const auto sr = t.v2f.at("brdf.s.range"), er = t.v2f.at("brdf.eta.range");
    auto texel = [&](int c, int x, int y, int z) {
      return static_cast<double>(t.planes[c][static_cast<size_t>((z / cols) * ny + y) * t.width + (z % cols) * nx + x]);
    };
    auto index = [&](double v, int n) {
      v = std::clamp(v, 0.0, 1.0);
      return std::clamp(node ? v * (n - 1) : v * n - 0.5, 0.0, n - 1.0);
    };
    auto host = [&](int c, double mu, double r, double eta) {
      const double s = (eta - 1) / (eta + 1);
      const double p[3] = {index(mu, nx), index(r, ny), index((s - sr.first) / (sr.second - sr.first), nz)};
      const int n[3] = {nx, ny, nz};
      int i0[3], i1[3];
      double f[3];
      for (int a = 0; a < 3; ++a) {
        i0[a] = static_cast<int>(std::floor(p[a]));
        i1[a] = std::min(i0[a] + 1, n[a] - 1);
        f[a] = p[a] - i0[a];
      }
      double v = 0;
      for (int k = 0; k < 8; ++k)
        v += ((k & 1) ? f[0] : 1 - f[0]) * ((k & 2) ? f[1] : 1 - f[1]) * ((k & 4) ? f[2] : 1 - f[2]) *
             texel(c, (k & 1) ? i1[0] : i0[0], (k & 2) ? i1[1] : i0[1], (k & 4) ? i1[2] : i0[2]);
      return v;
    };
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<float> pts;
    const int n = 2000;
    for (int i = 0; i < n; ++i) {
      // eta up to 10% past both ends of the range
      const float eta = static_cast<float>(er.first * 0.9 + (er.second * 1.1 - er.first * 0.9) * u(rng));
      pts.insert(pts.end(), {i == 0 ? 1.0f : u(rng), i == 0 ? 0.0f : u(rng), i == 0 ? er.first : eta, 0.0f});
    }
    const std::string P = shaderPrefix(path);
    std::vector<float> gpu = glharness::runOnGpu(shaderForTable(path, t, ShaderLang::Glsl),
                                                 "  res[2 * i] = vec4(" + P +
                                                     "_albedos(tab, p.x, p.y, p.z), 0.0);\n"
                                                     "  res[2 * i + 1] = vec4(" +
                                                     P + "_albedosExact(tab, p.x, p.y, p.z), 0.0);\n",
                                                 texels(t, false), pts, 2);
    ASSERT_FALSE(gpu.empty());
    double exact = 0, hardware = 0;
    for (int i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c) {
        const double h = host(c, pts[4 * i], pts[4 * i + 1], pts[4 * i + 2]);
        exact = std::max(exact, std::fabs(gpu[8 * i + 4 + c] - h));
        hardware = std::max(hardware, std::fabs(gpu[8 * i + c] - h));
      }
    std::printf("%-46s exact %.1e  hardware %.1e\n", file.c_str(), exact, hardware);
    EXPECT_LT(exact, 2e-6) << file;     // the same texels and weights, float arithmetic
    EXPECT_LT(hardware, 2e-5) << file;  // llvmpipe filters with float weights
    if (node) {
      // mu = 1, r = 0 at eta 0.6: the smooth interface, E_R = F0, E_T = 1 - F0
      const double f0 = std::pow((er.first - 1) / (er.first + 1), 2);
      EXPECT_NEAR(gpu[4], f0, 1e-6) << file;
      EXPECT_NEAR(gpu[5], 1 - f0, 1e-6) << file;
    }
  }
  const std::string avgPath = (d / "glassavg/dielectric-avg_ggx_smith-correlated.exr").string();
  TableImage a = readTableExr(avgPath);
  const auto sr = a.v2f.at("brdf.s.range");
  std::vector<float> pts;
  for (float r : {0.1f, 0.5f, 0.9f})
    for (float eta : {0.5f, 1.0f, 1.33f, 2.0f}) pts.insert(pts.end(), {r, eta, 0.0f, 0.0f});
  const std::string P = shaderPrefix(avgPath);
  std::vector<float> gpu = glharness::runOnGpu(shaderForTable(avgPath, a, ShaderLang::Glsl),
                                               "  res[i] = vec4(" + P + "_albedosAvgExact(tab, p.x, p.y), 0.0);\n",
                                               texels(a, false), pts, 1);
  ASSERT_FALSE(gpu.empty());
  for (size_t i = 0; i < pts.size() / 4; ++i) {
    const double r = pts[4 * i], eta = pts[4 * i + 1], s = (eta - 1) / (eta + 1);
    const double px = std::clamp(r * a.width - 0.5, 0.0, a.width - 1.0);
    const double py = std::clamp((s - sr.first) / (sr.second - sr.first) * a.height - 0.5, 0.0, a.height - 1.0);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(gpu[4 * i + c], bilinear(a, c, px, py), 2e-6) << "r " << r << " eta " << eta << " channel " << c;
  }
}

}  // namespace
