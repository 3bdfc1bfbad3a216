// Every format and precision the baker writes, through the real GL pipeline (gl_harness.h): the
// split-sum and albedo tables baked as exr (float32, float16), ktx2 and dds (float32, float16,
// unorm16, unorm8) and png16 (unorm16, also a scaled mapping), each file read by a reader other
// than our writer (tests/ktx2_reader.h, tests/dds_reader.h, OpenImageIO for PNG and EXR), uploaded
// in the matching GL internal format (RGBA32F, RGBA16F, RGBA16 through GL_EXT_texture_norm16,
// RGBA8), sampled through the GLSL `brdfbake shader` generates from the file's own metadata (for
// png16 its value mapping is built in) and compared:
//   (1) with the host's bilinear lookup of the texels the reader decoded (float arithmetic; on the
//       hardware path, the filter's precision);
//   (2) with the float32 table (the storage rounding: within the file's brdf.error.storage);
//   (3) with the independent reference, within brdf.error + brdf.interp-error (the exact path)
//       plus, on the hardware path, the filter's deviation measured in (1).
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <Imath/half.h>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <random>
#include <sstream>

#include "common/models.h"
#include "dds_reader.h"
#include "doc_figures.h"
#include "formats/exr/table_file.h"
#include "formats/storage.h"
#include "gl_harness.h"
#include "ktx2_reader.h"
#include "reference/reference.h"
#include "shader/shader_gen.h"

