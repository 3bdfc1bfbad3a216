// Layout presets on the GL pipeline: each preset's file, read by a reader other than our writer
// (tests/ktx2_reader.h, tests/dds_reader.h, OpenImageIO for PNG; our EXR reader where the preset
// writes EXR) and uploaded as the engine does (unreal: unorm16 RG; the glTF Sample Viewer: 8-bit
// RGBA from its PNG), sampled with that engine's own lookup expression, written here in GLSL from the
// convention cited in host/formats/layout.cpp, must match the reference F0 A + B within the file's
// brdf.error + brdf.interp-error, and agree with the generated code's Schlick lookup (which builds
// the layout in). The flags without a preset (--axes r,mu --flip-y --channels B,A+B) through the
// generated code; an unknown preset exits 64 with the list and writes nothing. unity-hdrp-sqrt:
// HDRP's current lookup, x = sqrt(NdotV) on a node grid (Remap01ToHalfTexelCoord), at its 64^2; the
// older linear-NdotV expression must not match that file.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

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
#include "gl_harness.h"
#include "ktx2_reader.h"
#include "reference/reference.h"
#include "shader/shader_gen.h"

namespace fs = std::filesystem;
namespace {
using namespace brdfbake;
using glharness::gl;
using testing_docs::expectPagesQuote;
using testing_docs::sci;

fs::path dir() {
  static fs::path d = fs::path(testing::TempDir()) / ("brdfbake_glpre_" + std::to_string(getpid()));
  return d;
}

int bake(const std::string& args) {
  const std::string cmd = std::string("'") + BRDFBAKE_EXE + "' --table splitsum " + args + " > /dev/null 2>&1";
  const int rc = std::system(cmd.c_str());
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

struct File {
  std::string path;
  TableImage header;
  glharness::Texels tex;
};

// The file, read by a reader other than our writer, as the engine uploads it, and its header:
// KTX2 (tests/ktx2_reader.h) and EXR as RGBA32F (float16 and float32 values are exact in float);
// DDS (tests/dds_reader.h, unorm16) as RGBA16 codes, its header the KTX2 twin's key/value data
// (DDS has none); PNG (OpenImageIO) as RGBA8, the 8 bits of each 16-bit sample a browser's decoder
// hands WebGL's texImage2D(RGBA, UNSIGNED_BYTE), its header the text chunks.
File load(const std::string& path) {
  File f;
  f.path = path;
  const std::string ext = path.substr(path.rfind('.'));
  std::vector<float> px;
  if (ext == ".ktx2") {
    ktx2check::Texture t = ktx2check::read(f.path);
    EXPECT_TRUE(t.problems.empty()) << f.path;
    f.header = tableHeaderFromText(static_cast<int>(t.width), static_cast<int>(t.height), t.kv);
    px.assign(static_cast<size_t>(t.width) * t.height * 4, 0.0f);
    for (size_t i = 0; i < px.size() / 4; ++i)
      for (int c = 0; c < t.components && c < 4; ++c)
        px[i * 4 + c] = static_cast<float>(t.texels[i * t.components + c]);
  } else if (ext == ".dds") {
    ddscheck::Texture t = ddscheck::read(f.path);
    EXPECT_TRUE(t.problems.empty()) << f.path;
    EXPECT_TRUE(!t.isFloat && t.bits == 16) << "the unreal preset stores unorm16, as PF_G16R16";
    const std::string twin = path.substr(0, path.size() - 4) + ".ktx2";
    f.header = tableHeaderFromText(static_cast<int>(t.width), static_cast<int>(t.height), ktx2check::read(twin).kv);
    std::vector<uint16_t> codes(static_cast<size_t>(t.width) * t.height * 4, 0);
    for (size_t i = 0; i < codes.size() / 4; ++i)
      for (int c = 0; c < t.components && c < 4; ++c)
        codes[i * 4 + c] = static_cast<uint16_t>(std::lround(t.texels[i * t.components + c] * 65535.0));
    f.tex.internalFormat = glharness::kRgba16Ext;
    f.tex.type = GL_UNSIGNED_SHORT;
    f.tex.width = f.header.width;
    f.tex.height = f.header.height;
    f.tex.assign(codes);
    return f;
  } else if (ext == ".png") {
    auto in = OIIO::ImageInput::open(path);
    EXPECT_TRUE(in) << OIIO::geterror();
    if (!in) return f;
    const OIIO::ImageSpec& spec = in->spec();
    std::map<std::string, std::string> kv;
    for (const auto& a : spec.extra_attribs) kv[a.name().string()] = a.get_string();
    f.header = tableHeaderFromText(spec.width, spec.height, kv);
    const size_t n = static_cast<size_t>(spec.width) * spec.height;
    std::vector<uint16_t> samples(n * 3);
    EXPECT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT16, samples.data()));
    std::vector<uint8_t> bytes(n * 4, 255);
    for (size_t i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c) bytes[i * 4 + c] = static_cast<uint8_t>(std::lround(samples[i * 3 + c] / 257.0));
    f.tex.internalFormat = GL_RGBA8;
    f.tex.type = GL_UNSIGNED_BYTE;
    f.tex.width = spec.width;
    f.tex.height = spec.height;
    f.tex.assign(bytes);
    return f;
  } else {
    f.header = readTableExr(f.path);
    px.assign(static_cast<size_t>(f.header.width) * f.header.height * 4, 0.0f);
    for (size_t i = 0; i < px.size() / 4; ++i)
      for (size_t c = 0; c < f.header.planes.size(); ++c) px[i * 4 + c] = f.header.planes[c][i];
  }
  f.tex.width = f.header.width;
  f.tex.height = f.header.height;
  f.tex.assign(px);
  return f;
}

