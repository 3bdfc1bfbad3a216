// The white furnace grid on GL and its measurement (render/furnace.h).
#include "render/furnace.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>

#include "brdfbake/brdfbake.h"
#include "common/errors.h"
#include "common/format.h"
#include "brdfbake/table_kind.h"
#include "common/models.h"
#include "reference/dielectric_reference.h"
#include "reference/reference.h"
#include "render/furnace_bounds.h"
#include "render/shader_parts.h"
#include "shader/shader_gen.h"

namespace brdfbake {

namespace {

// Gold's reflectance at normal incidence, linear RGB (Hoffman, "Physics and Math of Shading",
// SIGGRAPH 2015 course notes, table of metals: gold 1.00, 0.71, 0.29).
constexpr float kGold[3] = {1.00f, 0.71f, 0.29f};
constexpr float kDielectricF0 = 0.04f;  // a dielectric of IOR 1.5: ((1.5 - 1)/(1.5 + 1))^2
// The glass table's one slice: texel centres put it at the middle of the s range, s(1.5) = 0.2
// (s = (eta - 1)/(eta + 1), docs/rough-glass.md), the range's ends 0.01 either side of it.
constexpr double kGlassS = 0.2, kGlassHalfWidth = 0.01;

// What a float texture lookup and the float arithmetic after it add: the lerp's rounding of values
// up to 1 (a few ulps, 6e-8 each) with a wide margin.
constexpr double kFloatLookup = 1e-5;

// The shader: one invocation per pixel; .a is -1 on the background, the Kulla-Conty row's rule error
// estimate, 1e-5 (float rounding) on the rows that conserve by algebra, -2 elsewhere.
std::string furnaceSource(const FurnaceSpec& s, const FurnaceTables& t) {
  const int W = s.columns * s.cell, H = static_cast<int>(s.rows.size()) * s.cell;
  std::vector<double> x32, w32, x16, w16;
  gaussLegendre(32, &x32, &w32);
  gaussLegendre(16, &x16, &w16);
  std::string rowList;
  for (int k : s.rows) rowList += (rowList.empty() ? "" : ", ") + std::to_string(k);
  std::string src =
      "#version 310 es\nprecision highp float;\nprecision highp int;\nprecision highp sampler2D;\n"
      "layout(local_size_x = 8, local_size_y = 8) in;\n"
      "layout(std430, binding = 0) buffer Pixels { vec4 px[]; };\n";
  src += shaderForFiles(t.all(), ShaderLang::Glsl) + "\nuniform sampler2D sheen_tex;\nuniform sampler2D glass_tex;\n";
  src += t.albedo.empty() ? "" : multiscatterBody();
  src += "const int W = " + std::to_string(W) + ", H = " + std::to_string(H) + ", CELL = " + std::to_string(s.cell) +
         ", COLS = " + std::to_string(s.columns) + ", NROWS = " + std::to_string(s.rows.size()) + ";\n";
  src += "const int ROW[NROWS] = int[NROWS](" + rowList + ");\n";
  src +=
      "const float X32[32] = float[32](" + floats(x32) + ");\nconst float W32[32] = float[32](" + floats(w32) + ");\n";
  src +=
      "const float X16[16] = float[16](" + floats(x16) + ");\nconst float W16[16] = float[16](" + floats(w16) + ");\n";
  src += "const vec3 GOLD = vec3(" + lit(kGold[0]) + ", " + lit(kGold[1]) + ", " + lit(kGold[2]) + ");\n";
  src += "const float F0_DIELECTRIC = " + lit(kDielectricF0) + ", SPHERE = " + lit(kSphere) + ";\n";
  // test hook: BRDFBAKE_TEST_RENDER_LOBE_SCALE scales the Kulla-Conty lobe, so that a test can see
  // the measurement fail a compensation that does not conserve (tests/render_test.cpp)
  const char* lobeScale = std::getenv("BRDFBAKE_TEST_RENDER_LOBE_SCALE");
  src += "const float LOBE_SCALE = " + lit(lobeScale ? std::atof(lobeScale) : 1.0) + ";\n";
  src += t.sheen.empty()
             ? "float sheenE(float mu, float r) { return 0.0; }\n"
             : "float sheenE(float mu, float r) { return " + shaderPrefix(t.sheen) + "_lookup(sheen_tex, mu, r).r; }\n";
  src += t.glass.empty() ? "float glassE(float mu, float r) { return 0.0; }\n"
                         : "float glassE(float mu, float r) { return " + shaderPrefix(t.glass) +
                               "_albedos(glass_tex, mu, r, " + lit(kGlassEta) + ").b; }\n";
  if (t.albedo.empty()) {
    // no microfacet rows: the functions they call are never reached
    src +=
        "vec2 lookupAB(float mu, float r) { return vec2(0.0); }\nfloat lookupE(float mu, float r) { return 0.0; }\n"
        "float lookupEavg(float r) { return 0.0; }\nfloat kullaContyLobe(float a, float b, float r) { return 0.0; }\n"
        "vec3 fdezAgueraSingle(float mu, float r, vec3 f0) { return vec3(0.0); }\n"
        "vec3 fdezAgueraMultiple(float mu, float r, vec3 f0) { return vec3(0.0); }\nconst float MS_FLOOR = 1e-6;\n"
        "const float MS_PI = 3.14159265;\n";
  }
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
    bound = abs(a - a16);  // the light integral's rule error; the host adds the tables' (furnace_bounds.h)
  } else if (kind == 2) {
    v = fdezAgueraSingle(mu, r, vec3(1.0)) + fdezAgueraMultiple(mu, r, vec3(1.0));
    bound = 1e-5;
  } else if (kind == 3) {
    vec3 spec = fdezAgueraSingle(mu, r, vec3(F0_DIELECTRIC)) + fdezAgueraMultiple(mu, r, vec3(F0_DIELECTRIC));
    v = spec + (vec3(1.0) - spec) * 1.0;  // Lambert, rho = 1, gets what the specular left
    bound = 1e-5;
  } else if (kind == 4) {
    v = fdezAgueraSingle(mu, r, GOLD) + fdezAgueraMultiple(mu, r, GOLD);
  } else if (kind == 5) {
    v = vec3(sheenE(mu, r));
  } else {
    v = vec3(glassE(mu, r));  // E_R + E_T: what the interface reflects and transmits, once
  }
  px[idx] = vec4(v, bound);
}
)glsl";
  return src;
}

