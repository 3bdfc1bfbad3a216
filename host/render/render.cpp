// The white furnace through GL (render/render.h).
#include "render/render.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>


#include "brdfbake/brdfbake.h"
#include "common/errors.h"
#include "common/format.h"
#include "common/models.h"
#include "formats/output_set.h"
#include "formats/exr/table_file.h"
#include "formats/writers.h"
#include "reference/reference.h"
#include "render/gl_context.h"
#include "render/shader_parts.h"
#include "shader/shader_gen.h"

namespace brdfbake {

namespace {

// Gold's reflectance at normal incidence, linear RGB (Hoffman, "Physics and Math of Shading",
// SIGGRAPH 2015 course notes, table of metals: gold 1.00, 0.71, 0.29).
constexpr float kGold[3] = {1.00f, 0.71f, 0.29f};
constexpr float kDielectricF0 = 0.04f;  // a dielectric of IOR 1.5: ((1.5 - 1)/(1.5 + 1))^2

// The row kinds the shader switches on, in furnaceRows() order.
int rowKind(const std::string& name) {
  const auto& rows = furnaceRows();
  for (size_t i = 0; i < rows.size(); ++i)
    if (rows[i].name == name) return static_cast<int>(i);
  return -1;
}

struct Budget {
  double claim = 0, interp = 0;
  double total() const { return claim + interp; }
};
Budget budgetOf(const Table& t) {
  Budget b;
  auto num = [&](const char* k) { return t.metadata.count(k) ? std::stod(t.metadata.at(k)) : 0.0; };
  b.claim = num("brdf.error");
  b.interp = num("brdf.interp-error");
  return b;
}

}  // namespace

const std::vector<FurnaceRow>& furnaceRows() {
  static const std::vector<FurnaceRow> rows = {
      {"single", "F = 1, single scattering: E = A + B from the split sum", false},
      {"kulla-conty", "F = 1, single scattering + the Kulla-Conty lobe (albedo, albedo-avg), integrated over the light", true},
      {"single-table", "F = 1, compensated from the split sum alone (Fdez-Aguera 2019)", true},
      {"dielectric-lambert", "specular F0 = 0.04 (compensated) over Lambert rho = 1 with albedo scaling", true},
      {"gold", "gold, Schlick F0 = (1, 0.71, 0.29), compensated: absorbs, so darker than the background", false},
      {"sheen", "the Charlie sheen's albedo alone (charlie + charlie-smith split sum)", false},
  };
  return rows;
}

int runRender(const RenderOptions& o) {
  // the options first: nothing is opened, baked or written for a bad one
  if (o.cell < 16 || o.cell > 256)
    throw Error(kExitUsage, "--cell: pixels per sphere, 16..256, got " + std::to_string(o.cell));
  if (o.columns < 2 || o.columns > 33)
    throw Error(kExitUsage, "--columns: roughness steps, 2..33, got " + std::to_string(o.columns));
  std::vector<std::string> names;
  for (const auto& r : furnaceRows()) names.push_back(r.name);
  std::vector<int> kinds;
  for (const std::string& r : o.rows.empty() ? names : o.rows) {
    if (rowKind(r) < 0)
      throw Error(kExitUsage, "--rows: unknown row '" + r + "'" + didYouMean(r, names) + "; valid: " + joinNames(names));
    kinds.push_back(rowKind(r));
  }
  const bool sheen = std::find(kinds.begin(), kinds.end(), rowKind("sheen")) != kinds.end();
  checkOutputDir(o.outDir);
  GlContext gl;  // no EGL: exit 69 before anything is baked
  const GlFunctions& g = gl.gl();

  // the tables, baked into DIR/tables as `brdfbake bake` bakes them
  const std::string tableDir = o.outDir + "/tables";
  BakeRequest req = defaultRequest();
  req.tables = {tableKind("splitsum"), tableKind("albedo"), tableKind("albedo-avg")};
  req.outDir = tableDir;
  req.device = o.device;
  req.noWait = o.noWait;
  std::vector<std::string> paths;
  for (const TableReport& r : bakeToDirectory(req)) paths.push_back(r.path);
  std::string sheenPath;
  if (sheen) {
    BakeRequest s = req;
    s.ndfs = {ndfId("charlie")};
    s.gafs = {gafId("charlie-smith")};
    s.tables = {tableKind("splitsum")};
    for (const TableReport& r : bakeToDirectory(s)) sheenPath = r.path;
    paths.push_back(sheenPath);
  }

  // read back as an engine loads them; their lookup code as `brdfbake shader --lang glsl` writes it
  std::map<std::string, Table> tables;
  for (const std::string& p : paths) tables[p] = readTable(p);
  auto pathOf = [&](const std::string& stem) {
    for (const std::string& p : paths)
      if (p.find("/" + stem + "_ggx_smith-correlated") != std::string::npos) return p;
    throw Error(kExitSoftware, "internal: render baked no " + stem + " table");
  };
  const std::string split = pathOf("splitsum"), alb = pathOf("albedo"), avg = pathOf("albedo-avg");
  const Budget bSplit = budgetOf(tables[split]), bAlb = budgetOf(tables[alb]), bAvg = budgetOf(tables[avg]);

  const int cols = o.columns, nrows = static_cast<int>(kinds.size()), W = cols * o.cell, H = nrows * o.cell;
  std::vector<double> x32, w32, x16, w16;
  gaussLegendre(32, &x32, &w32);
  gaussLegendre(16, &x16, &w16);
  std::string rowList;
  for (int k : kinds) rowList += (rowList.empty() ? "" : ", ") + std::to_string(k);
  const std::string head = "#version 310 es\nprecision highp float;\nprecision highp int;\nprecision highp sampler2D;\n"
                           "layout(local_size_x = 8, local_size_y = 8) in;\n";
  const std::string lookups = shaderForFiles(paths, ShaderLang::Glsl) + "\nuniform sampler2D sheen_tex;\n" + multiscatterBody();
  std::string src = head + "layout(std430, binding = 0) buffer Pixels { vec4 px[]; };\n" + lookups;
  src += "const int W = " + std::to_string(W) + ", H = " + std::to_string(H) + ", CELL = " + std::to_string(o.cell) +
         ", COLS = " + std::to_string(cols) + ", NROWS = " + std::to_string(nrows) + ";\n";
  src += "const int ROW[NROWS] = int[NROWS](" + rowList + ");\n";
  src += "const float X32[32] = float[32](" + floats(x32) + ");\nconst float W32[32] = float[32](" + floats(w32) + ");\n";
  src += "const float X16[16] = float[16](" + floats(x16) + ");\nconst float W16[16] = float[16](" + floats(w16) + ");\n";
  src += "const float D_E = " + lit(bAlb.total()) + ", D_AVG = " + lit(bAvg.total()) + ";\n";
  src += "const vec3 GOLD = vec3(" + lit(kGold[0]) + ", " + lit(kGold[1]) + ", " + lit(kGold[2]) + ");\n";
  src += "const float F0_DIELECTRIC = " + lit(kDielectricF0) + ", SPHERE = " + lit(kSphere) + ";\n";
  // test hook: BRDFBAKE_TEST_RENDER_LOBE_SCALE scales the Kulla-Conty lobe, so that a test can see
  // the measurement fail a compensation that does not conserve (tests/render_test.cpp)
  const char* lobeScale = std::getenv("BRDFBAKE_TEST_RENDER_LOBE_SCALE");
  src += "const float LOBE_SCALE = " + lit(lobeScale ? std::atof(lobeScale) : 1.0) + ";\n";
  src += sheen ? "float sheenE(float mu, float r) { return " + shaderPrefix(sheenPath) + "_lookup(sheen_tex, mu, r).r; }\n"
               : "float sheenE(float mu, float r) { return 0.0; }\n";
  src += R"glsl(
// The Kulla-Conty lobe's albedo under a uniform white light: 2 pi int_0^1 f_ms(mu_o, mu_i) mu_i dmu_i
// (the lobe does not depend on phi), by Gauss-Legendre with 32 and 16 nodes (their difference is
// the estimate of the rule's error).
float kcAlbedo32(float muO, float r) {
  float s = 0.0;
  for (int k = 0; k < 32; ++k) s += W32[k] * kullaContyLobe(muO, X32[k], r) * X32[k];
  return 2.0 * MS_PI * s;
}
float kcAlbedo16(float muO, float r) {
  float s = 0.0;
  for (int k = 0; k < 16; ++k) s += W16[k] * kullaContyLobe(muO, X16[k], r) * X16[k];
  return 2.0 * MS_PI * s;
}

// One pixel: its sphere's normal seen along the view axis (orthographic), mu = n.v; the white
// furnace's radiance is 1 in every direction, so the pixel is the material's directional albedo.
// .a: the error the tables and the rule predict for it (-1: background, -2: no prediction).
void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (p.x >= W || p.y >= H) return;
  int idx = p.y * W + p.x;
  vec2 c = (vec2(p % CELL) + 0.5) / float(CELL) * 2.0 - 1.0;
  float d2 = dot(c, c) / (SPHERE * SPHERE);
  if (d2 >= 1.0) { px[idx] = vec4(1.0, 1.0, 1.0, -1.0); return; }
  float mu = sqrt(1.0 - d2);
  float r = float(p.x / CELL) / float(COLS - 1);
  int kind = ROW[p.y / CELL];
  vec3 v = vec3(0.0);
  float bound = -2.0;
  if (kind == 0) {
    vec2 ab = lookupAB(mu, r);
    v = vec3(ab.x + ab.y);
  } else if (kind == 1) {
    float e = lookupE(mu, r);
    float a = LOBE_SCALE * kcAlbedo32(mu, r), a16 = LOBE_SCALE * kcAlbedo16(mu, r);
    v = vec3(e + a);
    // P = E + (1 - E) I/(1 - E_avg), I = 2 int (1 - E) mu dmu: E's error moves I by at most D_E,
    // E_avg's moves the ratio by D_AVG/(1 - E_avg); P's own E cancels to first order
    float lost = max(1.0 - lookupEavg(r), MS_FLOOR);
    float ratio = a / max(1.0 - e, MS_FLOOR);
    bound = max(1.0 - e, 0.0) * (D_E + D_AVG) / lost + abs(a - a16) + D_E * abs(1.0 - ratio) + 1e-5;
  } else if (kind == 2) {
    v = fdezAgueraSingle(mu, r, vec3(1.0)) + fdezAgueraMultiple(mu, r, vec3(1.0));
    bound = 1e-5;
  } else if (kind == 3) {
    vec3 spec = fdezAgueraSingle(mu, r, vec3(F0_DIELECTRIC)) + fdezAgueraMultiple(mu, r, vec3(F0_DIELECTRIC));
    v = spec + (vec3(1.0) - spec) * 1.0;  // Lambert, rho = 1, gets what the specular left
    bound = 1e-5;
  } else if (kind == 4) {
    v = fdezAgueraSingle(mu, r, GOLD) + fdezAgueraMultiple(mu, r, GOLD);
  } else {
    v = vec3(sheenE(mu, r));
  }
  px[idx] = vec4(v, bound);
}
)glsl";
  const GLuint prog = gl.computeProgram(src);
  g.UseProgram(prog);

  // the tables as RGBA32F textures, bilinear, clamped: what the generated code expects
  int unit = 0;
  std::vector<std::pair<std::string, int>> samplers;
  auto bind = [&](const Table& t, const std::string& uniform) {
    std::vector<float> rgba(static_cast<size_t>(t.width) * t.height * 4, 1.0f);
    for (size_t i = 0; i < static_cast<size_t>(t.width) * t.height; ++i)
      for (size_t c = 0; c < t.planes.size() && c < 4; ++c) rgba[i * 4 + c] = t.planes[c][i];
    GLuint tex = 0;
    g.GenTextures(1, &tex);
    g.ActiveTexture(GL_TEXTURE0 + unit);
    g.BindTexture(GL_TEXTURE_2D, tex);
    g.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, t.width, t.height, 0, GL_RGBA, GL_FLOAT, rgba.data());
    g.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    g.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    g.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    g.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    samplers.push_back({uniform, unit});
    ++unit;
  };
  auto setSamplers = [&](GLuint program) {
    g.UseProgram(program);
    for (const auto& [name, u] : samplers) {
      const GLint loc = g.GetUniformLocation(program, name.c_str());
      if (loc >= 0) g.Uniform1i(loc, u);
    }
  };
  for (const std::string& p : {split, alb, avg}) bind(tables[p], shaderPrefix(p) + "_tex");
  if (sheen) bind(tables[sheenPath], "sheen_tex");
  setSamplers(prog);
  GLuint buf = 0;
  const size_t n = static_cast<size_t>(W) * H;
  g.GenBuffers(1, &buf);
  g.BindBuffer(GL_SHADER_STORAGE_BUFFER, buf);
  g.BufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(n * 4 * sizeof(float)), nullptr, GL_DYNAMIC_READ);
  g.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buf);
  g.DispatchCompute(static_cast<GLuint>((W + 7) / 8), static_cast<GLuint>((H + 7) / 8), 1);
  g.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  g.Finish();
  const float* mapped = static_cast<const float*>(
      g.MapBufferRange(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(n * 4 * sizeof(float)), GL_MAP_READ_BIT));
  if (!mapped) throw Error(kExitSoftware, "render: could not read the pixels back (GL error " + std::to_string(g.GetError()) + ")");
  std::vector<float> px(mapped, mapped + n * 4);
  g.UnmapBuffer(GL_SHADER_STORAGE_BUFFER);

  // the lobe picture: single scattering from kernels/brdf on the host, the Kulla-Conty lobe from
  // the generated lookups on GL, added in the bottom row
  const int LW = 3 * o.cell, LH = 2 * o.cell;
  const size_t ln = static_cast<size_t>(LW) * LH;
  const LobeInput lin = lobeInput(o.cell);
  const std::string lobeSrc = head + "layout(std430, binding = 1) buffer Geometry { vec4 geo[]; };\n"
                              "layout(std430, binding = 2) buffer Lobe { float lobe[]; };\n" + lookups +
                              "const int LW = " + std::to_string(LW) + ", LH = " + std::to_string(LH) + ";\n" + R"glsl(
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
  const GLuint lobeProg = gl.computeProgram(lobeSrc);
  setSamplers(lobeProg);
  GLuint lbuf[2] = {0, 0};
  g.GenBuffers(2, lbuf);
  g.BindBuffer(GL_SHADER_STORAGE_BUFFER, lbuf[0]);
  g.BufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(ln * 4 * sizeof(float)), lin.geometry.data(), GL_STATIC_DRAW);
  g.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, lbuf[0]);
  g.BindBuffer(GL_SHADER_STORAGE_BUFFER, lbuf[1]);
  g.BufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(ln * sizeof(float)), nullptr, GL_DYNAMIC_READ);
  g.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, lbuf[1]);
  g.DispatchCompute(static_cast<GLuint>((LW + 7) / 8), static_cast<GLuint>((LH + 7) / 8), 1);
  g.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  g.Finish();
  const float* lm = static_cast<const float*>(
      g.MapBufferRange(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(ln * sizeof(float)), GL_MAP_READ_BIT));
  if (!lm) throw Error(kExitSoftware, "render: could not read the lobe picture back (GL error " + std::to_string(g.GetError()) + ")");
  std::vector<float> lobe(lm, lm + ln);
  g.UnmapBuffer(GL_SHADER_STORAGE_BUFFER);
  TableImage lobeImg;
  lobeImg.width = LW;
  lobeImg.height = LH;
  lobeImg.channels = {"R", "G", "B"};
  lobeImg.planes.assign(3, std::vector<float>(ln, 0.0f));
  double lobeMax[3] = {0, 0, 0}, singleAt[3] = {0, 0, 0};  // per roughness: the largest lobe, single there
  for (int y = 0; y < LH; ++y)
    for (int x = 0; x < LW; ++x) {
      const size_t k = static_cast<size_t>(y) * LW + x, top = static_cast<size_t>(y % o.cell) * LW + x;
      if (!std::isfinite(lobe[k]) || !std::isfinite(lin.single[k]))
        throw Error(kExitSoftware, "render: a pixel of the lobe picture is not finite");
      // top row: single scattering; bottom row: the same sphere's pixel with the lobe added
      const float v = y < o.cell ? lin.single[k] : lin.single[top] + lobe[top];
      for (int c = 0; c < 3; ++c) lobeImg.planes[c][k] = v;
      if (y < o.cell && lobe[k] > lobeMax[x / o.cell]) {
        lobeMax[x / o.cell] = lobe[k];
        singleAt[x / o.cell] = lin.single[k];
      }
    }

  // the measurement: conserving rows against 1 within their predicted error; the single row against
  // the independent reference's E(mu, r) at sampled pixels, within the split sum's claim + interpolation
  struct RowResult {
    double worst = 0, worstBound = 0, maxBound = 0;
    long over = 0, pixels = 0;
  };
  std::vector<RowResult> res(static_cast<size_t>(nrows));
  bool fail = false;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const float* q = &px[(static_cast<size_t>(y) * W + x) * 4];
      for (int c = 0; c < 3; ++c)
        if (!std::isfinite(q[c])) throw Error(kExitSoftware, "render: a pixel is not finite (row " + std::to_string(y / o.cell) + ")");
      if (q[3] == -1.0f) continue;  // background
      const int row = y / o.cell, kind = kinds[static_cast<size_t>(row)];
      RowResult& rr = res[static_cast<size_t>(row)];
      ++rr.pixels;
      if (!furnaceRows()[static_cast<size_t>(kind)].conserves) continue;
      const double dev = std::max({std::fabs(q[0] - 1.0), std::fabs(q[1] - 1.0), std::fabs(q[2] - 1.0)});
      if (dev >= rr.worst) {
        rr.worst = dev;
        rr.worstBound = q[3];
      }
      rr.maxBound = std::max(rr.maxBound, static_cast<double>(q[3]));
      if (dev > q[3]) {
        ++rr.over;
        fail = true;
      }
    }
  // the single row: every 6th pixel of each sphere against reference::albedo in double
  for (int row = 0; row < nrows; ++row) {
    if (kinds[static_cast<size_t>(row)] != rowKind("single")) continue;
    RowResult& rr = res[static_cast<size_t>(row)];
    rr.maxBound = bSplit.total();
    for (int y = row * o.cell; y < (row + 1) * o.cell; y += 6)
      for (int x = 0; x < W; x += 6) {
        const float* q = &px[(static_cast<size_t>(y) * W + x) * 4];
        if (q[3] == -1.0f) continue;
        const double cx = ((x % o.cell) + 0.5) / o.cell * 2 - 1, cy = ((y % o.cell) + 0.5) / o.cell * 2 - 1;
        const double mu = std::sqrt(std::max(0.0, 1 - (cx * cx + cy * cy) / (kSphere * kSphere)));
        const double r = static_cast<double>(x / o.cell) / (cols - 1);
        const double ref = reference::albedo(ndfId("ggx"), gafId("smith-correlated"), r, mu).e();
        const double dev = std::fabs(q[0] - ref) / std::max(1.0, std::fabs(ref));
        if (dev > rr.worst) {
          rr.worst = dev;
          rr.worstBound = bSplit.total();
        }
        if (dev > bSplit.total()) {
          ++rr.over;
          fail = true;
        }
      }
  }

  // the files, as one set: the linear EXR with what made it, the sRGB PNG to look at
  TableImage img;
  img.width = W;
  img.height = H;
  img.channels = {"R", "G", "B"};
  img.planes.assign(3, std::vector<float>(n));
  for (size_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) img.planes[c][i] = px[i * 4 + c];
  std::string rowNames;
  for (int k : kinds) rowNames += (rowNames.empty() ? "" : ",") + furnaceRows()[static_cast<size_t>(k)].name;
  std::string tableNames;
  for (const std::string& p : paths) tableNames += (tableNames.empty() ? "" : ",") + p;
  img.strings["render.kind"] = "white furnace: uniform environment of radiance 1, background 1";
  img.strings["render.model"] = "ggx + smith-correlated (sheen: charlie + charlie-smith)";
  img.strings["render.rows"] = rowNames;
  img.strings["render.columns"] = "perceptual roughness r = column/" + std::to_string(cols - 1);
  img.strings["render.tables"] = tableNames;
  img.strings["render.settings"] = std::to_string(o.cell) + " px per sphere, radius " + fmtG(kSphere) +
                                   " of half a cell, orthographic view: mu = n.v = sqrt(1 - d^2)";
  img.strings["render.renderer"] = gl.renderer();
  img.strings["render.generator"] = "brdfbake render";
  std::vector<std::pair<std::string, std::string>> text;
  for (const auto& [k, v] : img.strings) text.push_back({k, v});
  lobeImg.strings = img.strings;
  lobeImg.strings["render.kind"] = "one sphere per roughness (columns: r = 0.4, 0.7, 1) under a directional light of "
                                   "irradiance 1 from (-0.5, 0.5, 0.7), black background";
  lobeImg.strings["render.rows"] = "single scattering (kernels/brdf on the host), + the Kulla-Conty lobe (GL)";
  lobeImg.strings["render.columns"] = "perceptual roughness 0.4, 0.7, 1";
  std::vector<std::pair<std::string, std::string>> lobeText;
  for (const auto& [k, v] : lobeImg.strings) lobeText.push_back({k, v});
  const std::string exr = o.outDir + "/furnace.exr", png = o.outDir + "/furnace.png";
  const std::string lobeExr = o.outDir + "/lobe.exr", lobePng = o.outDir + "/lobe.png";
  std::vector<OutputFile> files(4);
  files[0].path = exr;
  files[0].write = [&img, exr](const std::string& tmp) { writeTableExrTemporary(tmp, exr, img, false); };
  files[0].bytesBound = n * 12 + (1 << 16);
  files[1].path = png;
  files[1].write = [&img, &text, png, W, H](const std::string& tmp) { writePng8SrgbTemporary(tmp, png, W, H, img.planes, text); };
  files[1].bytesBound = n * 3 + (1 << 16);
  files[2].path = lobeExr;
  files[2].write = [&lobeImg, lobeExr](const std::string& tmp) { writeTableExrTemporary(tmp, lobeExr, lobeImg, false); };
  files[2].bytesBound = ln * 12 + (1 << 16);
  files[3].path = lobePng;
  files[3].write = [&lobeImg, &lobeText, lobePng, LW, LH](const std::string& tmp) {
    writePng8SrgbTemporary(tmp, lobePng, LW, LH, lobeImg.planes, lobeText);
  };
  files[3].bytesBound = ln * 3 + (1 << 16);
  commitOutputs(o.outDir, files, !o.noWait);

  std::printf("render: white furnace, %d x %d spheres (%d px each) on %s; tables in %s/\n", cols, nrows, o.cell,
              gl.renderer().c_str(), tableDir.c_str());
  std::printf("%-19s %-9s %-34s %-12s %s\n", "row", "conserves", "largest deviation", "its bound", "pixels over");
  for (int row = 0; row < nrows; ++row) {
    const FurnaceRow& fr = furnaceRows()[static_cast<size_t>(kinds[static_cast<size_t>(row)])];
    const RowResult& rr = res[static_cast<size_t>(row)];
    char dev[64] = "-", bnd[32] = "-", over[32] = "-";
    if (fr.conserves || fr.name == "single") {
      std::snprintf(dev, sizeof dev, "%.3g %s", rr.worst, fr.conserves ? "(|pixel - 1|)" : "(|pixel - E_ref|)");
      std::snprintf(bnd, sizeof bnd, "%.3g", rr.worstBound);
      std::snprintf(over, sizeof over, "%ld", rr.over);
    }
    std::printf("%-19s %-9s %-34s %-12s %s\n", fr.name.c_str(), fr.conserves ? "yes" : "no", dev, bnd, over);
  }
  std::printf("lobe picture (directional light): the Kulla-Conty lobe adds at most");
  for (int i = 0; i < 3; ++i)
    std::printf("%s %.3g at r = %g (single scattering %.3g there)", i ? "," : "", lobeMax[i], kLobeRoughness[i], singleAt[i]);
  std::printf("\nwrote %s, %s (linear) and %s, %s (sRGB)\n", exr.c_str(), lobeExr.c_str(), png.c_str(), lobePng.c_str());
  if (fail) std::printf("FAIL: a row's pixels are off by more than the tables predict\n");
  return fail ? 1 : 0;
}

}  // namespace brdfbake