struct Figures {
  double engine = 0, generated = 0, agree = 0, predicted = 0;
};

// `expr`: the engine's GLSL, reading p.x = NoV, p.y = roughness, p.z = f0, writing vec3 spec.
Figures run(const File& f, const std::string& expr) {
  const std::string P = shaderPrefix(f.path);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<float> pts;
  const int n = 2000, refPoints = 60;
  for (int i = 0; i < n; ++i) pts.insert(pts.end(), {u(rng), u(rng), i % 2 ? 1.0f : 0.04f, 0});
  std::vector<float> gpu = glharness::runOnGpu(shaderForTable(f.path, f.header, ShaderLang::Glsl),
                                               "  vec3 spec = vec3(0.0);\n" + (expr.empty() ? "" : "  " + expr + "\n") +
                                                   "  res[2 * i] = vec4(spec, 0.0);\n" + "  res[2 * i + 1] = vec4(" +
                                                   P + "_Schlick(tab, vec3(p.z), p.x, p.y), 0.0);\n",
                                               f.tex, pts, 2);
  Figures fig;
  fig.predicted = f.header.floats.at("brdf.error") + f.header.floats.at("brdf.interp-error") +
                  (f.tex.type == GL_UNSIGNED_BYTE ? 2.0 / 255 : 0.0);  // 8 bits: rounding, and llvmpipe's 8-bit filter
  if (gpu.empty()) return fig;
  const int ndf = ndfId(f.header.strings.at("brdf.ndf")), gaf = gafId(f.header.strings.at("brdf.gaf"));
  for (int i = 0; i < n; ++i) {
    fig.agree = std::max(fig.agree, static_cast<double>(std::fabs(gpu[8 * i] - gpu[8 * i + 4])));
    if (i >= refPoints) continue;
    reference::Moments m = reference::albedo(ndf, gaf, pts[4 * i + 1], pts[4 * i]);
    const double want = pts[4 * i + 2] * m.a + m.b, s = std::max(1.0, std::fabs(want));
    fig.engine = std::max(fig.engine, std::fabs(gpu[8 * i] - want) / s);
    fig.generated = std::max(fig.generated, std::fabs(gpu[8 * i + 4] - want) / s);
  }
  return fig;
}