// Runs `prog` over W x H pixels with the tables bound, returns RGBA per pixel.
std::vector<float> dispatch(const GlContext& gl, GLuint prog, int W, int H,
                            const std::vector<std::pair<const Table*, std::string>>& tex) {
  const GlFunctions& g = gl.gl();
  g.UseProgram(prog);
  int unit = 0;
  std::vector<GLuint> ids;  // deleted after the read-back: one context serves every page's pairs
  for (const auto& [t, uniform] : tex) {
    ids.push_back(bindTableTexture(gl, *t, unit));
    const GLint loc = g.GetUniformLocation(prog, uniform.c_str());
    if (loc >= 0) g.Uniform1i(loc, unit);
    ++unit;
  }
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
  if (!mapped)
    throw Error(kExitSoftware,
                "render: could not read the pixels back (GL error " + std::to_string(g.GetError()) + ")");
  std::vector<float> px(mapped, mapped + n * 4);
  g.UnmapBuffer(GL_SHADER_STORAGE_BUFFER);
  g.DeleteBuffers(1, &buf);
  g.DeleteTextures(static_cast<GLsizei>(ids.size()), ids.data());
  g.DeleteProgram(prog);
  return px;
}

}  // namespace

GLuint bindTableTexture(const GlContext& gl, const Table& t, int unit) {
  return bindPlanesTexture(gl, t.width, t.height, t.planes, unit);
}

GLuint bindPlanesTexture(const GlContext& gl, int width, int height, const std::vector<std::vector<float>>& planes,
                         int unit) {
  const GlFunctions& g = gl.gl();
  std::vector<float> rgba(static_cast<size_t>(width) * height * 4, 1.0f);
  for (size_t i = 0; i < static_cast<size_t>(width) * height; ++i)
    for (size_t c = 0; c < planes.size() && c < 4; ++c) rgba[i * 4 + c] = planes[c][i];
  GLuint id = 0;
  g.GenTextures(1, &id);
  g.ActiveTexture(GL_TEXTURE0 + unit);
  g.BindTexture(GL_TEXTURE_2D, id);
  g.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, rgba.data());
  g.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  g.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  g.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  g.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return id;
}

