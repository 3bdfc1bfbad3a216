// `brdfbake render --light quad` (render/ltc_render.h).
//
// The scene: unit spheres viewed along z (orthographic, v = (0, 0, 1)), one per column of roughness
// r = 0.25 .. 1, under a two-sided quad light of radiance 1 with corners (+-2, 3, 0.5) and (+-2, 3,
// 3.5): above and in front, so that it crosses the horizon of many normals. F = 1.
//
// Each pixel's bound. The GPU computes E_i int_A D_i, E_i and D_i the tables' magnitude and LTC
// interpolated at the pixel's (n.v, r); the truth is int_A f cos = E int_A p. So
//   |E_i int_A D_i - E int_A p| <= E_i TV_i + |E_i - E|,
// TV_i the distance of the interpolated LTC to the pixel's own lobe (estimated on the host as the
// bake estimates it, with its error), plus the host quadrature's error estimate and the GPU's float
// arithmetic (acos, normalize: 2e-4 of the value, 3 times the largest deviation measured on flat
// lobes). Interpolation is inside TV_i and |E_i - E|: nothing is assumed about it.
#include "render/ltc_render.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <thread>

#include "brdfbake/brdfbake.h"
#include "common/brdf_host.h"
#include "common/errors.h"
#include "common/format.h"
#include "brdfbake/table_kind.h"
#include "common/models.h"
#include "formats/exr/table_file.h"
#include "formats/output_set.h"
#include "formats/writers.h"
#include "render/furnace.h"
#include "render/gl_context.h"
#include "shader/shader_gen.h"

