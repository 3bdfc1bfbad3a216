// Atlas lookups (shader/atlas_lookups.h).
#include "shader/atlas_lookups.h"

#include <array>
#include <cstdio>

#include "common/errors.h"
#include "common/format.h"

namespace brdfbake::shadergen {

namespace {

// An atlas table's size (brdf.size NXxNYxNZ) and tile grid (brdf.atlas COLSxROWS).
struct AtlasShape {
  int nx = 0, ny = 0, nz = 0, cols = 0, rows = 0;
};
AtlasShape atlasShape(const std::string& path, const TableImage& h) {
  AtlasShape a;
  if (std::sscanf(attr(h, "brdf.size").c_str(), "%dx%dx%d", &a.nx, &a.ny, &a.nz) != 3 ||
      std::sscanf(attr(h, "brdf.atlas").c_str(), "%dx%d", &a.cols, &a.rows) != 2)
    throw Error(kExitDataErr,
                path + ": brdf.size / brdf.atlas missing: not a " + attr(h, "brdf.table") + " table brdfbake wrote");
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
  s += "  " + L.f2() + " q = clamp(p, " + L.f2() + "(0.0, 0.0), " + P + "_SIZE.xy - 1.0) + tile * " + P +
       "_SIZE.xy + 0.5;\n";
  s += "  return " + L.sample("q / (" + P + "_ATLAS * " + P + "_SIZE.xy)") + ";\n}\n";
  s += L.f4() + " " + P + "_lookup(" + L.texParam() + ", " + args + ") {\n";
  s += "  " + L.f3() + " p = clamp(" + P + "_index(" + call + "), " + L.f3() + "(0.0, 0.0, 0.0), " + P +
       "_SIZE - 1.0);\n";
  s += "  float z0 = floor(p.z);\n  float z1 = min(z0 + 1.0, " + P + "_SIZE.z - 1.0);\n";
  s += "  return " + L.mix() + "(" + P + "_slice(" + L.texArgs() + ", p.xy, z0), " + P + "_slice(" + L.texArgs() +
       ", p.xy, z1), p.z - z0);\n}\n";
  s += L.f4() + " " + P + "_texel(" + L.texParam() + ", " + L.i2() + " xy, float z) {\n";
  s += "  " + L.i2() + " tile = " + L.i2() + "(int(z) % int(" + P + "_ATLAS.x), int(z) / int(" + P + "_ATLAS.x));\n";
  s += "  return " + L.fetch("xy + tile * " + L.i2() + "(" + P + "_SIZE.xy)") + ";\n}\n";
  s += L.f4() + " " + P + "_lookupExact(" + L.texParam() + ", " + args + ") {\n";
  s += "  " + L.f3() + " p = clamp(" + P + "_index(" + call + "), " + L.f3() + "(0.0, 0.0, 0.0), " + P +
       "_SIZE - 1.0);\n";
  s += "  " + L.f3() + " i0 = floor(p);\n  " + L.f3() + " f = p - i0;\n";
  s += "  " + L.i2() + " a0 = " + L.i2() + "(i0.xy);\n  " + L.i2() + " a1 = min(a0 + 1, " + L.i2() + "(" + P +
       "_SIZE.xy) - 1);\n";
  s += "  float z1 = min(i0.z + 1.0, " + P + "_SIZE.z - 1.0);\n";
  s += "  " + L.f4() + " r0 = " + L.mix() + "(" + L.mix() + "(" + P + "_texel(" + L.texArgs() + ", a0, i0.z), " + P +
       "_texel(" + L.texArgs() + ", " + L.i2() + "(a1.x, a0.y), i0.z), f.x), " + L.mix() + "(" + P + "_texel(" +
       L.texArgs() + ", " + L.i2() + "(a0.x, a1.y), i0.z), " + P + "_texel(" + L.texArgs() +
       ", a1, i0.z), f.x), f.y);\n";
  s += "  " + L.f4() + " r1 = " + L.mix() + "(" + L.mix() + "(" + P + "_texel(" + L.texArgs() + ", a0, z1), " + P +
       "_texel(" + L.texArgs() + ", " + L.i2() + "(a1.x, a0.y), z1), f.x), " + L.mix() + "(" + P + "_texel(" +
       L.texArgs() + ", " + L.i2() + "(a0.x, a1.y), z1), " + P + "_texel(" + L.texArgs() + ", a1, z1), f.x), f.y);\n";
  s += "  return " + L.mix() + "(r0, r1, f.z);\n}\n";
  return s;
}

}  // namespace

// The rough-dielectric cube (tables/dielectric/dielectric.cpp): an atlas of eta slices over (mu, r), the eta
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
  s += L.cst() + " " + L.f3() + " " + P + "_SIZE = " + L.f3() + "(" + lit(a.nx) + ", " + lit(a.ny) + ", " + lit(a.nz) +
       ");\n";
  s += L.cst() + " " + L.f2() + " " + P + "_ATLAS = " + L.f2() + "(" + lit(a.cols) + ", " + lit(a.rows) + ");\n";
  s += "// texel index of (mu, r, eta): the " + attr(h, "brdf.grid") + " grid, eta by s = (eta - 1)/(eta + 1) in [" +
       lit(sr[0]) + ", " + lit(sr[1]) + "] (eta " + fmtG(eta[0]) + " to " + fmtG(eta[1]) +
       "); outside it the edge slice\n";
  s += L.f3() + " " + P + "_index(float mu, float r, float eta) {\n";
  s += "  float s = (eta - 1.0) / (eta + 1.0);\n";
  s += "  " + L.f3() + " t = " + L.f3() + "((mu - " + lit(mu[0]) + ") / " + lit(mu[1] - mu[0]) + ", (r - " + lit(r[0]) +
       ") / " + lit(r[1] - r[0]) + ", (s - " + lit(sr[0]) + ") / " + lit(sr[1] - sr[0]) + ");\n";
  s += gridIndex(P, attr(h, "brdf.grid"));
  s += "}\n";
  s += atlasLookups(L, P, "float mu, float r, float eta", "mu, r, eta");
  s += "// E_R (reflected albedo), E_T (transmitted: the fraction of energy that crosses), E_R + E_T\n";
  for (std::string variant : {"", "Exact"})
    s += L.f3() + " " + P + "_albedos" + variant + "(" + L.texParam() + ", float mu, float r, float eta) {\n  return " +
         P + "_lookup" + variant + "(" + L.texArgs() + ", mu, r, eta).rgb;\n}\n";
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
  s += L.cst() + " " + L.f3() + " " + P + "_SIZE = " + L.f3() + "(" + lit(a.nx) + ", " + lit(a.ny) + ", " + lit(a.nz) +
       ");\n";
  s += L.cst() + " " + L.f2() + " " + P + "_ATLAS = " + L.f2() + "(" + lit(a.cols) + ", " + lit(a.rows) + ");\n";
  s += "// texel index of each angle (radians): the " + grid + " grid" + (sq ? ", theta_h by MERL's sqrt index" : "") +
       "\n";
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
    s += "  if (dot(b, b) < 1e-12) b = cross(n, abs(n.x) < 0.9 ? " + L.f3() + "(1.0, 0.0, 0.0) : " + L.f3() +
         "(0.0, 1.0, 0.0));\n";
    s += "  b = normalize(b);\n  " + L.f3() + " t = cross(b, h);\n";
    s += "  float phi = atan2(dot(l, b), dot(l, t));\n";
    if (!L.hlsl) s.replace(s.rfind("atan2("), 6, "atan(");
    s += "  if (phi < 0.0) phi += 3.14159265;  // f(phi_d) = f(phi_d + pi): reciprocity\n";
    s += "  return " + L.f3() + "(acos(clamp(dot(n, h), -1.0, 1.0)), acos(clamp(dot(h, l), -1.0, 1.0)), phi);\n";
  }
  s += "}\n";
  return s;
}

}  // namespace brdfbake::shadergen