const std::vector<FurnaceRow>& furnaceRows() {
  using C = FurnaceRow::Checks;
  static const std::vector<FurnaceRow> rows = {
      {"single", "F = 1, single scattering: E = A + B from the split sum", false, C::Tables, "(|pixel - E_ref|)",
       "below 1 as r grows: single scattering loses energy"},
      {"kulla-conty", "F = 1, single scattering + the Kulla-Conty lobe (albedo, albedo-avg), integrated over the light",
       true, C::Tables, "(|pixel - 1|)", "vanishes: tests the albedo tables"},
      {"single-table", "F = 1, compensated from the split sum alone (Fdez-Aguera 2019)", true, C::Algebra,
       "(|pixel - 1|)", "vanishes: 1 by algebra"},
      {"dielectric-lambert", "specular F0 = 0.04 (compensated) over Lambert rho = 1 with albedo scaling", true,
       C::Algebra, "(|pixel - 1|)", "vanishes: 1 by algebra"},
      {"gold", "gold, Schlick F0 = (1, 0.71, 0.29), compensated: absorbs, so darker than the background", false,
       C::None, "", "darker: gold absorbs blue most"},
      {"sheen", "the Charlie sheen's albedo alone (charlie + charlie-smith split sum): dark, a sheen reflects little",
       false, C::None, "", "black at r = 0 is expected: a sheen reflects little"},
      {"glass", "rough glass, eta 1.5: E_R + E_T from the dielectric table, single scattering (never above 1)", false,
       C::Tables, "(|pixel - E_ref|)", "below 1 as r grows: single scattering"},
  };
  return rows;
}

int furnaceRowIndex(const std::string& name) {
  const auto& rows = furnaceRows();
  for (size_t i = 0; i < rows.size(); ++i)
    if (rows[i].name == name) return static_cast<int>(i);
  return -1;
}

bool furnaceRowFits(int row, int ndf, int gaf) {
  const std::string& name = furnaceRows()[static_cast<size_t>(row)].name;
  if (name == "sheen") return true;
  if (name == "glass")
    return (ndf == ndfId("ggx") || ndf == ndfId("beckmann")) &&
           (gaf == gafId("smith") || gaf == gafId("smith-correlated"));
  return !isSheenNdf(ndf);
}

std::vector<std::string> FurnaceTables::all() const {
  std::vector<std::string> v;
  for (const std::string* p : {&splitsum, &albedo, &albedoAvg, &sheen, &glass})
    if (!p->empty()) v.push_back(*p);
  return v;
}

FurnaceTables bakeFurnaceTables(const FurnaceSpec& s, const std::string& dir, const std::string& device, bool noWait) {
  bool microfacet = false, sheen = false, glass = false;
  for (int k : s.rows) {
    const std::string& name = furnaceRows()[static_cast<size_t>(k)].name;
    if (name == "sheen")
      sheen = true;
    else if (name == "glass")
      glass = true;
    else
      microfacet = true;
  }
  FurnaceTables t;
  BakeRequest base = defaultRequest();
  base.outDir = dir;
  base.device = device;
  base.noWait = noWait;
  auto bakeOne = [&](BakeRequest r, const char* kind) {
    std::string path;
    for (const TableReport& rep : bakeToDirectory(r))
      if (rep.path.find("/" + std::string(kind) + "_") != std::string::npos) path = rep.path;
    if (path.empty()) throw Error(kExitSoftware, std::string("internal: render baked no ") + kind + " table");
    return path;
  };
  if (microfacet) {
    BakeRequest r = base;
    r.ndfs = {s.ndf};
    r.gafs = {s.gaf};
    r.tables = {tableKind("splitsum"), tableKind("albedo"), tableKind("albedo-avg")};
    std::vector<TableReport> reps = bakeToDirectory(r);
    for (const TableReport& rep : reps) {
      if (rep.table == "splitsum")
        t.splitsum = rep.path;
      else if (rep.table == "albedo")
        t.albedo = rep.path;
      else if (rep.table == "albedo-avg")
        t.albedoAvg = rep.path;
    }
    if (t.splitsum.empty() || t.albedo.empty() || t.albedoAvg.empty())
      throw Error(kExitSoftware, "internal: render baked no split sum, albedo or albedo-avg table");
  }
  if (sheen) {
    BakeRequest r = base;
    r.ndfs = {ndfId("charlie")};
    r.gafs = {gafId("charlie-smith")};
    r.tables = {tableKind("splitsum")};
    t.sheen = bakeOne(r, "splitsum");
  }
  if (glass) {
    BakeRequest r = base;
    r.ndfs = {s.ndf};
    r.gafs = {s.gaf};
    r.tables = {tableKind("dielectric")};
    r.volume.size = std::array<int, 3>{s.glassMu, s.glassR, 1};
    const double lo = kGlassS - kGlassHalfWidth, hi = kGlassS + kGlassHalfWidth;
    r.etaRange = std::make_pair((1 + lo) / (1 - lo), (1 + hi) / (1 - hi));
    t.glass = bakeOne(r, "dielectric");
  }
  for (const std::string& p : t.all()) t.read[p] = readTable(p);
  return t;
}