namespace fs = std::filesystem;
namespace {
using namespace brdfbake;
using brdfbake::testing_docs::expectPagesQuote;
using brdfbake::testing_docs::sci;
using glharness::gl;

// One bake per precision (the formats that hold it), plus a png16 whose mapping is not the identity
// (k_p, 1D, reaches 2.95: scale > 1).
fs::path bakeDir() {
  static fs::path d = [] {
    fs::path dir = fs::path(testing::TempDir()) / ("brdfbake_glfmt_" + std::to_string(getpid()));
    fs::remove_all(dir);
    const std::string exe = std::string("'") + BRDFBAKE_EXE + "' --size 32 --table ";
    for (std::string args :
         {"splitsum,albedo --grid node --format exr,ktx2,dds --precision float32 -o '" + (dir / "float32").string() +
              "'",
          "splitsum,albedo --grid node --format exr,ktx2,dds --precision float16 -o '" + (dir / "float16").string() +
              "'",
          "splitsum,albedo --grid node --format ktx2,dds,png16 --precision unorm16 -o '" + (dir / "unorm16").string() +
              "'",
          "splitsum,albedo --grid node --format ktx2,dds --precision unorm8 -o '" + (dir / "unorm8").string() + "'",
          "kp --format exr,png16 -o '" + (dir / "scaled").string() + "'"})
      EXPECT_EQ(std::system((exe + args + " > /dev/null").c_str()), 0) << args;
    return dir;
  }();
  return d;
}

// A file as the GPU and the host see it: the texels to upload, the values they stand for (RGB
// planes, after the file's mapping) and the header the shader code is generated from.
struct Loaded {
  glharness::Texels tex;
  std::vector<std::vector<float>> planes;
  TableImage header;
  double scale = 1, offset = 0;  // png16's mapping
};

// Texels decoded as doubles (components per texel) -> the GL upload of precision `p`, and planes.
void fromDecoded(Loaded& l, const std::vector<double>& texels, int components, const std::string& p) {
  const size_t n = static_cast<size_t>(l.tex.width) * l.tex.height;
  l.planes.assign(3, std::vector<float>(n));
  std::vector<float> f32(n * 4, 1.0f);
  std::vector<uint16_t> u16(n * 4);
  std::vector<uint8_t> u8(n * 4);
  for (size_t i = 0; i < n; ++i)
    for (int c = 0; c < 4; ++c) {
      const double v = c < components ? texels[i * components + c] : 1.0;
      if (c < 3) l.planes[c][i] = static_cast<float>(v);
      f32[i * 4 + c] = static_cast<float>(v);
      u16[i * 4 + c] =
          p == "float16" ? Imath::half(static_cast<float>(v)).bits() : static_cast<uint16_t>(std::lround(v * 65535));
      u8[i * 4 + c] = static_cast<uint8_t>(std::lround(v * 255));
    }
  if (p == "float32") l.tex.internalFormat = GL_RGBA32F, l.tex.type = GL_FLOAT, l.tex.assign(f32);
  if (p == "float16") l.tex.internalFormat = GL_RGBA16F, l.tex.type = GL_HALF_FLOAT, l.tex.assign(u16);
  if (p == "unorm16") l.tex.internalFormat = glharness::kRgba16Ext, l.tex.type = GL_UNSIGNED_SHORT, l.tex.assign(u16);
  if (p == "unorm8") l.tex.internalFormat = GL_RGBA8, l.tex.type = GL_UNSIGNED_BYTE, l.tex.assign(u8);
}

Loaded loadKtx2(const std::string& path) {
  ktx2check::Texture t = ktx2check::read(path);
  EXPECT_TRUE(t.problems.empty()) << path << ": " << (t.problems.empty() ? "" : t.problems[0]);
  Loaded l;
  l.tex.width = static_cast<int>(t.width);
  l.tex.height = static_cast<int>(t.height);
  l.header = tableHeaderFromText(l.tex.width, l.tex.height, t.kv);
  fromDecoded(l, t.texels, t.components, l.header.strings["brdf.precision"]);
  return l;
}

// DDS has no metadata: its texels are the KTX2 sibling's (same precision, same packing), whose
// key/value data describes them (the bake's report states the same error for both).
Loaded loadDds(const std::string& path, const std::string& precision) {
  ddscheck::Texture t = ddscheck::read(path);
  EXPECT_TRUE(t.problems.empty()) << path << ": " << (t.problems.empty() ? "" : t.problems[0]);
  Loaded l;
  l.tex.width = static_cast<int>(t.width);
  l.tex.height = static_cast<int>(t.height);
  l.header =
      tableHeaderFromText(l.tex.width, l.tex.height, ktx2check::read(path.substr(0, path.size() - 4) + ".ktx2").kv);
  fromDecoded(l, t.texels, t.components, precision);
  return l;
}

// PNG and EXR through OpenImageIO: the samples, and (PNG) the text chunks as the header.
Loaded loadOiio(const std::string& path) {
  Loaded l;
  auto in = OIIO::ImageInput::open(path);
  EXPECT_TRUE(in) << OIIO::geterror();
  if (!in) return l;
  const OIIO::ImageSpec& spec = in->spec();
  l.tex.width = spec.width;
  l.tex.height = spec.height;
  const bool png = path.size() > 4 && path.compare(path.size() - 4, 4, ".png") == 0;
  const size_t n = static_cast<size_t>(spec.width) * spec.height;
  if (png) {
    std::map<std::string, std::string> kv;
    for (const auto& a : spec.extra_attribs) kv[a.name().string()] = a.get_string();
    l.header = tableHeaderFromText(spec.width, spec.height, kv);
    l.scale = std::stod(kv.at("brdf.mapping.scale"));
    l.offset = std::stod(kv.at("brdf.mapping.offset"));
    std::vector<uint16_t> px(n * 3), rgba(n * 4, 65535);
    EXPECT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT16, px.data()));
    l.planes.assign(3, std::vector<float>(n));
    for (size_t i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c) {
        rgba[i * 4 + c] = px[i * 3 + c];
        l.planes[c][i] = static_cast<float>(px[i * 3 + c] / 65535.0 * l.scale + l.offset);
      }
    l.tex.internalFormat = glharness::kRgba16Ext;
    l.tex.type = GL_UNSIGNED_SHORT;
    l.tex.assign(rgba);
  } else {
    l.header = readTableExrHeader(path);
    std::vector<float> px(n * 3);
    EXPECT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, px.data()));
    std::vector<double> d(px.begin(), px.end());
    fromDecoded(l, d, 3, tableExrIsHalf(path) ? "float16" : "float32");
  }
  return l;
}

// The independent reference (adaptive quadrature in double) of channel c at (x = mu, y = r).
double referenceAt(const TableImage& h, double x, double y, int c) {
  const std::string table = h.strings.at("brdf.table");
  if (table == "kp") return reference::kp(ndfId(h.strings.at("brdf.ndf")), x);
  reference::Moments m = reference::albedo(ndfId(h.strings.at("brdf.ndf")), gafId(h.strings.at("brdf.gaf")), y, x);
  if (table == "albedo") return m.a + m.b;
  return c == 0 ? m.a : c == 1 ? m.b : m.a + m.b;
}

struct Figures {
  double exact = 0, hardware = 0, weights8 = 0, storage = 0, refExact = 0, refHardware = 0;
};

