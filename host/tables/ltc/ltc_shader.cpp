// The LTC tables' accessors and polygon integral (tables/ltc/ltc_shader.h): the grid's lookups
// (P_lookup, P_lookupExact) come from the generator; these read the LTC's quantities through them.
#include "tables/ltc/ltc_shader.h"

namespace brdfbake {

namespace {

using shadergen::attr;
using shadergen::Lang;

// ltc1 (ltc.file "matrix"): M^-1's four entries; ltc2: the magnitude, and Schlick's form of it.
// x = r, y = sqrt(1 - mu) (docs/ltc.md); mu clamped to [0, 1] first.
std::string accessors(const Lang& L, const std::string& P, const TableImage& h, const std::string& variant) {
  std::string s;
  const std::string at = P + "_lookup" + variant + "(" + L.texArgs() + ", r, sqrt(1.0 - clamp(mu, 0.0, 1.0)))";
  if (attr(h, "ltc.file") == "matrix") {
    s += "// M^-1 / M^-1_11 at (mu, r): entries (0,0), (2,0), (0,2), (2,2), as ltc_polygon() takes them\n";
    s +=
        L.f4() + " " + P + "_invM" + variant + "(" + L.texParam() + ", float mu, float r) {\n  return " + at + ";\n}\n";
  } else {
    s += "// the lobe's magnitude E (F = 1) and Fresnel moment at (mu, r); Schlick's magnitude f0 E + (1 - f0) G\n";
    s += L.f2() + " " + P + "_magnitude" + variant + "(" + L.texParam() + ", float mu, float r) {\n  return " + at +
         ".rg;\n}\n";
    s += L.f3() + " " + P + "_Schlick" + variant + "(" + L.texParam() + ", " + L.f3() +
         " f0, float mu, float r) {\n  " + L.f2() + " m = " + at + ".rg;\n  return f0 * m.x + (1.0 - f0) * m.y;\n}\n";
  }
  return s;
}

// The LTC's integral over a polygon light (Heitz et al. 2016, sec. 3.3 and 4): the vertices in the
// shading frame (T1 toward the view, T2, N), times M^-1, clipped to the cosine's upper hemisphere
// (Sutherland-Hodgman against z = 0: at most one vertex more), then the closed-form integral of the
// clamped cosine over a spherical polygon, sum over edges of acos(a.b) normalize(a x b).z / (2 pi)
// (Lambert's form, Arvo 1995). Two-sided: the magnitude. No matrix types, so GLSL and HLSL read
// the same text.
std::string polygonCode(const Lang& L) {
  const std::string f3 = L.f3(), f4 = L.f4();
  std::string s =
      "// ---- LTC polygon lights (docs/ltc.md): the integral of the LTC over a quad light of radiance 1\n"
      "// invM: the ltc1 table's four entries at (n.v, r); N, V: unit normal and view; P: the shaded point;\n"
      "// q0..q3: the quad's corners in order. Times the ltc2 table's magnitude (E, or f0 E + (1 - f0) G).\n"
      "// Its error, as a fraction of the magnitude, is at most the ltc2 table's distance (B channel).\n";
  s += f3 + " ltc_to_cosine(" + f4 + " invM, " + f3 + " T1, " + f3 + " T2, " + f3 + " N, " + f3 + " d) {\n" + "  " +
       f3 + " l = " + f3 + "(dot(T1, d), dot(T2, d), dot(N, d));\n" + "  return " + f3 +
       "(invM.x * l.x + invM.z * l.z, l.y, invM.y * l.x + invM.w * l.z);\n}\n";
  s += "float ltc_edge(" + f3 + " a, " + f3 +
       " b) {\n"
       "  float x = clamp(dot(a, b), -1.0, 1.0);\n"
       "  float s = sqrt(max(1.0 - x * x, 1e-12));\n"
       "  // acos(x)/sin: 1 as the edge shrinks\n"
       "  float k = s < 1e-4 ? 1.0 : acos(x) / s;\n"
       "  return (a.x * b.y - a.y * b.x) * k;\n}\n";
  s += "float ltc_polygon(" + f4 + " invM, " + f3 + " N, " + f3 + " V, " + f3 + " P, " + f3 + " q0, " + f3 + " q1, " +
       f3 + " q2, " + f3 +
       " q3) {\n"
       "  " +
       f3 +
       " T1 = V - N * dot(V, N);\n"
       "  float t1 = length(T1);\n"
       "  // the view along the normal: any tangent (the lobe is symmetric there)\n"
       "  T1 = t1 > 1e-6 ? T1 / t1 : normalize(abs(N.x) < 0.9 ? cross(N, " +
       f3 + "(1.0, 0.0, 0.0)) : cross(N, " + f3 +
       "(0.0, 1.0, 0.0)));\n"
       "  " +
       f3 +
       " T2 = cross(N, T1);\n"
       "  " +
       f3 +
       " v[4];\n"
       "  v[0] = ltc_to_cosine(invM, T1, T2, N, q0 - P);\n"
       "  v[1] = ltc_to_cosine(invM, T1, T2, N, q1 - P);\n"
       "  v[2] = ltc_to_cosine(invM, T1, T2, N, q2 - P);\n"
       "  v[3] = ltc_to_cosine(invM, T1, T2, N, q3 - P);\n"
       "  " +
       f3 +
       " c[5];\n"
       "  int n = 0;\n"
       "  for (int i = 0; i < 4; ++i) {\n"
       "    " +
       f3 +
       " a = v[i];\n"
       "    " +
       f3 +
       " b = v[(i + 1) % 4];\n"
       "    if (a.z >= 0.0) { c[n] = a; n += 1; }\n"
       "    if ((a.z >= 0.0) != (b.z >= 0.0)) { c[n] = a + (b - a) * (a.z / (a.z - b.z)); c[n].z = 0.0; n += 1; }\n"
       "  }\n"
       "  if (n < 3) return 0.0;\n"
       "  float sum = 0.0;\n"
       "  for (int i = 0; i < n; ++i) sum += ltc_edge(normalize(c[i]), normalize(c[(i + 1) % n]));\n"
       "  return abs(sum) / (2.0 * 3.14159265358979);\n}\n";
  return s;
}

}  // namespace

ShaderCode ltcShaderCode() { return {accessors, polygonCode}; }

}  // namespace brdfbake