FurnacePicture renderFurnace(const GlContext& gl, const FurnaceSpec& s, const FurnaceTables& t) {
  const std::map<std::string, Table>& tables = t.read;
  const GLuint prog = gl.computeProgram(furnaceSource(s, t));
  std::vector<std::pair<const Table*, std::string>> bind;
  for (const std::string* p : {&t.splitsum, &t.albedo, &t.albedoAvg})
    if (!p->empty()) bind.push_back({&tables.at(*p), shaderPrefix(*p) + "_tex"});
  if (!t.sheen.empty()) bind.push_back({&tables.at(t.sheen), "sheen_tex"});
  if (!t.glass.empty()) bind.push_back({&tables.at(t.glass), "glass_tex"});
  const int nrows = static_cast<int>(s.rows.size()), W = s.columns * s.cell, H = nrows * s.cell;
  const std::vector<float> px = dispatch(gl, prog, W, H, bind);

  FurnacePicture pic;
  pic.width = W;
  pic.height = H;
  pic.renderer = gl.renderer();
  pic.rows.resize(static_cast<size_t>(nrows));
  pic.rgb.assign(3, std::vector<float>(static_cast<size_t>(W) * H));
  for (size_t i = 0; i < px.size() / 4; ++i)
    for (int c = 0; c < 3; ++c) {
      if (!std::isfinite(px[i * 4 + c]))
        throw Error(kExitSoftware, "render: a pixel is not finite (row " + std::to_string(i / W / s.cell) + ")");
      pic.rgb[c][i] = px[i * 4 + c];
    }
  // The tables as the lookups read them, with their local errors (render/furnace_bounds.h).
  std::unique_ptr<LocalTable> split, albedo, avg, glass;
  if (!t.splitsum.empty()) split = std::make_unique<LocalTable>(tables.at(t.splitsum), std::vector<int>{0, 1});
  if (!t.albedo.empty()) albedo = std::make_unique<LocalTable>(tables.at(t.albedo), std::vector<int>{0});
  if (!t.albedoAvg.empty()) avg = std::make_unique<LocalTable>(tables.at(t.albedoAvg), std::vector<int>{0});
  if (!t.glass.empty()) glass = std::make_unique<LocalTable>(tables.at(t.glass), std::vector<int>{2});
  std::vector<double> x32, w32;
  gaussLegendre(32, &x32, &w32);
  // The rows compared with the reference (one integral a pixel, up to 0.1 s for glass) take the
  // pixels on each sphere's radius to the right along its middle pixel row, every 3rd: a pixel's
  // value depends on mu = n.v and the column's r only, and that radius runs from the centre (mu ~ 1)
  // to the rim (mu ~ 0.07 at 48 pixels).
  constexpr int kRefStride = 3;
  const int singleRow = furnaceRowIndex("single"), kcRow = furnaceRowIndex("kulla-conty"),
            glassRow = furnaceRowIndex("glass");
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const size_t i = static_cast<size_t>(y) * W + x;
      const float* q = &px[i * 4];
      if (q[3] == -1.0f) continue;  // background
      const int row = y / s.cell, kind = s.rows[static_cast<size_t>(row)];
      const FurnaceRow& fr = furnaceRows()[static_cast<size_t>(kind)];
      RowMeasure& rm = pic.rows[static_cast<size_t>(row)];
      ++rm.pixels;
      if (fr.checks == FurnaceRow::Checks::None) continue;
      const bool sampled =
          y % s.cell == s.cell / 2 && x % s.cell >= s.cell / 2 && (x % s.cell - s.cell / 2) % kRefStride == 0;
      if ((kind == singleRow || kind == glassRow) && !sampled) continue;
      const double cx = ((x % s.cell) + 0.5) / s.cell * 2 - 1, cy = ((y % s.cell) + 0.5) / s.cell * 2 - 1;
      const double mu = std::sqrt(std::max(0.0, 1 - (cx * cx + cy * cy) / (static_cast<double>(kSphere) * kSphere)));
      const double r = static_cast<double>(x / s.cell) / (s.columns - 1);
      double dev = 0, bound = 0;
      if (kind == singleRow) {
        // E = A + B against the reference's E(mu, r) in double
        dev = std::fabs(q[0] - reference::albedo(s.ndf, s.gaf, r, mu).e());
        bound = split->error(mu, r) + kFloatLookup;
      } else if (kind == kcRow) {
        // P = E + (1 - E) I/(1 - E_avg) with I = 2 sum_k w_k (1 - E(x_k)) x_k, the lobe's light
        // integral, and E_avg = 1 - I in exact arithmetic: P = 1 whatever E(mu) is. The tables' errors
        // move I by at most 2 sum_k w_k x_k e_E(x_k) and E_avg by e_avg, so P by (1 - E)(that)/(1 - E_avg);
        // the pixel's own E enters through (1 - I/(1 - E_avg)) only (first order). Where albedo-avg's
        // texels sit on albedo's r rows, both lookups blend the same two rows with the same weights and
        // I - (1 - E_avg) is that blend of each row's: the r interpolation cancels, and e_E is the mu
        // axis' term and the claims (e_avg the claim). Plus the rule's error estimate (the shader's
        // 32- and 16-node difference) and float rounding.
        const double e = albedo->value(mu, r), lost = std::max(1 - avg->value(r, 0.5), 1e-6);
        const bool shared = avg->width() == albedo->height() && avg->height() == 1;
        double moved = shared ? avg->claim() : avg->error(r, 0.5);
        for (size_t k = 0; k < x32.size(); ++k)
          moved += 2 * w32[k] * x32[k] * (shared ? albedo->errorAlongX(x32[k], r) : albedo->error(x32[k], r));
        const double ratio = (q[0] - e) / std::max(1 - e, 1e-6);
        dev = std::max({std::fabs(q[0] - 1.0), std::fabs(q[1] - 1.0), std::fabs(q[2] - 1.0)});
        bound = std::max(1 - e, 0.0) * moved / lost + albedo->error(mu, r) * std::fabs(1 - ratio) + q[3] + kFloatLookup;
      } else if (kind == glassRow) {
        // E_R + E_T against the reference's (a smooth interface keeps all of it: 1 at r = 0)
        double ref = 1;
        if (r > 0) {
          const reference::DielectricAlbedo d =
              reference::dielectricAlbedo(s.ndf, s.gaf, std::max(mu, 1e-6), r, kGlassEta);
          ref = d.r + d.t;
        }
        dev = std::fabs(q[0] - ref);
        bound = glass->error(mu, r) + kFloatLookup;
        if (q[0] > 1 + kFloatLookup) ++rm.created;  // more light out than in
      } else {
        dev = std::max({std::fabs(q[0] - 1.0), std::fabs(q[1] - 1.0), std::fabs(q[2] - 1.0)});
        bound = q[3];  // algebra: 1 up to float rounding whatever the tables hold
      }
      if (!rm.measured || dev >= rm.worst) {
        rm.worst = dev;
        rm.worstBound = bound;
      }
      rm.measured = true;
      rm.largestBound = std::max(rm.largestBound, bound);
      if (dev > bound) ++rm.over;
    }
  for (const RowMeasure& rm : pic.rows) pic.fail = pic.fail || rm.over > 0 || rm.created > 0;
  return pic;
}