TEST(GlPipeline, LayoutPresetsMatchEachEnginesOwnLookup) {
  ASSERT_TRUE(gl().problem.empty()) << "no usable OpenGL ES through EGL: " << gl().problem;
  // the engines' expressions (host/formats/layout.cpp cites the code each follows)
  const std::vector<std::pair<std::string, std::string>> engines = {
      // Filament light_indirect.fs: dfg = textureLod(light_iblDFG, vec2(NoV, roughness), 0.0).rg; mix(dfg.xxx, dfg.yyy,
      // f0)
      {"filament", "vec2 dfg = textureLod(tab, vec2(p.x, p.y), 0.0).rg; spec = mix(dfg.xxx, dfg.yyy, vec3(p.z));"},
      // Bevy environment_map.wgsl: f_ab = textureSample(lut, s, vec2(NdotV, perceptual_roughness)).rg; kS * f_ab.x +
      // f_ab.y
      {"bevy", "vec2 f_ab = textureLod(tab, vec2(p.x, p.y), 0.0).rg; spec = vec3(p.z) * f_ab.x + f_ab.y;"},
      // HDRP PreIntegratedFGD.hlsl: preFGD = SAMPLE(float2(NdotV, perceptualRoughness)).xyz; lerp(preFGD.xxx,
      // preFGD.yyy, f0)
      {"unity-hdrp", "vec3 pre = textureLod(tab, vec2(p.x, p.y), 0.0).xyz; spec = mix(pre.xxx, pre.yyy, vec3(p.z));"},
      // HDRP's current GetPreIntegratedFGDGGXAndDisneyDiffuse: coordLUT = Remap01ToHalfTexelCoord(float2(sqrt(NdotV),
      // perceptualRoughness), FGDTEXTURE_RESOLUTION), Remap01ToHalfTexelCoord (core Common.hlsl) = coord * (1 - 1/size)
      // + 0.5/size, FGDTEXTURE_RESOLUTION 64 (PreIntegratedFGD.cs.hlsl); lerp(preFGD.xxx, preFGD.yyy, fresnel0)
      {"unity-hdrp-sqrt",
       "vec2 coordLUT = vec2(sqrt(p.x), p.y) * (1.0 - 1.0 / 64.0) + 0.5 / 64.0; vec3 pre = textureLod(tab, coordLUT, "
       "0.0).xyz; "
       "spec = mix(pre.xxx, pre.yyy, vec3(p.z));"},
      // Unreal BRDF.ush EnvBRDF: AB = Texture2DSampleLevel(PreIntegratedGF, s, float2(NoV, Roughness), 0).rg;
      // SpecularColor * AB.x + saturate(50.0 * SpecularColor.g) * AB.y
      {"unreal",
       "vec2 AB = textureLod(tab, vec2(p.x, p.y), 0.0).rg; spec = vec3(p.z) * AB.x + clamp(50.0 * p.z, 0.0, 1.0) * "
       "AB.y;"},
      // glTF Sample Viewer ibl.glsl: brdf = texture(u_GGXLUT, clamp(vec2(NdotV, perceptualRoughness), 0, 1)).rg;
      // specularColor * brdf.x + brdf.y (textureLod at 0: a compute shader has no implicit level; the LUT has one)
      {"gltf-sample-viewer",
       "vec2 brdf = textureLod(tab, clamp(vec2(p.x, p.y), vec2(0.0), vec2(1.0)), 0.0).rg; spec = vec3(p.z) * brdf.x + "
       "brdf.y;"}};
  // the table docs/layouts.md shows
  std::ostringstream table;
  table << "| preset (size, file) | engine's expression vs reference F0 A + B | generated `P_Schlick` vs reference | "
           "predicted (`brdf.error + brdf.interp-error`) | engine vs generated |\n|---|---|---|---|---|\n";
  for (const auto& [name, expr] : engines) {
    // the preset's own format; the DDS (no metadata) with its KTX2 twin beside it for the header
    const std::string ext = name == "unreal"                   ? ".dds"
                            : name == "gltf-sample-viewer"     ? ".png"
                            : name.rfind("unity-hdrp", 0) == 0 ? ".exr"
                                                               : ".ktx2";
    // 32^2, but HDRP's sqrt lookup at its own FGDTEXTURE_RESOLUTION (the preset's 64), built into its expression
    const std::string size = name == "unity-hdrp-sqrt" ? "" : " --size 32";
    // the DDS preset writes its KTX2 twin itself
    ASSERT_EQ(bake("--layout " + name + size + " -o '" + (dir() / name).string() + "'"), 0) << name;
    File f = load((dir() / name / ("splitsum_ggx_smith-correlated_" + name)).string() + ext);
    EXPECT_EQ(f.header.strings["brdf.layout"], name) << "info names the preset";
    EXPECT_NE(f.header.strings["brdf.layout.sampling"].find(name == "unreal" ? "EnvBRDF" : ""), std::string::npos);
    Figures fig = run(f, expr);
    table << "| `" << name << "` (" << f.tex.width << "^2, " << f.path.substr(f.path.rfind('.') + 1) << ") | "
          << sci(fig.engine, 2) << " | " << sci(fig.generated, 2) << " | " << sci(fig.predicted, 2) << " | "
          << sci(fig.agree, 1) << " |\n";
    EXPECT_LE(fig.engine, fig.predicted) << name << ": the engine's lookup of our file is off the reference";
    EXPECT_LE(fig.generated, fig.predicted) << name;
    EXPECT_LT(fig.agree, 2e-5) << name << ": the generated code does not follow the layout";
  }
  // the older HDRP lookup (linear NdotV at texel centres) of the sqrt file: the axis matters
  {
    File f = load((dir() / "unity-hdrp-sqrt" / "splitsum_ggx_smith-correlated_unity-hdrp-sqrt.exr").string());
    Figures fig = run(f, engines[2].second);
    char off[16];
    std::snprintf(off, sizeof off, "%.2f", fig.engine);
    table << "| `unity-hdrp-sqrt` (" << f.tex.width << "^2, exr) read by the older linear-NdotV lookup | " << off
          << " (caught) | " << sci(fig.generated, 2) << " | " << sci(fig.predicted, 2) << " | - |\n";
    EXPECT_GT(fig.engine, 0.05) << "a linear-NdotV reader must not match the sqrt(NdotV) file";
  }
  // without a preset: transposed, flipped, (B, A+B); the engines' plain expression must then fail
  ASSERT_EQ(
      bake("--axes r,mu --flip-y --channels B,A+B --size 32 --format exr -o '" + (dir() / "flags").string() + "'"), 0);
  File f = load((dir() / "flags" / "splitsum_ggx_smith-correlated_r-mu_flip-y_B-AB.exr").string());
  EXPECT_EQ(f.header.strings["brdf.axes"], "r,mu");
  EXPECT_EQ(f.header.strings["brdf.layout.flip"], "y");
  Figures fig = run(f, "vec2 ab = textureLod(tab, vec2(p.x, p.y), 0.0).rg; spec = vec3(p.z) * ab.x + ab.y;");
  char off[16];
  std::snprintf(off, sizeof off, "%.2f", fig.engine);
  table << "| flags `--axes r,mu --flip-y --channels B,A+B` (" << f.tex.width
        << "^2, exr) read as (A, B) along mu, r | " << off << " (caught) | " << sci(fig.generated, 2) << " | "
        << sci(fig.predicted, 2) << " | - |\n";
  std::printf("%s", table.str().c_str());
  expectPagesQuote(table.str());
  EXPECT_LE(fig.generated, fig.predicted);
  EXPECT_GT(fig.engine, 0.1) << "a reader assuming mu,r and (A, B) must not match a transposed, flipped (B, A+B) file";
}

TEST(GlPipeline, UnknownLayoutPresetExits64WritingNothing) {
  const fs::path out = dir() / "unknown";
  EXPECT_EQ(bake("--layout godot-3 -o '" + out.string() + "'"), 64);
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(bake("--channels A+B,C -o '" + out.string() + "'"), 64);
  EXPECT_EQ(bake("--axes x,y -o '" + out.string() + "'"), 64);
  EXPECT_FALSE(fs::exists(out));
  // two channels cannot be a PNG (RGB or RGBA): 64, not an internal error
  EXPECT_EQ(bake("--channels A,B --format png16 -o '" + out.string() + "'"), 64);
  EXPECT_EQ(bake("--layout unreal --format png16 -o '" + out.string() + "'"), 64);
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
