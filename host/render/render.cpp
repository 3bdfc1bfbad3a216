// `brdfbake render` (render/render.h): the furnace grid, the lobe picture, the files.
#include "render/render.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "brdfbake/brdfbake.h"
#include "common/errors.h"
#include "common/format.h"
#include "brdfbake/table_kind.h"
#include "common/models.h"
#include "formats/exr/table_file.h"
#include "formats/output_set.h"
#include "formats/writers.h"
#include "render/furnace.h"
#include "render/labels.h"
#include "render/ltc_render.h"
#include "render/gl_context.h"
#include "render/shader_parts.h"
#include "shader/shader_gen.h"

namespace brdfbake {

namespace {

struct LobePicture {
  TableImage img;
  double lobeMax[3] = {0, 0, 0}, singleAt[3] = {0, 0, 0};  // per roughness: the largest lobe, single there
};

// Single scattering from kernels/brdf on the host (render/shader_parts.h lobeInput), the Kulla-Conty
// lobe from the generated lookups on GL, added in the bottom row.
LobePicture renderLobe(const GlContext& gl, const FurnaceSpec& s, const FurnaceTables& t) {
  const GlFunctions& g = gl.gl();
  const int cell = s.cell, LW = 3 * cell, LH = 2 * cell;
  const size_t ln = static_cast<size_t>(LW) * LH;
  const LobeInput lin = lobeInput(cell, s.ndf, s.gaf);
  const std::vector<std::string> paths = {t.splitsum, t.albedo, t.albedoAvg};
  const std::string src =
      "#version 310 es\nprecision highp float;\nprecision highp int;\nprecision highp sampler2D;\n"
      "layout(local_size_x = 8, local_size_y = 8) in;\n"
      "layout(std430, binding = 1) buffer Geometry { vec4 geo[]; };\n"
      "layout(std430, binding = 2) buffer Lobe { float lobe[]; };\n" +
      shaderForFiles(paths, ShaderLang::Glsl) + multiscatterBody() + "const int LW = " + std::to_string(LW) +
      ", LH = " + std::to_string(LH) + ";\n" + R"glsl(
// The Kulla-Conty lobe times n.l at each pixel (mu_o, mu_i, r from the host): f_ms(o, l) (n.l) under
// a directional light of irradiance 1.
void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (p.x >= LW || p.y >= LH) return;
  int k = p.y * LW + p.x;
  vec4 g = geo[k];
  lobe[k] = (g.w == 0.0 || g.y <= 0.0) ? 0.0 : kullaContyLobe(g.x, g.y, g.z) * g.y;
}
)glsl";
  const GLuint prog = gl.computeProgram(src);
  g.UseProgram(prog);
  std::vector<GLuint> textures;
  int unit = 0;
  for (const std::string& p : paths) {
    textures.push_back(bindTableTexture(gl, t.read.at(p), unit));
    const GLint loc = g.GetUniformLocation(prog, (shaderPrefix(p) + "_tex").c_str());
    if (loc >= 0) g.Uniform1i(loc, unit);
    ++unit;
  }
  GLuint buf[2] = {0, 0};
  g.GenBuffers(2, buf);
  g.BindBuffer(GL_SHADER_STORAGE_BUFFER, buf[0]);
  g.BufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(ln * 4 * sizeof(float)), lin.geometry.data(),
               GL_STATIC_DRAW);
  g.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, buf[0]);
  g.BindBuffer(GL_SHADER_STORAGE_BUFFER, buf[1]);
  g.BufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(ln * sizeof(float)), nullptr, GL_DYNAMIC_READ);
  g.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, buf[1]);
  g.DispatchCompute(static_cast<GLuint>((LW + 7) / 8), static_cast<GLuint>((LH + 7) / 8), 1);
  g.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  g.Finish();
  const float* lm = static_cast<const float*>(
      g.MapBufferRange(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(ln * sizeof(float)), GL_MAP_READ_BIT));
  if (!lm)
    throw Error(kExitSoftware,
                "render: could not read the lobe picture back (GL error " + std::to_string(g.GetError()) + ")");
  std::vector<float> lobe(lm, lm + ln);
  g.UnmapBuffer(GL_SHADER_STORAGE_BUFFER);
  g.DeleteBuffers(2, buf);
  g.DeleteTextures(static_cast<GLsizei>(textures.size()), textures.data());
  g.DeleteProgram(prog);
  LobePicture out;
  out.img.width = LW;
  out.img.height = LH;
  out.img.channels = {"R", "G", "B"};
  out.img.planes.assign(3, std::vector<float>(ln, 0.0f));
  for (int y = 0; y < LH; ++y)
    for (int x = 0; x < LW; ++x) {
      const size_t k = static_cast<size_t>(y) * LW + x, top = static_cast<size_t>(y % cell) * LW + x;
      if (!std::isfinite(lobe[k]) || !std::isfinite(lin.single[k]))
        throw Error(kExitSoftware, "render: a pixel of the lobe picture is not finite");
      // top row: single scattering; bottom row: the same sphere's pixel with the lobe added
      const float v = y < cell ? lin.single[k] : lin.single[top] + lobe[top];
      for (int c = 0; c < 3; ++c) out.img.planes[c][k] = v;
      if (y < cell && lobe[k] > out.lobeMax[x / cell]) {
        out.lobeMax[x / cell] = lobe[k];
        out.singleAt[x / cell] = lin.single[k];
      }
    }
  return out;
}