namespace brdfbake {

namespace {

constexpr double kRLo = 0.25;                // the first column's roughness: narrower lobes need a finer host quadrature
constexpr double kSphere = 0.9;              // the sphere's radius, of half a cell
constexpr double kGpuFloat = 2e-4;           // the GPU's float arithmetic, relative to E_i
const double kQuad[4][3] = {{-2, 3, 0.5}, {2, 3, 0.5}, {2, 3, 3.5}, {-2, 3, 3.5}};

struct Vec {
  double x, y, z;
};
Vec sub(Vec a, Vec b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
double dot(Vec a, Vec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec cross(Vec a, Vec b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
Vec scale(Vec a, double s) { return {a.x * s, a.y * s, a.z * s}; }
Vec add(Vec a, Vec b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }

// f(v, w) (n.w) of the pair at F = 1, from kernels/brdf in double.
double fcos(const brdf64::BrdfMaterial& m, Vec n, Vec v, Vec w) {
  const double ni = dot(n, w), no = dot(n, v);
  if (ni <= 0 || no <= 0) return 0;
  brdf64::BrdfGeometry g;
  g.ni = ni;
  g.no = no;
  g.s2i = std::max(0.0, 1 - ni * ni);
  g.s2o = std::max(0.0, 1 - no * no);
  Vec h = add(v, w);
  const double hl = std::sqrt(dot(h, h));
  h = scale(h, 1 / hl);
  g.nh = dot(n, h);
  g.s2h = std::max(0.0, 1 - g.nh * g.nh);
  g.oh = dot(v, h);
  const Vec ti = sub(w, scale(n, ni)), to = sub(v, scale(n, no));
  const double sio = std::sqrt(g.s2i * g.s2o);
  g.cphi = sio > 0 ? dot(ti, to) / sio : 1;
  return brdf64::brdf_f(m, g, 0, 0, 0) * ni;
}

// int over the quad's solid angle of fcos, composite Gauss-Legendre (8 nodes) on k x k panels of
// the quad's parameter square: dw = |n_L . (X - P)| |U x W| ds dt / |X - P|^3.
double quadIntegral(const brdf64::BrdfMaterial& m, Vec n, Vec v, Vec p, int k) {
  static const double x8[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290, -0.1834346424956498,
                               0.1834346424956498,  0.5255324099163290,  0.7966664774136267,  0.9602898564975363};
  static const double w8[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873, 0.3626837833783620,
                               0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
  const Vec q0{kQuad[0][0], kQuad[0][1], kQuad[0][2]}, q1{kQuad[1][0], kQuad[1][1], kQuad[1][2]},
      q3{kQuad[3][0], kQuad[3][1], kQuad[3][2]};
  const Vec U = sub(q1, q0), W = sub(q3, q0), nl = cross(U, W);
  double sum = 0;
  for (int a = 0; a < k; ++a)
    for (int b = 0; b < k; ++b)
      for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 8; ++j) {
          const double s = (a + 0.5 + 0.5 * x8[i]) / k, t = (b + 0.5 + 0.5 * x8[j]) / k;
          const Vec d = sub(add(q0, add(scale(U, s), scale(W, t))), p);
          const double d2 = dot(d, d), dl = std::sqrt(d2);
          const Vec w = scale(d, 1 / dl);
          sum += w8[i] * w8[j] * fcos(m, n, v, w) * std::fabs(dot(nl, d)) / (d2 * dl);
        }
  return sum / (4.0 * k * k);
}

// Bilinear in double on the node grid x = r, y = sqrt(1 - mu) (the shader's exact path in float).
double bilinear(const TableImage& t, int c, double r, double mu) {
  const int n = t.width;
  const double px = std::clamp(r, 0.0, 1.0) * (n - 1), py = std::sqrt(std::clamp(1 - mu, 0.0, 1.0)) * (n - 1);
  const int x0 = std::min(static_cast<int>(px), n - 2), y0 = std::min(static_cast<int>(py), n - 2);
  const double fx = px - x0, fy = py - y0;
  auto at = [&](int x, int y) { return static_cast<double>(t.planes[c][static_cast<size_t>(y) * n + x]); };
  return (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x0 + 1, y0)) + fy * ((1 - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1));
}

struct Pixel {
  Vec n;
  double r;
  bool sphere = false;
};

}  // namespace

int runLtcRender(const RenderOptions& o) {
  if (o.cell < 16 || o.cell > 256)
    throw Error(kExitUsage, "--cell: pixels per sphere, 16..256, got " + std::to_string(o.cell));
  if (o.columns < 2 || o.columns > 33)
    throw Error(kExitUsage, "--columns: roughness steps, 2..33, got " + std::to_string(o.columns));
  if (!o.rows.empty()) throw Error(kExitUsage, "--rows: the furnace's rows; --light quad draws one row of spheres");
  const int ndf = ndfId(o.ndf), gaf = gafId(o.gaf);
  checkPair(ndf, gaf);
  checkOutputDir(o.outDir);
  GlContext gl;  // no EGL: exit 69 before anything is baked

  // the tables, as `brdfbake bake --table ltc` bakes them
  BakeRequest req = defaultRequest();
  req.ndfs = {ndf};
  req.gafs = {gaf};
  req.tables = {TableKind::Ltc};
  req.outDir = o.outDir + "/tables";
  req.device = o.device;
  req.cacheDir = o.cacheDir;
  req.noWait = o.noWait;
  std::string p1, p2;
  for (const TableReport& rep : bakeToDirectory(req))
    (rep.path.find("/ltc1_") != std::string::npos ? p1 : p2) = rep.path;
  const TableImage t1 = readTableExr(p1), t2 = readTableExr(p2);
  if (t1.planes.size() != 4 || t2.planes.size() != 4)
    throw Error(kExitSoftware, "internal: render read LTC tables without four channels");

  // the pixels
  const int cell = o.cell, W = cell * o.columns, H = cell;
  const size_t np = static_cast<size_t>(W) * H;
  std::vector<Pixel> px(np);
  std::vector<float> geo(np * 4, 0.0f);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const int c = x / cell;
      const double dx = ((x % cell) + 0.5) / cell * 2 - 1, dy = 1 - (y + 0.5) / cell * 2;
      const double ux = dx / kSphere, uy = dy / kSphere, d2 = ux * ux + uy * uy;
      const size_t k = static_cast<size_t>(y) * W + x;
      if (d2 >= 1) continue;
      Pixel& p = px[k];
      p.n = {ux, uy, std::sqrt(1 - d2)};
      p.r = kRLo + (1 - kRLo) * c / (o.columns - 1);
      p.sphere = true;
      geo[k * 4] = static_cast<float>(p.n.x);
      geo[k * 4 + 1] = static_cast<float>(p.n.y);
      geo[k * 4 + 2] = static_cast<float>(p.n.z);
      geo[k * 4 + 3] = static_cast<float>(p.r);
    }

  // GL: the generated lookups and polygon integral, the exact (float-weight) path
  const std::string P1 = shaderPrefix(p1), P2 = shaderPrefix(p2);
  auto corner = [](int i) {
    return "vec3(" + fmtG9(kQuad[i][0]) + ", " + fmtG9(kQuad[i][1]) + ", " + fmtG9(kQuad[i][2]) + ")";
  };
  const std::string src =
      "#version 310 es\nprecision highp float;\nprecision highp int;\nprecision highp sampler2D;\n"
      "layout(local_size_x = 8, local_size_y = 8) in;\n"
      "layout(std430, binding = 1) buffer Geometry { vec4 geo[]; };\n"
      "layout(std430, binding = 2) buffer Out { float outv[]; };\n"
      "uniform sampler2D " + P1 + "_tex;\nuniform sampler2D " + P2 + "_tex;\n" +
      shaderForFiles({p1, p2}, ShaderLang::Glsl) + "const int W = " + std::to_string(W) +
      ", H = " + std::to_string(H) + ";\n" +
      "void main() {\n"
      "  ivec2 p = ivec2(gl_GlobalInvocationID.xy);\n"
      "  if (p.x >= W || p.y >= H) return;\n"
      "  int k = p.y * W + p.x;\n"
      "  vec4 g = geo[k];\n"
      "  if (g.w <= 0.0) { outv[k] = 0.0; return; }\n"
      "  vec3 N = normalize(g.xyz), V = vec3(0.0, 0.0, 1.0);\n"
      "  float mu = clamp(dot(N, V), 0.0, 1.0);\n"
      "  vec4 invM = " + P1 + "_invMExact(" + P1 + "_tex, mu, g.w);\n"
      "  float e = " + P2 + "_magnitudeExact(" + P2 + "_tex, mu, g.w).x;\n"
      "  outv[k] = e * ltc_polygon(invM, N, V, N, " + corner(0) + ", " + corner(1) + ", " + corner(2) + ", " +
      corner(3) + ");\n"
      "}\n";
  const GlFunctions& g = gl.gl();
  const GLuint prog = gl.computeProgram(src);
  g.UseProgram(prog);
  GLuint tex[2] = {bindPlanesTexture(gl, t1.width, t1.height, t1.planes, 0),
                   bindPlanesTexture(gl, t2.width, t2.height, t2.planes, 1)};
  g.Uniform1i(g.GetUniformLocation(prog, (P1 + "_tex").c_str()), 0);
  g.Uniform1i(g.GetUniformLocation(prog, (P2 + "_tex").c_str()), 1);
  GLuint buf[2] = {0, 0};
  g.GenBuffers(2, buf);
  g.BindBuffer(GL_SHADER_STORAGE_BUFFER, buf[0]);
  g.BufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(geo.size() * sizeof(float)), geo.data(), GL_STATIC_DRAW);
  g.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, buf[0]);
  g.BindBuffer(GL_SHADER_STORAGE_BUFFER, buf[1]);
  g.BufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(np * sizeof(float)), nullptr, GL_DYNAMIC_READ);
  g.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, buf[1]);
  g.DispatchCompute(static_cast<GLuint>((W + 7) / 8), static_cast<GLuint>((H + 7) / 8), 1);
  g.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  g.Finish();
  const float* m = static_cast<const float*>(
      g.MapBufferRange(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(np * sizeof(float)), GL_MAP_READ_BIT));
  if (!m) throw Error(kExitSoftware, "render: could not read the quad-light picture back (GL error " +
                                         std::to_string(g.GetError()) + ")");
  std::vector<float> shown(m, m + np);
  g.UnmapBuffer(GL_SHADER_STORAGE_BUFFER);
  g.DeleteBuffers(2, buf);
  g.DeleteTextures(2, tex);
  g.DeleteProgram(prog);

  // the truth and each pixel's bound, on the host (two threads)
  std::vector<double> ref(np, 0), bound(np, 0);
  auto work = [&](size_t from, size_t step) {
    for (size_t k = from; k < np; k += step) {
      const Pixel& p = px[k];
      if (!p.sphere) continue;
      brdf64::BrdfMaterial mat;
      mat.ndf = ndf;
      mat.gaf = gaf;
      mat.p = brdf64::brdf_params(ndf, gaf, p.r);
      mat.fresnel = FRESNEL_ONE;
      mat.diffuse = -1;
      mat.dparam = 0;
      const Vec v{0, 0, 1};
      const double coarse = quadIntegral(mat, p.n, v, p.n, 8), fine = quadIntegral(mat, p.n, v, p.n, 16);
      ref[k] = fine;
      const double mu = std::clamp(p.n.z, 0.0, 1.0);
      const double ei = bilinear(t2, 0, p.r, mu);
      const brdf64::HemiResult h = brdf64::hemisphere_texel(ndf, gaf, mu, p.r, 1e-8);
      const double e = h.a + h.b;
      const brdf64::LtcLobe L = brdf64::ltc_lobe(0, ndf, gaf, -1, mu, p.r, 0, mat.p.inv_kp, e);
      const brdf64::Ltc l = brdf64::ltc_from_stored(bilinear(t1, 0, p.r, mu), bilinear(t1, 1, p.r, mu),
                                                    bilinear(t1, 2, p.r, mu), bilinear(t1, 3, p.r, mu));
      double tv[3];
      brdf64::ltc_tv(&L, l, 128, 16, tv);  // 16 shifts: the error estimate ltc_tv states (4 standard errors)
      bound[k] = ei * (tv[0] + tv[1]) + std::fabs(ei - e) + std::fabs(fine - coarse) + kGpuFloat * ei;
    }
  };
  std::thread other(work, 1, 2);
  work(0, 2);
  other.join();

  // the measurement
  size_t worst = 0, over = 0, pixels = 0, tightest = 0;
  double worstDev = -1, worstRatio = -1;
  for (size_t k = 0; k < np; ++k) {
    if (!px[k].sphere) continue;
    if (!std::isfinite(shown[k])) throw Error(kExitSoftware, "render: a quad-light pixel is not finite");
    ++pixels;
    const double dev = std::fabs(shown[k] - ref[k]);
    if (dev > worstDev) worstDev = dev, worst = k;
    if (dev / bound[k] > worstRatio) worstRatio = dev / bound[k], tightest = k;
    over += dev > bound[k];
  }

  // the files: the GL picture (linear EXR, sRGB PNG), the truth beside it in the EXR's G channel
  TableImage img;
  img.width = W;
  img.height = H;
  img.channels = {"R", "G", "B"};
  img.planes.assign(3, std::vector<float>(np, 0.0f));
  for (size_t k = 0; k < np; ++k) {
    img.planes[0][k] = shown[k];
    img.planes[1][k] = static_cast<float>(ref[k]);
    img.planes[2][k] = static_cast<float>(bound[k]);
  }
  img.strings["render.kind"] =
      "quad light of radiance 1, corners (+-2, 3, 0.5), (+-2, 3, 3.5), two-sided; unit spheres, view (0, 0, 1), F = 1";
  img.strings["render.channels"] = "R = GL with the LTC tables, G = the host's exact integral, B = the pixel's bound";
  img.strings["render.model"] = o.ndf + " + " + o.gaf;
  img.strings["render.columns"] = "perceptual roughness " + fmtG(kRLo) + " .. 1 in " + std::to_string(o.columns) + " steps";
  img.strings["render.renderer"] = gl.renderer();
  img.strings["render.generator"] = "brdfbake render --light quad";
  TableImage view = img;
  view.planes = {shown, shown, shown};
  std::vector<std::pair<std::string, std::string>> text;
  for (const auto& [k, v] : img.strings) text.push_back({k, v});
  const std::string exr = o.outDir + "/ltc_quad.exr", png = o.outDir + "/ltc_quad.png";
  std::vector<OutputFile> files(2);
  files[0].path = exr;
  files[0].write = [&img, exr](const std::string& tmp) { writeTableExrTemporary(tmp, exr, img, false); };
  files[0].bytesBound = np * 12 + (1 << 16);
  files[1].path = png;
  files[1].write = [&view, &text, png, W, H](const std::string& tmp) {
    writePng8SrgbTemporary(tmp, png, W, H, view.planes, text);
  };
  files[1].bytesBound = np * 3 + (1 << 16);
  commitOutputs(o.outDir, files, !o.noWait);

  auto where = [&](size_t k) {
    return "r = " + fmt3(px[k].r) + ", n.v = " + fmt3(px[k].n.z);
  };
  std::printf("render: quad light, %d spheres (%d px each, r = %g .. 1), %s + %s, on %s; tables in %s/\n", o.columns,
              cell, kRLo, o.ndf.c_str(), o.gaf.c_str(), gl.renderer().c_str(), req.outDir.c_str());
  std::printf("largest deviation from the exact integral %.3g at %s (value %.3g), its bound %.3g\n", worstDev,
              where(worst).c_str(), ref[worst], bound[worst]);
  std::printf("closest to its bound: %.3g of %.3g at %s; %zu of %zu pixels over their bound\n",
              std::fabs(shown[tightest] - ref[tightest]), bound[tightest], where(tightest).c_str(), over, pixels);
  std::printf("wrote %s (R: GL, G: exact, B: bound) and %s\n", exr.c_str(), png.c_str());
  if (over) std::printf("FAIL: %zu pixels are off by more than their bound\n", over);
  return over ? 1 : 0;
}

}  // namespace brdfbake
