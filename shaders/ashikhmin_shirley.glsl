// The anisotropic Ashikhmin-Shirley BRDF (Ashikhmin and Shirley 2000, "An anisotropic Phong BRDF
// model", J. Graphics Tools 5(2)) recombined from brdfbake's three factorised textures
// (`brdfbake bake --table ashikhmin-shirley`: as_tex0.exr, as_tex1.exr, as_tex2.exr; seed 001's
// factorisation). docs/MODELS.md "Ashikhmin-Shirley: factorised textures" has the formulas;
// tests/ashikhmin_test.cpp measures this file against the direct formula.
//
// One source for GLSL and C++ (like multiscatter.glsl): the common subset of GLSL (ES 3.00 / 3.30
// and later) and C++17 with GLM (`using namespace glm;`); scalar expressions meet vectors only
// through float variables. The including code provides the lookups: bilinear, clamp-to-edge
// texture() calls, each with its file's grid (brdf.grid; n = the texture's size):
//   float asTex0(float nl, float nv);  node:       texture(tex0, (0.5 + (n-1) vec2(n.l, n.v))/n).r
//   vec2  asTex1(float hl, float m);   upper-node: texture(tex1, vec2(h.l, m) - 0.5/n).rg, m = max(n.l, n.v)
//   float asTex2(float nh, float t);   node:       texture(tex2, (0.5 + (n-1) vec2(n.h, t))/n).r
float asTex0(float nl, float nv);
vec2 asTex1(float hl, float m);
float asTex2(float nh, float t);

const float AS_PI = 3.14159265358979;
// Tex2's value mapping (the file's brdf.scale and brdf.offset): t = sqrt(n_u) h.x/scale + offset.
const float AS_SCALE = 10.0;
const float AS_OFFSET = 0.5;
const float AS_ZERO = 0.0;

// The specular term rho_s (without n.l). n, x, y: normal, tangent (the nu direction) and
// bitangent, orthonormal; l, v: unit light and view directions above the surface; nu, nv: the
// Phong exponents along x and y; rs: the specular reflectance R_s (Schlick's F0).
//   rho_s = sqrt((nu+1)(nv+1))/(8 pi) Tex1(h.l, max(n.l, n.v)) Tex2(n.h, sqrt(nu) h.x) Tex2(n.h, sqrt(nv) h.y)
float ashikhminSpecular(vec3 n, vec3 x, vec3 y, vec3 l, vec3 v, float nu, float nv, float rs) {
  vec3 h = normalize(l + v);
  float nh = dot(n, h);
  vec2 t1 = asTex1(dot(h, l), max(dot(n, l), dot(n, v)));
  float fresnelVis = rs * t1.x + t1.y;  // F(h.l)/((h.l) max(n.l, n.v)), Schlick's F split by R_s
  float tu = sqrt(nu) * dot(h, x) / AS_SCALE + AS_OFFSET;
  float tv = sqrt(nv) * dot(h, y) / AS_SCALE + AS_OFFSET;
  float lobe = asTex2(nh, tu) * asTex2(nh, tv);  // (n.h)^(nu cos^2 phi_h + nv sin^2 phi_h)
  float nu1 = nu + 1.0;
  float nv1 = nv + 1.0;
  float norm = sqrt(nu1 * nv1) / (8.0 * AS_PI);
  return norm * lobe * fresnelVis;
}

// The diffuse term rho_d for albedo 1 (times R_d, without n.l):
//   rho_d = 28/(23 pi) (1 - R_s) Tex0(n.l, n.v)
float ashikhminDiffuse(float nl, float nv, float rs) {
  float k = 28.0 / (23.0 * AS_PI);
  return k * (1.0 - rs) * asTex0(nl, nv);
}

// The whole BRDF times n.l, as a light's contribution: (R_d rho_d + rho_s) n.l.
vec3 ashikhminShirley(vec3 n, vec3 x, vec3 y, vec3 l, vec3 v, float nu, float nv, float rs, vec3 rd) {
  float nl = max(dot(n, l), AS_ZERO);
  float nvw = max(dot(n, v), AS_ZERO);
  float d = ashikhminDiffuse(nl, nvw, rs) * nl;
  float s = ashikhminSpecular(n, x, y, l, v, nu, nv, rs) * nl;
  return rd * d + vec3(s);
}