std::vector<std::pair<std::string, std::string>> textOf(const TableImage& img) {
  std::vector<std::pair<std::string, std::string>> text;
  for (const auto& [k, v] : img.strings) text.push_back({k, v});
  return text;
}

}  // namespace

int runRender(const RenderOptions& o) {
  if (o.light == "quad") return runLtcRender(o);
  // the options first: nothing is opened, baked or written for a bad one
  if (o.cell < 16 || o.cell > 256)
    throw Error(kExitUsage, "--cell: pixels per sphere, 16..256, got " + std::to_string(o.cell));
  if (o.columns < 2 || o.columns > 33)
    throw Error(kExitUsage, "--columns: roughness steps, 2..33, got " + std::to_string(o.columns));
  FurnaceSpec spec;
  spec.ndf = ndfId(o.ndf);
  spec.gaf = gafId(o.gaf);
  if (isSheenNdf(spec.ndf))
    throw Error(kExitUsage,
                "--ndf: render shades ggx, beckmann, blinn-phong or gaussian (the sheen row is charlie's), got '" +
                    o.ndf + "'");
  checkPair(spec.ndf, spec.gaf);
  spec.cell = o.cell;
  spec.columns = o.columns;
  std::vector<std::string> names;
  for (const auto& r : furnaceRows()) names.push_back(r.name);
  if (o.rows.empty()) {
    for (size_t k = 0; k < names.size(); ++k)
      if (furnaceRowFits(static_cast<int>(k), spec.ndf, spec.gaf)) spec.rows.push_back(static_cast<int>(k));
  }
  for (const std::string& r : o.rows) {
    const int k = furnaceRowIndex(r);
    if (k < 0)
      throw Error(kExitUsage,
                  "--rows: unknown row '" + r + "'" + didYouMean(r, names) + "; valid: " + joinNames(names));
    if (!furnaceRowFits(k, spec.ndf, spec.gaf))
      throw Error(kExitUsage,
                  "--rows: the glass row takes --ndf ggx or beckmann with --gaf smith or smith-correlated "
                  "(the rough dielectric's models), not " +
                      o.ndf + " + " + o.gaf);
    spec.rows.push_back(k);
  }
  checkOutputDir(o.outDir);
  GlContext gl;  // no EGL: exit 69 before anything is baked

  // the tables, baked into DIR/tables as `brdfbake bake` bakes them; the lobe picture needs the pair's
  const std::string tableDir = o.outDir + "/tables";
  FurnaceSpec withLobe = spec;
  if (std::find(spec.rows.begin(), spec.rows.end(), furnaceRowIndex("kulla-conty")) == spec.rows.end())
    withLobe.rows.push_back(furnaceRowIndex("kulla-conty"));
  const FurnaceTables tables = bakeFurnaceTables(withLobe, tableDir, o.device, o.noWait);
  const FurnacePicture pic = renderFurnace(gl, spec, tables);
  const LobePicture lobe = renderLobe(gl, spec, tables);

  // the files, as one set: the linear EXRs with what made them, the sRGB PNGs to look at
  const int W = pic.width, H = pic.height;
  TableImage img;
  img.width = W;
  img.height = H;
  img.channels = {"R", "G", "B"};
  img.planes = pic.rgb;
  std::string rowNames;
  for (int k : spec.rows) rowNames += (rowNames.empty() ? "" : ",") + furnaceRows()[static_cast<size_t>(k)].name;
  std::string tableNames;
  for (const std::string& p : tables.all()) tableNames += (tableNames.empty() ? "" : ",") + p;
  img.strings["render.kind"] = "white furnace: uniform environment of radiance 1, background 1";
  img.strings["render.model"] =
      o.ndf + " + " + o.gaf + " (sheen: charlie + charlie-smith; glass: eta " + fmtG(kGlassEta) + ")";
  img.strings["render.rows"] = rowNames;
  img.strings["render.columns"] = "perceptual roughness r = column/" + std::to_string(spec.columns - 1);
  img.strings["render.tables"] = tableNames;
  img.strings["render.settings"] = std::to_string(spec.cell) + " px per sphere, radius " + fmtG(kSphere) +
                                   " of half a cell, orthographic view: mu = n.v = sqrt(1 - d^2)";
  img.strings["render.renderer"] = pic.renderer;
  img.strings["render.generator"] = "brdfbake render";
  TableImage lobeImg = lobe.img;
  lobeImg.strings = img.strings;
  lobeImg.strings["render.kind"] =
      "one sphere per roughness (columns: r = 0.4, 0.7, 1) under a directional light of "
      "irradiance 1 from (-0.5, 0.5, 0.7), black background";
  lobeImg.strings["render.rows"] = "single scattering (kernels/brdf on the host), + the Kulla-Conty lobe (GL)";
  lobeImg.strings["render.columns"] = "perceptual roughness 0.4, 0.7, 1";
  const std::vector<std::pair<std::string, std::string>> text = textOf(img), lobeText = textOf(lobeImg);
  // the PNG to look at: the grid with its rows named and its columns' roughness on top
  std::vector<std::pair<std::string, std::string>> rowLabels;
  for (int k : spec.rows)
    rowLabels.push_back({furnaceRows()[static_cast<size_t>(k)].name, furnaceRows()[static_cast<size_t>(k)].expect});
  const LabelledPicture shown = labelFurnace(img.planes, W, H, spec.cell, spec.columns, rowLabels);
  const std::string exr = o.outDir + "/furnace.exr", png = o.outDir + "/furnace.png";
  const std::string lobeExr = o.outDir + "/lobe.exr", lobePng = o.outDir + "/lobe.png";
  const size_t n = static_cast<size_t>(W) * H, ln = static_cast<size_t>(lobeImg.width) * lobeImg.height;
  const int LW = lobeImg.width, LH = lobeImg.height;
  std::vector<OutputFile> files(4);
  files[0].path = exr;
  files[0].write = [&img, exr](const std::string& tmp) { writeTableExrTemporary(tmp, exr, img, false); };
  files[0].bytesBound = n * 12 + (1 << 16);
  files[1].path = png;
  files[1].write = [&shown, &text, png](const std::string& tmp) {
    writePng8SrgbTemporary(tmp, png, shown.width, shown.height, shown.planes, text);
  };
  files[1].bytesBound = static_cast<size_t>(shown.width) * shown.height * 3 + (1 << 16);
  files[2].path = lobeExr;
  files[2].write = [&lobeImg, lobeExr](const std::string& tmp) {
    writeTableExrTemporary(tmp, lobeExr, lobeImg, false);
  };
  files[2].bytesBound = ln * 12 + (1 << 16);
  files[3].path = lobePng;
  files[3].write = [&lobeImg, &lobeText, lobePng, LW, LH](const std::string& tmp) {
    writePng8SrgbTemporary(tmp, lobePng, LW, LH, lobeImg.planes, lobeText);
  };
  files[3].bytesBound = ln * 3 + (1 << 16);
  commitOutputs(o.outDir, files, !o.noWait);

  std::printf("render: white furnace, %d x %zu spheres (%d px each), %s + %s, on %s; tables in %s/\n", spec.columns,
              spec.rows.size(), spec.cell, o.ndf.c_str(), o.gaf.c_str(), pic.renderer.c_str(), tableDir.c_str());
  std::fputs(furnaceTable(spec, pic).c_str(), stdout);
  std::printf("lobe picture (directional light): the Kulla-Conty lobe adds at most");
  for (int i = 0; i < 3; ++i)
    std::printf("%s %.3g at r = %g (single scattering %.3g there)", i ? "," : "", lobe.lobeMax[i], kLobeRoughness[i],
                lobe.singleAt[i]);
  std::printf("\nwrote %s, %s (linear) and %s, %s (sRGB)\n", exr.c_str(), lobeExr.c_str(), png.c_str(),
              lobePng.c_str());
  if (pic.fail) std::printf("FAIL: a row's pixels are off by more than the tables predict\n");
  return pic.fail ? 1 : 0;
}

}  // namespace brdfbake