// Samples `l` through its generated lookups at 4000 points (the reference at 60 of them); `f32`
// is the float32 table the file was stored from.
Figures check(const std::string& name, const Loaded& l, const TableImage& f32) {
  const std::string P = shaderPrefix(name);
  const bool node = l.header.strings.at("brdf.grid") == "node";
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<float> pts;
  const int n = 4000, refPoints = 60;
  for (int i = 0; i < n; ++i)
    pts.insert(pts.end(), {i < 4 ? float(i & 1) : u(rng), i < 4 ? float(i >> 1) : u(rng), 0, 0});
  const std::string call = l.tex.height == 1 ? "p.x" : "p.x, p.y";  // 1D tables: one argument
  std::vector<float> gpu = glharness::runOnGpu(shaderForTable(name, l.header, ShaderLang::Glsl),
                                               "  res[2 * i] = " + P + "_lookup(tab, " + call +
                                                   ");\n  res[2 * i + 1] = " + P + "_lookupExact(tab, " + call + ");\n",
                                               l.tex, pts, 2);
  Figures f;
  if (gpu.empty()) return f;
  const int w = l.tex.width, h = l.tex.height;
  for (int i = 0; i < n; ++i) {
    const double x = pts[4 * i], y = pts[4 * i + 1];
    const double px = node ? x * (w - 1) : x * w - 0.5, py = h == 1 ? 0 : node ? y * (h - 1) : y * h - 0.5;
    for (int c = 0; c < 3; ++c) {
      const double host = glharness::bilinear(l.planes, w, h, c, px, py), s = std::max(1.0, std::fabs(host));
      const double full = glharness::bilinear(f32.planes, w, h, c, px, py);
      f.exact = std::max(f.exact, std::fabs(gpu[8 * i + 4 + c] - host) / s);
      f.hardware = std::max(f.hardware, std::fabs(gpu[8 * i + c] - host) / s);
      f.weights8 = std::max(f.weights8, std::fabs(glharness::bilinear(l.planes, w, h, c, px, py, 8) - host) / s);
      f.storage = std::max(f.storage, std::fabs(host - full) / std::max(1.0, std::fabs(full)));
      if (i >= refPoints) continue;
      const double want = referenceAt(l.header, x, y, c), ws = std::max(1.0, std::fabs(want));
      f.refExact = std::max(f.refExact, std::fabs(gpu[8 * i + 4 + c] - want) / ws);
      f.refHardware = std::max(f.refHardware, std::fabs(gpu[8 * i + c] - want) / ws);
    }
  }
  return f;
}

double leadingNumber(const TableImage& h, const std::string& key) {
  auto it = h.strings.find(key);
  return it == h.strings.end() ? -1 : std::strtod(it->second.c_str(), nullptr);
}