std::string furnaceTable(const FurnaceSpec& s, const FurnacePicture& p) {
  char line[320];
  const char* fmt = "%-19s %-9s %-22s %-30s %-11s %-13s %s\n";
  std::snprintf(line, sizeof line, fmt, "row", "conserves", "tests", "largest deviation", "bound there",
                "largest bound", "pixels over");
  std::string out = line;
  for (size_t row = 0; row < s.rows.size(); ++row) {
    const FurnaceRow& fr = furnaceRows()[static_cast<size_t>(s.rows[row])];
    const RowMeasure& rm = p.rows[row];
    char dev[64] = "-", bnd[32] = "-", big[32] = "-", over[32] = "-";
    if (rm.measured) {
      std::snprintf(dev, sizeof dev, "%.3g %s", rm.worst, fr.against.c_str());
      std::snprintf(bnd, sizeof bnd, "%.3g", rm.worstBound);
      std::snprintf(big, sizeof big, "%.3g", rm.largestBound);
      std::snprintf(over, sizeof over, "%ld", rm.over + rm.created);
    }
    const char* tests = fr.checks == FurnaceRow::Checks::Tables    ? "the tables"
                        : fr.checks == FurnaceRow::Checks::Algebra ? "algebra only"
                                                                   : "nothing (looks)";
    std::snprintf(line, sizeof line, fmt, fr.name.c_str(), fr.conserves ? "yes" : "no", tests, dev, bnd, big, over);
    out += line;
  }
  out +=
      "tests: \"the tables\": the row's pixels move with the tables' values and are held to bounds from the texels "
      "each "
      "lookup reads; \"algebra only\": the row is 1 by construction whatever the tables hold (it checks the shading "
      "code, not the tables); gold and sheen are for the eye: gold is darker than the background, the sheen black at "
      "r = 0 and dim elsewhere, as they should be\n";
  return out;
}

}  // namespace brdfbake
