#include "shader/shader_gen.h"

#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>

#include "common/errors.h"
#include "common/format.h"
#include "formats/readers/table_reader.h"

namespace brdfbake {

namespace {

// The few words GLSL (ES 3.00 / 3.30 and later) and HLSL (shader model 4 and later) spell apart.
struct Lang {
  bool hlsl;
  std::string f2() const { return hlsl ? "float2" : "vec2"; }
  std::string f3() const { return hlsl ? "float3" : "vec3"; }
  std::string f4() const { return hlsl ? "float4" : "vec4"; }
  std::string i2() const { return hlsl ? "int2" : "ivec2"; }
  std::string mix() const { return hlsl ? "lerp" : "mix"; }
  std::string cst() const { return hlsl ? "static const" : "const"; }
  std::string texParam() const { return hlsl ? "Texture2D<float4> tex, SamplerState smp" : "sampler2D tex"; }
  std::string texArgs() const { return hlsl ? "tex, smp" : "tex"; }
  std::string sample(const std::string& uv) const {
    return hlsl ? "tex.SampleLevel(smp, " + uv + ", 0.0)" : "textureLod(tex, " + uv + ", 0.0)";
  }
  std::string fetch(const std::string& ij) const {
    return hlsl ? "tex.Load(int3(" + ij + ", 0))" : "texelFetch(tex, " + ij + ", 0)";
  }
};

std::string lit(double v) {
  std::string s = fmtG9(v);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

std::string attr(const TableImage& h, const std::string& k, const std::string& fallback = "") {
  auto it = h.strings.find(k);
  return it == h.strings.end() ? fallback : it->second;
}

// Axis a of a 2D/1D table: its range from brdf.<name>.range, its name from brdf.axes; the mu axis
// spaced in u = sqrt(mu) where brdf.mu.index says sqrt (--mu-axis sqrt).
struct Axis {
  std::string name;
  double lo = 0, hi = 1;
  bool sqrtIndex = false;
};

std::vector<Axis> axesOf(const std::string& path, const TableImage& h) {
  std::string list = attr(h, "brdf.axes");
  if (list.empty()) throw Error(kExitDataErr, path + ": no brdf.axes attribute: not a table brdfbake wrote");
  std::vector<Axis> axes;
  size_t start = 0;
  while (true) {
    size_t comma = list.find(',', start);
    Axis a;
    a.name = list.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    auto it = h.v2f.find("brdf." + a.name + ".range");
    if (it != h.v2f.end()) {
      a.lo = it->second.first;
      a.hi = it->second.second;
    }
    axes.push_back(a);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  const std::string index = attr(h, "brdf.mu.index", "linear");
  const bool sq = index.rfind("sqrt", 0) == 0;
  if (!sq && index.rfind("linear", 0) != 0)
    throw Error(kExitDataErr, path + ": brdf.mu.index '" + index + "' is not one brdfbake reads: linear or sqrt");
  bool found = false;
  for (Axis& a : axes) found = (a.sqrtIndex = sq && a.name == "mu" && a.lo >= 0 && a.hi > a.lo) || found;
  if (sq && !found)
    throw Error(kExitDataErr, path + ": brdf.mu.index is sqrt but brdf.axes (" + list +
                                  ") has no mu axis with a range in [0, inf) to take the square root of");
  return axes;
}

// A number attribute: a float one, or a string that is all number (text metadata: KTX2, PNG).
bool numberAttr(const TableImage& h, const std::string& k, double* v) {
  if (auto f = h.floats.find(k); f != h.floats.end()) return *v = f->second, true;
  auto it = h.strings.find(k);
  if (it == h.strings.end() || it->second.empty()) return false;
  char* end = nullptr;
  *v = std::strtod(it->second.c_str(), &end);
  return *end == '\0';
}

// The stored values' mapping (png16: value = stored * scale + offset, brdf.mapping.scale/offset)
// applied to a texel `v` (RGB; alpha is padding); `v` itself when the file stores the values as they are.
std::string mapped(const Lang& L, const TableImage& h, const std::string& v) {
  double scale = 1, offset = 0;
  bool has = numberAttr(h, "brdf.mapping.scale", &scale);
  has = numberAttr(h, "brdf.mapping.offset", &offset) || has;
  if (!has || (scale == 1 && offset == 0)) return v;
  return v + " * " + L.f4() + "(" + lit(scale) + ", " + lit(scale) + ", " + lit(scale) + ", 1.0) + " + L.f4() + "(" +
         lit(offset) + ", " + lit(offset) + ", " + lit(offset) + ", 0.0)";
}

// The coordinate maps and both lookup paths of a 2D (or 1D: height 1) table.
std::string lookups2d(const Lang& L, const std::string& P, const TableImage& h, const std::vector<Axis>& ax, bool node) {
  const int w = h.width, hgt = h.height;
  const bool oneD = hgt == 1;
  // the fraction of axis a's range `v` lies at; on a sqrt(mu) axis the fraction of sqrt(mu)'s
  auto frac = [&](const Axis& a, const std::string& v) {
    if (!a.sqrtIndex) return "(" + v + " - " + lit(a.lo) + ") / (" + lit(a.hi) + " - " + lit(a.lo) + ")";
    return "(sqrt(max(" + v + ", 0.0)) - " + lit(std::sqrt(a.lo)) + ") / (" + lit(std::sqrt(a.hi)) + " - " +
           lit(std::sqrt(a.lo)) + ")";
  };
  std::string s;
  s += L.cst() + " " + L.f2() + " " + P + "_SIZE = " + L.f2() + "(" + lit(w) + ", " + lit(hgt) + ");\n";
  std::string args = oneD ? "float x" : "float x, float y";
  std::string yExpr = oneD ? "0.5" : frac(ax[1], "y");
  s += "// fraction of each axis' range, clamped: quantities outside the table read its edge\n";
  for (size_t a = 0; a < ax.size() && a < 2; ++a)
    if (ax[a].sqrtIndex)
      s += "// " + std::string(a ? "y" : "x") + " is spaced in sqrt(mu) (brdf.mu.index sqrt): texel i holds mu = u_i^2\n";
  const std::string flip = attr(h, "brdf.layout.flip", "none");
  const bool fx = flip.find('x') != std::string::npos, fy = flip.find('y') != std::string::npos;
  s += L.f2() + " " + P + "_t(" + args + ") {\n  " + L.f2() + " t = clamp(" + L.f2() + "(" + frac(ax[0], "x") + ", " + yExpr +
       "), 0.0, 1.0);\n";
  if (fx) s += "  t.x = 1.0 - t.x;  // texel 0 holds the high end of x (brdf.layout.flip)\n";
  if (fy) s += "  t.y = 1.0 - t.y;  // texel 0 holds the high end of y (brdf.layout.flip)\n";
  s += "  return t;\n}\n";
  s += "// texture coordinate for the hardware filter (" + std::string(node ? "node grid: texel i holds i/(n-1)" :
                                                                        "texel-center grid: texel i holds (i+0.5)/n") + ")\n";
  s += L.f2() + " " + P + "_uv(" + args + ") {\n";
  if (node) s += "  return (0.5 + " + P + "_t(" + (oneD ? "x" : "x, y") + ") * (" + P + "_SIZE - 1.0)) / " + P + "_SIZE;\n";
  else s += "  return " + P + "_t(" + (oneD ? "x" : "x, y") + ");\n";
  s += "}\n";
  s += L.f4() + " " + P + "_lookup(" + L.texParam() + ", " + args + ") {\n  return " +
       mapped(L, h, L.sample(P + "_uv(" + (oneD ? "x" : "x, y") + ")")) + ";\n}\n";
  s += "// exact filtering: the four texels and the weights in float (hardware weights may have 8 bits)\n";
  s += L.f4() + " " + P + "_lookupExact(" + L.texParam() + ", " + args + ") {\n";
  s += "  " + L.f2() + " p = " + P + "_t(" + (oneD ? "x" : "x, y") + ") * " +
       (node ? "(" + P + "_SIZE - 1.0)" : P + "_SIZE - 0.5") + ";\n";
  s += "  p = clamp(p, " + L.f2() + "(0.0, 0.0), " + P + "_SIZE - 1.0);\n";
  s += "  " + L.f2() + " i0 = floor(p);\n  " + L.f2() + " f = p - i0;\n";
  s += "  " + L.i2() + " a = " + L.i2() + "(i0);\n  " + L.i2() + " b = min(a + 1, " + L.i2() + "(" + P + "_SIZE) - 1);\n";
  s += "  " + L.f4() + " v00 = " + L.fetch("a") + ";\n";
  s += "  " + L.f4() + " v10 = " + L.fetch(L.i2() + "(b.x, a.y)") + ";\n";
  s += "  " + L.f4() + " v01 = " + L.fetch(L.i2() + "(a.x, b.y)") + ";\n";
  s += "  " + L.f4() + " v11 = " + L.fetch("b") + ";\n";
  s += "  return " + mapped(L, h, L.mix() + "(" + L.mix() + "(v00, v10, f.x), " + L.mix() + "(v01, v11, f.x), f.y)") +
       ";\n}\n";
  return s;
}

// The quantities of each table kind, on both paths.
std::string semantics2d(const Lang& L, const std::string& P, const TableImage& h, bool oneD) {
  const std::string table = attr(h, "brdf.table"), channels = attr(h, "brdf.channels");
  const bool rgb = channels.rfind("R,G,B", 0) == 0;
  const std::string args = oneD ? "float x" : "float mu, float r";
  // the layout (formats/layout.h): r along x swaps the arguments; the stored channels give A and B
  const std::string call = oneD ? "x" : attr(h, "brdf.axes") == "r,mu" ? "r, mu" : "mu, r";
  const std::string stored = attr(h, "brdf.layout.channels", "A,B,A+B");
  std::vector<std::string> ch;
  for (size_t at = 0; at <= stored.size();) {
    size_t comma = stored.find(',', at);
    if (comma == std::string::npos) comma = stored.size();
    ch.push_back(stored.substr(at, comma - at));
    at = comma + 1;
  }
  auto idx = [&](const std::string& q) {
    for (size_t c = 0; c < ch.size(); ++c)
      if (ch[c] == q) return std::string("v.") + "rgb"[c];
    return std::string();
  };
  const std::string sA = idx("A"), sB = idx("B"), sAB = idx("A+B");
  const std::string exA = !sA.empty() ? sA : "(" + sAB + " - " + sB + ")", exB = !sB.empty() ? sB : "(" + sAB + " - " + sA + ")";
  const bool plainLayout = stored == "A,B,A+B";
  std::string s;
  for (std::string variant : {"", "Exact"}) {
    std::string get = P + "_lookup" + variant + "(" + L.texArgs() + ", " + call + ")";
    auto fn = [&](const std::string& type, const std::string& name, const std::string& extra, const std::string& body) {
      s += type + " " + P + "_" + name + variant + "(" + L.texParam() + (extra.empty() ? "" : ", " + extra) + ", " + args +
           ") {\n" + body + "}\n";
    };
    if (table == "splitsum") {
      fn(L.f2(), "AB", "", "  " + L.f4() + " v = " + get + ";\n  return " + L.f2() + "(" + exA + ", " + exB + ");\n");
      fn(L.f3(), "Schlick", L.f3() + " f0", "  " + L.f4() + " v = " + get + ";\n  return f0 * " + exA + " + " + exB + ";\n");
      if (!plainLayout) {
        // a layout's channels hold A, B and A + B only
      } else if (attr(h, "brdf.fresnel") == "f82-tint")
        fn(L.f3(), "F82Tint", L.f3() + " f0, " + L.f3() + " b",
           "  " + L.f4() + " v = " + get + ";\n  return f0 * v.r + v.g - b * v.b;\n");
      else if (channels.find("E_d") != std::string::npos)
        fn("float", "DiffuseAlbedo", "", "  return " + get + ".b;\n");
    } else if (table == "albedo" || table == "albedo-avg" || table == "kp" || table == "fresnel-avg") {
      std::string name = table == "albedo" ? "E" : table == "albedo-avg" ? "Eavg" : table == "kp" ? "Kp" : "Favg";
      if (rgb) fn(L.f3(), name, "", "  return " + get + ".rgb;\n");
      else fn("float", name, "", "  return " + get + ".r;\n");
    } else if (table == "dielectric-avg") {
      // (r, s) stored; the eta a material has, mapped as the table's eta axis is
      s += "// E_R,avg, E_T,avg and their sum at (r, eta), eta by s = (eta - 1)/(eta + 1)\n";
      s += L.f3() + " " + P + "_albedosAvg" + variant + "(" + L.texParam() + ", float r, float eta) {\n  return " + P +
           "_lookup" + variant + "(" + L.texArgs() + ", r, (eta - 1.0) / (eta + 1.0)).rgb;\n}\n";
    }
  }
  return s;
}

// An atlas table's size (brdf.size NXxNYxNZ) and tile grid (brdf.atlas COLSxROWS).
struct AtlasShape {
  int nx = 0, ny = 0, nz = 0, cols = 0, rows = 0;
};
AtlasShape atlasShape(const std::string& path, const TableImage& h) {
  AtlasShape a;
  if (std::sscanf(attr(h, "brdf.size").c_str(), "%dx%dx%d", &a.nx, &a.ny, &a.nz) != 3 ||
      std::sscanf(attr(h, "brdf.atlas").c_str(), "%dx%d", &a.cols, &a.rows) != 2)
    throw Error(kExitDataErr, path + ": brdf.size / brdf.atlas missing: not a " + attr(h, "brdf.table") +
                                  " table brdfbake wrote");
  return a;
}

// The index of t in [0, 1]^3 on the table's grid.
std::string gridIndex(const std::string& P, const std::string& grid) {
  if (grid == "node") return "  return clamp(t, 0.0, 1.0) * (" + P + "_SIZE - 1.0);\n";
  if (grid == "cell-start") return "  return clamp(t, 0.0, 1.0) * " + P + "_SIZE;\n";
  return "  return clamp(t, 0.0, 1.0) * " + P + "_SIZE - 0.5;\n";
}

// The atlas's lookups over P_index(args): one slice's bilinear lookup kept inside its tile, two of
// them and a lerp (P_lookup, the hardware filter), or eight texelFetches (P_lookupExact).
std::string atlasLookups(const Lang& L, const std::string& P, const std::string& args, const std::string& call) {
  std::string s;
  s += "// one slice's bilinear lookup, kept inside its tile of the atlas\n";
  s += L.f4() + " " + P + "_slice(" + L.texParam() + ", " + L.f2() + " p, float z) {\n";
  s += "  " + L.f2() + " tile = " + L.f2() + "(z - " + P + "_ATLAS.x * floor(z / " + P + "_ATLAS.x), floor(z / " + P +
       "_ATLAS.x));\n";
  s += "  " + L.f2() + " q = clamp(p, " + L.f2() + "(0.0, 0.0), " + P + "_SIZE.xy - 1.0) + tile * " + P + "_SIZE.xy + 0.5;\n";
  s += "  return " + L.sample("q / (" + P + "_ATLAS * " + P + "_SIZE.xy)") + ";\n}\n";
  s += L.f4() + " " + P + "_lookup(" + L.texParam() + ", " + args + ") {\n";
  s += "  " + L.f3() + " p = clamp(" + P + "_index(" + call + "), " + L.f3() + "(0.0, 0.0, 0.0), " + P + "_SIZE - 1.0);\n";
  s += "  float z0 = floor(p.z);\n  float z1 = min(z0 + 1.0, " + P + "_SIZE.z - 1.0);\n";
  s += "  return " + L.mix() + "(" + P + "_slice(" + L.texArgs() + ", p.xy, z0), " + P + "_slice(" + L.texArgs() +
       ", p.xy, z1), p.z - z0);\n}\n";
  s += L.f4() + " " + P + "_texel(" + L.texParam() + ", " + L.i2() + " xy, float z) {\n";
  s += "  " + L.i2() + " tile = " + L.i2() + "(int(z) % int(" + P + "_ATLAS.x), int(z) / int(" + P + "_ATLAS.x));\n";
  s += "  return " + L.fetch("xy + tile * " + L.i2() + "(" + P + "_SIZE.xy)") + ";\n}\n";
  s += L.f4() + " " + P + "_lookupExact(" + L.texParam() + ", " + args + ") {\n";
  s += "  " + L.f3() + " p = clamp(" + P + "_index(" + call + "), " + L.f3() + "(0.0, 0.0, 0.0), " + P + "_SIZE - 1.0);\n";
  s += "  " + L.f3() + " i0 = floor(p);\n  " + L.f3() + " f = p - i0;\n";
  s += "  " + L.i2() + " a0 = " + L.i2() + "(i0.xy);\n  " + L.i2() + " a1 = min(a0 + 1, " + L.i2() + "(" + P + "_SIZE.xy) - 1);\n";
  s += "  float z1 = min(i0.z + 1.0, " + P + "_SIZE.z - 1.0);\n";
  s += "  " + L.f4() + " r0 = " + L.mix() + "(" + L.mix() + "(" + P + "_texel(" + L.texArgs() + ", a0, i0.z), " + P + "_texel(" +
       L.texArgs() + ", " + L.i2() + "(a1.x, a0.y), i0.z), f.x), " + L.mix() + "(" + P + "_texel(" + L.texArgs() + ", " + L.i2() +
       "(a0.x, a1.y), i0.z), " + P + "_texel(" + L.texArgs() + ", a1, i0.z), f.x), f.y);\n";
  s += "  " + L.f4() + " r1 = " + L.mix() + "(" + L.mix() + "(" + P + "_texel(" + L.texArgs() + ", a0, z1), " + P + "_texel(" +
       L.texArgs() + ", " + L.i2() + "(a1.x, a0.y), z1), f.x), " + L.mix() + "(" + P + "_texel(" + L.texArgs() + ", " + L.i2() +
       "(a0.x, a1.y), z1), " + P + "_texel(" + L.texArgs() + ", a1, z1), f.x), f.y);\n";
  s += "  return " + L.mix() + "(r0, r1, f.z);\n}\n";
  return s;
}

// The rough-dielectric cube (tables/dielectric.cpp): an atlas of eta slices over (mu, r), the eta
// axis in s = (eta - 1)/(eta + 1) between brdf.s.range's ends; P_albedos(mu, r, eta) gives E_R,
// E_T and E_R + E_T.
std::string lookupsDielectric(const Lang& L, const std::string& P, const std::string& path, const TableImage& h) {
  const AtlasShape a = atlasShape(path, h);
  auto range = [&](const std::string& k) {
    auto it = h.v2f.find(k);
    if (it == h.v2f.end() || !(it->second.second > it->second.first))
      throw Error(kExitDataErr, path + ": " + k + " missing or empty: not a dielectric table brdfbake wrote");
    return std::array<double, 2>{it->second.first, it->second.second};
  };
  const auto mu = range("brdf.mu.range"), r = range("brdf.r.range"), sr = range("brdf.s.range"),
             eta = range("brdf.eta.range");
  std::string s;
  s += L.cst() + " " + L.f3() + " " + P + "_SIZE = " + L.f3() + "(" + lit(a.nx) + ", " + lit(a.ny) + ", " + lit(a.nz) + ");\n";
  s += L.cst() + " " + L.f2() + " " + P + "_ATLAS = " + L.f2() + "(" + lit(a.cols) + ", " + lit(a.rows) + ");\n";
  s += "// texel index of (mu, r, eta): the " + attr(h, "brdf.grid") + " grid, eta by s = (eta - 1)/(eta + 1) in [" +
       lit(sr[0]) + ", " + lit(sr[1]) + "] (eta " + fmtG(eta[0]) + " to " + fmtG(eta[1]) + "); outside it the edge slice\n";
  s += L.f3() + " " + P + "_index(float mu, float r, float eta) {\n";
  s += "  float s = (eta - 1.0) / (eta + 1.0);\n";
  s += "  " + L.f3() + " t = " + L.f3() + "((mu - " + lit(mu[0]) + ") / " + lit(mu[1] - mu[0]) + ", (r - " + lit(r[0]) + ") / " +
       lit(r[1] - r[0]) + ", (s - " + lit(sr[0]) + ") / " + lit(sr[1] - sr[0]) + ");\n";
  s += gridIndex(P, attr(h, "brdf.grid"));
  s += "}\n";
  s += atlasLookups(L, P, "float mu, float r, float eta", "mu, r, eta");
  s += "// E_R (reflected albedo), E_T (transmitted: the fraction of energy that crosses), E_R + E_T\n";
  for (std::string variant : {"", "Exact"})
    s += L.f3() + " " + P + "_albedos" + variant + "(" + L.texParam() + ", float mu, float r, float eta) {\n  return " + P +
         "_lookup" + variant + "(" + L.texArgs() + ", mu, r, eta).rgb;\n}\n";
  return s;
}

// The 3D table's atlas: two bilinear fetches of the neighbouring slices and a lerp (hardware), or
// eight texels (exact); the angles from vectors in the table's parameterisation.
std::string lookups3d(const Lang& L, const std::string& P, const std::string& path, const TableImage& h) {
  const AtlasShape a = atlasShape(path, h);
  const bool rus = attr(h, "brdf.param") == "rusinkiewicz";
  const bool sq = attr(h, "brdf.theta_h.index").rfind("sqrt", 0) == 0;
  const std::string grid = attr(h, "brdf.grid");
  std::string s;
  s += L.cst() + " " + L.f3() + " " + P + "_SIZE = " + L.f3() + "(" + lit(a.nx) + ", " + lit(a.ny) + ", " + lit(a.nz) + ");\n";
  s += L.cst() + " " + L.f2() + " " + P + "_ATLAS = " + L.f2() + "(" + lit(a.cols) + ", " + lit(a.rows) + ");\n";
  s += "// texel index of each angle (radians): the " + grid + " grid" + (sq ? ", theta_h by MERL's sqrt index" : "") + "\n";
  s += L.f3() + " " + P + "_index(float a, float b, float c) {\n";
  s += "  " + L.f3() + " t = " + L.f3() + "(a / 1.5707963, b / 1.5707963, c / 3.14159265);\n";
  if (sq) s += "  t.x = sqrt(max(t.x, 0.0));\n";
  s += gridIndex(P, grid);
  s += "}\n";
  s += atlasLookups(L, P, "float a, float b, float c", "a, b, c");
  for (std::string variant : {"", "Exact"})
    s += L.f3() + " " + P + "_f" + variant + "(" + L.texParam() + ", float a, float b, float c) {\n  return " + P +
         "_lookup" + variant + "(" + L.texArgs() + ", a, b, c).rgb;\n}\n";
  // angles from the unit vectors n (normal), l (to the light), v (to the viewer)
  s += "// the table's angles from unit vectors: n the normal, l towards the light (i), v towards the viewer (o)\n";
  s += L.f3() + " " + P + "_angles(" + L.f3() + " n, " + L.f3() + " l, " + L.f3() + " v) {\n";
  if (!rus) {
    s += "  float ci = clamp(dot(n, l), -1.0, 1.0);\n  float co = clamp(dot(n, v), -1.0, 1.0);\n";
    s += "  " + L.f3() + " lp = l - n * ci;\n  " + L.f3() + " vp = v - n * co;\n";
    s += "  float d = sqrt(dot(lp, lp) * dot(vp, vp));\n";
    s += "  float cphi = d > 1e-12 ? clamp(dot(lp, vp) / d, -1.0, 1.0) : 1.0;\n";
    s += "  return " + L.f3() + "(acos(ci), acos(co), acos(cphi));\n";
  } else {
    s += "  " + L.f3() + " h = normalize(l + v);\n";
    s += "  " + L.f3() + " b = cross(n, h);\n";
    s += "  if (dot(b, b) < 1e-12) b = cross(n, abs(n.x) < 0.9 ? " + L.f3() + "(1.0, 0.0, 0.0) : " + L.f3() + "(0.0, 1.0, 0.0));\n";
    s += "  b = normalize(b);\n  " + L.f3() + " t = cross(b, h);\n";
    s += "  float phi = atan2(dot(l, b), dot(l, t));\n";
    if (!L.hlsl) s.replace(s.rfind("atan2("), 6, "atan(");
    s += "  if (phi < 0.0) phi += 3.14159265;  // f(phi_d) = f(phi_d + pi): reciprocity\n";
    s += "  return " + L.f3() + "(acos(clamp(dot(n, h), -1.0, 1.0)), acos(clamp(dot(h, l), -1.0, 1.0)), phi);\n";
  }
  s += "}\n";
  return s;
}

}  // namespace

std::string shaderPrefix(const std::string& path) {
  size_t slash = path.find_last_of('/');
  std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
  base = base.substr(0, base.find('.'));
  std::string id = "brdf_";
  for (char c : base) id += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return id;
}

std::string shaderForTable(const std::string& path, const TableImage& h, ShaderLang lang) {
  Lang L{lang == ShaderLang::Hlsl};
  const std::string P = shaderPrefix(path), table = attr(h, "brdf.table");
  if (table.empty()) throw Error(kExitDataErr, path + ": no brdf.table attribute: not a table brdfbake wrote");
  std::string s = "// ---- " + path + ": " + table;
  if (!attr(h, "brdf.ndf").empty()) s += ", " + attr(h, "brdf.ndf") + " + " + attr(h, "brdf.gaf");
  s += "\n// axes " + attr(h, "brdf.axes") + ", " + attr(h, "brdf.grid") + " grid, " +
       (attr(h, "brdf.mu.index").rfind("sqrt", 0) == 0 ? "mu index sqrt, " : "") + "channels " + attr(h, "brdf.channels") + "\n";
  auto err = h.floats.find("brdf.error");
  if (err != h.floats.end())
    s += "// error budget (relative to max(1, |value|)): table " + fmtG(err->second) +
         " (integration, float arithmetic, storage); add the interpolation error of the resolution" +
         (h.floats.count("brdf.interp-error") ? " (brdf.interp-error " + fmtG(h.floats.at("brdf.interp-error")) + ")" : "") +
         " and, on the hardware path, the filter's (8-bit weights: up to ~1/512 of a texel step)\n";
  if (table == "brdf3d") return s + lookups3d(L, P, path, h);
  if (table == "dielectric") return s + lookupsDielectric(L, P, path, h);
  if (table == "ashikhmin-shirley")
    throw Error(kExitDataErr, path + ": the Ashikhmin-Shirley textures come with their own shader "
                                     "(shaders/ashikhmin_shirley.glsl)");
  std::vector<Axis> ax = axesOf(path, h);
  bool node = attr(h, "brdf.grid") == "node";
  if (!node)
    s += "// texel-center grid: within half a texel of an edge both paths return the edge texels (clamp)\n";
  return s + lookups2d(L, P, h, ax, node) + semantics2d(L, P, h, h.height == 1);
}

std::string shaderForFiles(const std::vector<std::string>& paths, ShaderLang lang) {
  std::string s = lang == ShaderLang::Glsl
                      ? "// Generated by brdfbake shader --lang glsl (GLSL ES 3.00, 3.30 and later)\n"
                      : "// Generated by brdfbake shader --lang hlsl (shader model 4 and later)\n";
  std::map<std::string, std::map<std::string, std::string>> byPair;  // ndf+gaf -> table -> prefix
  for (const auto& p : paths) {
    std::string from;
    TableImage h = tableMetadata(p, &from);  // any format the baker writes (a DDS's from the file beside it)
    s += "\n";
    if (!from.empty()) s += "// (" + p + " holds no metadata: the table's is read from " + from + ")\n";
    s += shaderForTable(p, h, lang);
    std::string table = attr(h, "brdf.table"), channels = attr(h, "brdf.channels");
    bool plain = attr(h, "brdf.fresnel", "one") == "one" || table == "splitsum";
    if (plain && channels.rfind("R,G,B", 0) != 0)
      byPair[attr(h, "brdf.ndf") + "+" + attr(h, "brdf.gaf")][table] = shaderPrefix(p);
  }
  for (const auto& [pair, tables] : byPair) {
    if (!tables.count("albedo") || !tables.count("albedo-avg") || !tables.count("splitsum")) continue;
    bool hlsl = lang == ShaderLang::Hlsl;
    auto decl = [&](const std::string& prefix) {
      return hlsl ? "Texture2D<float4> " + prefix + "_tex;\nSamplerState " + prefix + "_smp;\n"
                  : "uniform sampler2D " + prefix + "_tex;\n";
    };
    auto args = [&](const std::string& prefix) { return hlsl ? prefix + "_tex, " + prefix + "_smp" : prefix + "_tex"; };
    const std::string &e = tables.at("albedo"), &avg = tables.at("albedo-avg"), &ab = tables.at("splitsum");
    s += "\n// ---- " + pair + ": the lookups shaders/multiscatter.glsl calls (bind the three tables)\n";
    s += decl(e) + decl(avg) + decl(ab);
    s += "float lookupE(float mu, float r) { return " + e + "_E(" + args(e) + ", mu, r); }\n";
    s += "float lookupEavg(float r) { return " + avg + "_Eavg(" + args(avg) + ", r); }\n";
    s += std::string(hlsl ? "float2" : "vec2") + " lookupAB(float mu, float r) { return " + ab + "_AB(" + args(ab) +
         ", mu, r); }\n";
  }
  return s;
}

}  // namespace brdfbake