TEST(GlPipeline, EveryFormatAndPrecisionSamplesWithinItsPredictedError) {
  ASSERT_TRUE(gl().problem.empty()) << "no usable OpenGL ES through EGL: " << gl().problem;
  ASSERT_TRUE(gl().norm16) << "llvmpipe lacks GL_EXT_texture_norm16: unorm16 tables cannot be uploaded as RGBA16";
  const fs::path d = bakeDir();
  struct Case {
    std::string dir, format;
  };
  const std::vector<Case> cases = {{"float32", "exr"},  {"float32", "ktx2"}, {"float32", "dds"},  {"float16", "exr"},
                                   {"float16", "ktx2"}, {"float16", "dds"},  {"unorm16", "ktx2"}, {"unorm16", "dds"},
                                   {"unorm16", "png"},  {"unorm8", "ktx2"},  {"unorm8", "dds"},   {"scaled", "png"}};
  // the table docs/shader-code.md shows, a row per file
  std::ostringstream table;
  table << "| file (GL internal format) | GPU exact vs host bilinear | GPU hardware vs host bilinear | 8-bit weights "
           "emulated | storage (file states) | vs reference, exact path (predicted) | hardware path (predicted) |\n"
           "|---|---|---|---|---|---|---|\n";
  int checked = 0;
  for (const Case& k : cases)
    for (std::string stem : {"splitsum_ggx_smith-correlated", "albedo_ggx_smith-correlated", "kp_ggx"}) {
      const fs::path file = d / k.dir / (stem + "." + k.format);
      if (!fs::exists(file)) continue;
      const std::string path = file.string();
      const std::string precision = k.dir == "scaled" ? "unorm16" : k.dir;
      Loaded l = k.format == "ktx2" ? loadKtx2(path) : k.format == "dds" ? loadDds(path, precision) : loadOiio(path);
      // the float32 table it was stored from: the EXR of the float32 bake (of its own bake: scaled)
      const TableImage f32 = readTableExr((d / (k.dir == "scaled" ? "scaled" : "float32") / (stem + ".exr")).string());
      Figures f = check(path, l, f32);
      const double predicted = l.header.floats.at("brdf.error") + l.header.floats.at("brdf.interp-error");
      // EXR states no storage part (its brdf.error includes it): the a priori bound of its precision
      const double stated = k.format == "exr"
                                ? storageErrorBound(precision == "float16" ? Precision::Float16 : Precision::Float32)
                                : leadingNumber(l.header, "brdf.error.storage");
      // llvmpipe's filter: float weights on float and 16-bit textures, within twice the 8-bit
      // weights NVIDIA documents (emulated on the same texels: rounding either way)
      // llvmpipe filters RGBA8 in 8-bit fixed point: its result is a whole code (1/255) off at worst
      const double filter = precision == "unorm8" ? 1.0 / 255 + f.weights8 : std::max(2e-5, 2.0 * f.weights8);
      const std::map<std::string, std::string> internal = {
          {"float32", "RGBA32F"}, {"float16", "RGBA16F"}, {"unorm16", "RGBA16"}, {"unorm8", "RGBA8"}};
      table << "| " << k.format << " " << precision << (k.dir == "scaled" ? " scaled" : "") << " ("
            << internal.at(precision) << "): "
            << (stem[0] == 's'   ? "split sum"
                : stem[0] == 'a' ? "albedo"
                                 : "k_p")
            << " | " << sci(f.exact, 1) << " | " << sci(f.hardware, 1) << " | " << sci(f.weights8, 1) << " | "
            << sci(f.storage, 1) << " (" << sci(stated, 1) << ") | " << sci(f.refExact, 2) << " (" << sci(predicted, 2)
            << ") | " << sci(f.refHardware, 2) << " (" << sci(predicted + filter, 2) << ") |\n";
      ++checked;
      if (k.format != "exr") {
        EXPECT_EQ(l.header.strings["brdf.precision"], precision) << path;
      }
      EXPECT_LT(f.exact, 4e-6) << path;  // the same texels and weights, float arithmetic
      EXPECT_LT(f.hardware, filter) << path;
      // float32 holds the computed floats exactly: its stated rounding is 0, but it is stated
      EXPECT_TRUE(k.format == "exr" || l.header.strings.count("brdf.error.storage"))
          << path << ": no brdf.error.storage";
      if (precision != "float32") {
        EXPECT_GT(stated, 0) << path << ": brdf.error.storage states no rounding";
      }
      EXPECT_LE(f.storage, stated + 1e-6) << path;  // the rounding the file states, no more
      if (precision != "float32") {
        EXPECT_GT(f.storage, stated / 4) << path << ": not the stated rounding";
      }
      EXPECT_LE(f.refExact, predicted) << path;
      EXPECT_LE(f.refHardware, predicted + filter) << path;
    }
  EXPECT_EQ(checked, 23);
  std::printf("%s", table.str().c_str());
  expectPagesQuote(table.str());
}

// The scaled png16's lookups must include its mapping: the same texels without it read as [0, 1].
TEST(GlPipeline, Png16MappingIsBuiltIntoTheGeneratedCode) {
  const std::string path = (bakeDir() / "scaled" / "kp_ggx.png").string();
  Loaded l = loadOiio(path);
  EXPECT_GT(l.scale, 1.5);
  const std::string code = shaderForTable(path, l.header, ShaderLang::Glsl);
  EXPECT_NE(code.find("* vec4(" + std::string(l.header.strings.at("brdf.mapping.scale")).substr(0, 5)),
            std::string::npos)
      << code;
  TableImage plain = l.header;
  plain.strings.erase("brdf.mapping.scale");
  plain.strings.erase("brdf.mapping.offset");
  plain.floats.erase("brdf.mapping.scale");
  plain.floats.erase("brdf.mapping.offset");
  EXPECT_EQ(shaderForTable(path, plain, ShaderLang::Glsl).find("* vec4("), std::string::npos);
}

}  // namespace
