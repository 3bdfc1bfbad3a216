// The LTC tables as engines load them, on the GL pipeline: one bake in every format that carries
// four float channels (EXR, KTX2 and DDS as RGBA32F, the .mjs module three.js imports and the .h
// array), each decoded by a reader other than our writer (tests/ktx2_reader.h, tests/dds_reader.h,
// the module's text), must hold the EXR's texels exactly, in the same order; then each is uploaded
// as RGBA32F and sampled with three.js's own lookup (LTC_Uv: uv = (r, sqrt(1 - n.v)) (n - 1)/n +
// 0.5/n, texture()), which must match the host's bilinear lookup of the EXR on the node grid.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_run.h"
#include "dds_reader.h"
#include "formats/exr/table_file.h"
#include "gl_harness.h"
#include "ktx2_reader.h"

namespace fs = std::filesystem;
using namespace brdfbake;
using namespace brdfbake::testing_cli;

namespace {

// The numbers of a generated .mjs or .h array (after `open`, up to the closing bracket).
std::vector<double> arrayOf(const fs::path& file, const std::string& open, const std::string& close) {
  std::ifstream in(file);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  const size_t at = text.find(open);
  EXPECT_NE(at, std::string::npos) << file << ": no '" << open << "'";
  if (at == std::string::npos) return {};
  const size_t end = text.find(close, at + open.size());
  std::stringstream items(text.substr(at + open.size(), end - at - open.size()));
  std::vector<double> v;
  for (std::string item; std::getline(items, item, ',');) {
    const size_t d = item.find_first_of("-0123456789");
    if (d != std::string::npos) v.push_back(std::stod(item.substr(d)));
  }
  return v;
}

// Bilinear on the node grid, x = r, y = sqrt(1 - mu), channel c.
double hostLookup(const TableImage& t, int c, double mu, double r) {
  const int n = t.width;
  const double px = r * (n - 1), py = std::sqrt(1 - mu) * (n - 1);
  const int x0 = std::min(static_cast<int>(px), n - 2), y0 = std::min(static_cast<int>(py), n - 2);
  const double fx = px - x0, fy = py - y0;
  auto at = [&](int x, int y) { return static_cast<double>(t.planes[c][static_cast<size_t>(y) * n + x]); };
  return (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x0 + 1, y0)) + fy * ((1 - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1));
}

TEST(GlPipeline, LtcFilesSampleAsThreeJsReadsThem) {
  ASSERT_TRUE(glharness::gl().problem.empty()) << glharness::gl().problem;
  const fs::path dir = freshDir("gl-ltc", "bake");
  const int n = 16;
  CmdResult r = run("bake --table ltc --size 16 --format exr,ktx2,dds,header -o '" + dir.string() + "'");
  ASSERT_EQ(r.code, 0) << r.out;
  // points over (mu, r), the edges included
  std::vector<float> pts;
  for (int i = 0; i <= 24; ++i)
    for (int j = 0; j <= 24; ++j) pts.insert(pts.end(), {static_cast<float>(i / 24.0), static_cast<float>(j / 24.0), 0, 0});
  const std::string N = std::to_string(n) + ".0";
  const std::string body = "  vec2 uv = vec2(p.y, sqrt(1.0 - p.x)) * ((" + N + " - 1.0) / " + N + ") + 0.5 / " + N +
                           ";\n  res[i] = texture(tab, uv);\n";
  for (const std::string file : {"ltc1_ggx_smith-correlated", "ltc2_ggx_smith-correlated"}) {
    const TableImage exr = readTableExr((dir / (file + ".exr")).string());
    ASSERT_EQ(exr.planes.size(), 4u);
    const size_t texels = static_cast<size_t>(n) * n;
    std::vector<std::pair<std::string, std::vector<double>>> decoded;
    ktx2check::Texture k = ktx2check::read((dir / (file + ".ktx2")).string());
    EXPECT_TRUE(k.problems.empty()) << (k.problems.empty() ? "" : k.problems[0]);
    EXPECT_EQ(k.components, 4);
    decoded.push_back({"ktx2", k.texels});
    ddscheck::Texture d = ddscheck::read((dir / (file + ".dds")).string());
    EXPECT_TRUE(d.problems.empty()) << (d.problems.empty() ? "" : d.problems[0]);
    EXPECT_EQ(d.components, 4);
    decoded.push_back({"dds", d.texels});
    decoded.push_back({"mjs", arrayOf(dir / (file + ".mjs"), "Float32Array.from([", "])")});
    decoded.push_back({"h", arrayOf(dir / (file + ".h"), "_data[" + std::to_string(texels * 4) + "] = {", "}")});
    for (const auto& [format, v] : decoded) {
      ASSERT_EQ(v.size(), texels * 4) << file << "." << format;
      for (size_t t = 0; t < texels; ++t)
        for (int c = 0; c < 4; ++c)
          ASSERT_EQ(static_cast<float>(v[t * 4 + c]), exr.planes[c][t]) << file << "." << format << " texel " << t;
      // the engine's upload and lookup
      glharness::Texels tex;
      tex.width = tex.height = n;
      std::vector<float> f(v.begin(), v.end());
      tex.assign(f);
      const std::vector<float> got = glharness::runOnGpu("", body, tex, pts, 1);
      ASSERT_EQ(got.size(), pts.size()) << file << "." << format;
      for (size_t q = 0; q < pts.size() / 4; ++q)
        for (int c = 0; c < 4; ++c) {
          const double want = hostLookup(exr, c, pts[q * 4], pts[q * 4 + 1]);
          // llvmpipe filters with 8-bit weights: within 1/256 of the texels' spread, and float
          double lo = 1e30, hi = -1e30;
          for (size_t t = 0; t < texels; ++t) lo = std::min<double>(lo, exr.planes[c][t]), hi = std::max<double>(hi, exr.planes[c][t]);
          EXPECT_NEAR(got[q * 4 + c], want, (hi - lo) / 256 + 1e-6 * (1 + std::fabs(want)))
              << file << "." << format << " mu = " << pts[q * 4] << ", r = " << pts[q * 4 + 1] << " channel " << c;
        }
    }
  }
}

}  // namespace
