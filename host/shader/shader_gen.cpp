#include "shader/shader_gen.h"

#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <set>

#include "common/errors.h"
#include "common/format.h"
#include "formats/readers/table_reader.h"
#include "shader/atlas_lookups.h"
#include "formats/shader_lang.h"
#include "tables/registry.h"

namespace brdfbake {

namespace {

using shadergen::attr;
using shadergen::Lang;
using shadergen::lit;

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
std::string lookups2d(const Lang& L, const std::string& P, const TableImage& h, const std::vector<Axis>& ax,
                      bool node) {
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
      s += "// " + std::string(a ? "y" : "x") +
           " is spaced in sqrt(mu) (brdf.mu.index sqrt): texel i holds mu = u_i^2\n";
  const std::string flip = attr(h, "brdf.layout.flip", "none");
  const bool fx = flip.find('x') != std::string::npos, fy = flip.find('y') != std::string::npos;
  s += L.f2() + " " + P + "_t(" + args + ") {\n  " + L.f2() + " t = clamp(" + L.f2() + "(" + frac(ax[0], "x") + ", " +
       yExpr + "), 0.0, 1.0);\n";
  if (fx) s += "  t.x = 1.0 - t.x;  // texel 0 holds the high end of x (brdf.layout.flip)\n";
  if (fy) s += "  t.y = 1.0 - t.y;  // texel 0 holds the high end of y (brdf.layout.flip)\n";
  s += "  return t;\n}\n";
  s += "// texture coordinate for the hardware filter (" +
       std::string(node ? "node grid: texel i holds i/(n-1)" : "texel-center grid: texel i holds (i+0.5)/n") + ")\n";
  s += L.f2() + " " + P + "_uv(" + args + ") {\n";
  if (node)
    s += "  return (0.5 + " + P + "_t(" + (oneD ? "x" : "x, y") + ") * (" + P + "_SIZE - 1.0)) / " + P + "_SIZE;\n";
  else
    s += "  return " + P + "_t(" + (oneD ? "x" : "x, y") + ");\n";
  s += "}\n";
  s += L.f4() + " " + P + "_lookup(" + L.texParam() + ", " + args + ") {\n  return " +
       mapped(L, h, L.sample(P + "_uv(" + (oneD ? "x" : "x, y") + ")")) + ";\n}\n";
  s += "// exact filtering: the four texels and the weights in float (hardware weights may have 8 bits)\n";
  s += L.f4() + " " + P + "_lookupExact(" + L.texParam() + ", " + args + ") {\n";
  s += "  " + L.f2() + " p = " + P + "_t(" + (oneD ? "x" : "x, y") + ") * " +
       (node ? "(" + P + "_SIZE - 1.0)" : P + "_SIZE - 0.5") + ";\n";
  s += "  p = clamp(p, " + L.f2() + "(0.0, 0.0), " + P + "_SIZE - 1.0);\n";
  s += "  " + L.f2() + " i0 = floor(p);\n  " + L.f2() + " f = p - i0;\n";
  s += "  " + L.i2() + " a = " + L.i2() + "(i0);\n  " + L.i2() + " b = min(a + 1, " + L.i2() + "(" + P +
       "_SIZE) - 1);\n";
  s += "  " + L.f4() + " v00 = " + L.fetch("a") + ";\n";
  s += "  " + L.f4() + " v10 = " + L.fetch(L.i2() + "(b.x, a.y)") + ";\n";
  s += "  " + L.f4() + " v01 = " + L.fetch(L.i2() + "(a.x, b.y)") + ";\n";
  s += "  " + L.f4() + " v11 = " + L.fetch("b") + ";\n";
  s += "  return " + mapped(L, h, L.mix() + "(" + L.mix() + "(v00, v10, f.x), " + L.mix() + "(v01, v11, f.x), f.y)") +
       ";\n}\n";
  return s;
}

// The quantities of each table kind, on both paths.
std::string semantics2d(const Lang& L, const std::string& P, const TableImage& h, const KindInfo& kind, bool oneD) {
  const std::string channels = attr(h, "brdf.channels");
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
  const std::string exA = !sA.empty() ? sA : "(" + sAB + " - " + sB + ")",
                    exB = !sB.empty() ? sB : "(" + sAB + " - " + sA + ")";
  const bool plainLayout = stored == "A,B,A+B";
  std::string s;
  for (std::string variant : {"", "Exact"}) {
    std::string get = P + "_lookup" + variant + "(" + L.texArgs() + ", " + call + ")";
    auto fn = [&](const std::string& type, const std::string& name, const std::string& extra, const std::string& body) {
      s += type + " " + P + "_" + name + variant + "(" + L.texParam() + (extra.empty() ? "" : ", " + extra) + ", " +
           args + ") {\n" + body + "}\n";
    };
    if (kind.shader == ShaderLookup::SplitSum) {
      fn(L.f2(), "AB", "", "  " + L.f4() + " v = " + get + ";\n  return " + L.f2() + "(" + exA + ", " + exB + ");\n");
      fn(L.f3(), "Schlick", L.f3() + " f0",
         "  " + L.f4() + " v = " + get + ";\n  return f0 * " + exA + " + " + exB + ";\n");
      if (!plainLayout) {
        // a layout's channels hold A, B and A + B only
      } else if (attr(h, "brdf.fresnel") == "f82-tint")
        fn(L.f3(), "F82Tint", L.f3() + " f0, " + L.f3() + " b",
           "  " + L.f4() + " v = " + get + ";\n  return f0 * v.r + v.g - b * v.b;\n");
      else if (channels.find("E_d") != std::string::npos)
        fn("float", "DiffuseAlbedo", "", "  return " + get + ".b;\n");
    } else if (kind.shader == ShaderLookup::Value) {
      const std::string& name = kind.shaderValue;
      if (rgb)
        fn(L.f3(), name, "", "  return " + get + ".rgb;\n");
      else
        fn("float", name, "", "  return " + get + ".r;\n");
    } else if (kind.shader == ShaderLookup::Family) {
      s += kind.shaderCode.accessors(L, P, h, variant);
    } else if (kind.shader == ShaderLookup::EtaAverages) {
      // (r, s) stored; the eta a material has, mapped as the table's eta axis is
      s += "// E_R,avg, E_T,avg and their sum at (r, eta), eta by s = (eta - 1)/(eta + 1)\n";
      s += L.f3() + " " + P + "_albedosAvg" + variant + "(" + L.texParam() + ", float r, float eta) {\n  return " + P +
           "_lookup" + variant + "(" + L.texArgs() + ", r, (eta - 1.0) / (eta + 1.0)).rgb;\n}\n";
    }
  }
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
  const KindInfo* kind = findKind(table);
  if (!kind) throw Error(kExitDataErr, path + ": brdf.table '" + table + "' is no table kind brdfbake writes");
  std::string s = "// ---- " + path + ": " + table;
  if (!attr(h, "brdf.ndf").empty()) s += ", " + attr(h, "brdf.ndf") + " + " + attr(h, "brdf.gaf");
  s += "\n// axes " + attr(h, "brdf.axes") + ", " + attr(h, "brdf.grid") + " grid, " +
       (attr(h, "brdf.mu.index").rfind("sqrt", 0) == 0 ? "mu index sqrt, " : "") + "channels " +
       attr(h, "brdf.channels") + "\n";
  auto err = h.floats.find("brdf.error");
  if (err != h.floats.end())
    s += "// error budget (relative to max(1, |value|)): table " + fmtG(err->second) +
         " (integration, float arithmetic, storage); add the interpolation error of the resolution" +
         (h.floats.count("brdf.interp-error") ? " (brdf.interp-error " + fmtG(h.floats.at("brdf.interp-error")) + ")"
                                              : "") +
         " and, on the hardware path, the filter's (8-bit weights: up to ~1/512 of a texel step)\n";
  if (kind->shader == ShaderLookup::Volume) return s + shadergen::lookups3d(L, P, path, h);
  if (kind->shader == ShaderLookup::EtaVolume) return s + shadergen::lookupsDielectric(L, P, path, h);
  if (kind->shader == ShaderLookup::OwnShader)
    throw Error(kExitDataErr, path +
                                  ": the Ashikhmin-Shirley textures come with their own shader "
                                  "(shaders/ashikhmin_shirley.glsl)");
  std::vector<Axis> ax = axesOf(path, h);
  bool node = attr(h, "brdf.grid") == "node";
  if (!node) s += "// texel-center grid: within half a texel of an edge both paths return the edge texels (clamp)\n";
  return s + lookups2d(L, P, h, ax, node) + semantics2d(L, P, h, *kind, h.height == 1);
}

std::string shaderForFiles(const std::vector<std::string>& paths, ShaderLang lang) {
  std::string s = lang == ShaderLang::Glsl
                      ? "// Generated by brdfbake shader --lang glsl (GLSL ES 3.00, 3.30 and later)\n"
                      : "// Generated by brdfbake shader --lang hlsl (shader model 4 and later)\n";
  // ndf+gaf -> accessor ("E", "Eavg", "AB") -> prefix: the lookups shaders/multiscatter.glsl calls
  std::set<TableKind> seen;  // the files' kinds, for what a kind writes once
  std::map<std::string, std::map<std::string, std::string>> byPair;
  for (const auto& p : paths) {
    std::string from;
    TableImage h = tableMetadata(p, &from);  // any format the baker writes (a DDS's from the file beside it)
    s += "\n";
    if (!from.empty()) s += "// (" + p + " holds no metadata: the table's is read from " + from + ")\n";
    s += shaderForTable(p, h, lang);
    const KindInfo& kind = *findKind(attr(h, "brdf.table"));  // shaderForTable refused the others
    seen.insert(kind.kind);
    const std::string accessor = kind.shader == ShaderLookup::SplitSum ? "AB" : kind.shaderValue;
    bool plain = attr(h, "brdf.fresnel", "one") == "one" || kind.shader == ShaderLookup::SplitSum;
    if (plain && attr(h, "brdf.channels").rfind("R,G,B", 0) != 0)
      byPair[attr(h, "brdf.ndf") + "+" + attr(h, "brdf.gaf")][accessor] = shaderPrefix(p);
  }
  Lang L{lang == ShaderLang::Hlsl};
  // what the kinds among the files write once (the LTC's polygon integral), in the kinds' order
  for (const KindInfo& kind : allKinds())
    if (kind.shaderCode.once && seen.count(kind.kind)) s += "\n" + kind.shaderCode.once(L);
  for (const auto& [pair, tables] : byPair) {
    if (!tables.count("E") || !tables.count("Eavg") || !tables.count("AB")) continue;
    bool hlsl = lang == ShaderLang::Hlsl;
    auto decl = [&](const std::string& prefix) {
      return hlsl ? "Texture2D<float4> " + prefix + "_tex;\nSamplerState " + prefix + "_smp;\n"
                  : "uniform sampler2D " + prefix + "_tex;\n";
    };
    auto args = [&](const std::string& prefix) { return hlsl ? prefix + "_tex, " + prefix + "_smp" : prefix + "_tex"; };
    const std::string &e = tables.at("E"), &avg = tables.at("Eavg"), &ab = tables.at("AB");
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
