// Multiple-scattering energy compensation for a microfacet specular lobe, from brdfbake's tables.
// docs/multiple-scattering.md has the formulas, their sources, how to bind the tables, and what
// tests/multiscatter_test.cpp measured.
//
// One source for GLSL and C++: this file is written in the common subset of GLSL (ES 3.00 /
// 3.30 and later) and C++17 with GLM (`using namespace glm;`): float/vec2/vec3, max, mix, no
// suffixed or double literals in vector expressions (scalar expressions are assigned to float
// variables before they meet a vector), no `out` parameters, no overloading on the lookups.
// GLSL: paste it (or #include it with GL_ARB_shading_language_include / your preprocessor) after
// the lookups below are defined. C++: #include it with glm in scope (host/materials/multiscatter.cpp).
//
// The including code provides the table lookups (names fixed, bodies its own):
//   float lookupE(float mu, float r);     brdfbake `albedo` table, E(mu, r) at F = 1: texture(.., vec2(mu, r)).r
//   float lookupEavg(float r);            brdfbake `albedo-avg` table, E_avg(r): texture(.., vec2(r, 0.5)).r
//   vec2  lookupAB(float mu, float r);    brdfbake `splitsum` table, (A, B): texture(.., vec2(mu, r)).rg
// mu = n.v (or n.l), r = perceptual roughness (alpha = r^2), as the tables are indexed. With the
// default texel-centre tables a plain bilinear, clamp-to-edge texture() call is the exact lookup.
float lookupE(float mu, float r);
float lookupEavg(float r);
vec2 lookupAB(float mu, float r);

const float MS_PI = 3.14159265358979;
// Floor on the denominators. 1 - E_avg -> 0 as r -> 0 (and 1 - E(mu) with it): the lobe is then
// 0 * 0 / floor = 0, never 0/0. 1e-6 is ~16 float ulps of 1: below it 1 - E_avg is rounding.
const float MS_FLOOR = 1e-6;
const float MS_ZERO = 0.0;

// Schlick's Fresnel averaged over the hemisphere, F_avg = 2 int_0^1 F(mu) mu dmu
// = F0 + (1 - F0)/21 = (20 F0 + 1)/21 (Kulla and Conty 2017; Fdez-Aguera 2019).
vec3 msFavgSchlick(vec3 f0) {
  float w = 1.0 / 21.0;
  return mix(f0, vec3(1.0), w);
}

// ---- Kulla and Conty 2017 ------------------------------------------------------------------
// The F = 1 compensation lobe f_ms(o, i) = (1 - E(mu_o)) (1 - E(mu_i)) / (pi (1 - E_avg)):
// its directional albedo is 1 - E(mu_o), so E + its albedo = 1. Add it to the single-scattering
// BRDF like any lobe (times n.l for a light). 1 - E is floored at 0: tables above 1 (blinn-phong
// and gaussian with smith, see docs/MODELS.md) get no compensation rather than a negative one.
float kullaContyLobe(float muO, float muI, float r) {
  float eo = 1.0 - lookupE(muO, r);
  float ei = 1.0 - lookupE(muI, r);
  float lost = 1.0 - lookupEavg(r);
  return max(eo, MS_ZERO) * max(ei, MS_ZERO) / (MS_PI * max(lost, MS_FLOOR));
}

// The Fresnel factor of the compensation lobe: the energy of the bounces after the first, each
// scaled by F_avg: the lobe is multiplied by F_avg^2 E_avg / (1 - F_avg (1 - E_avg)) (Kulla and
// Conty 2017, the Fresnel term of their multiple-scattering lobe; it is 1 at F_avg = 1).
vec3 kullaContyFresnel(vec3 fAvg, float r) {
  float eAvg = lookupEavg(r);
  float lost = 1.0 - eAvg;
  vec3 den = max(vec3(1.0) - fAvg * lost, vec3(MS_FLOOR));
  return fAvg * fAvg * eAvg / den;
}

// The coloured compensation lobe for Schlick's Fresnel with reflectance f0.
vec3 kullaContyLobeF(float muO, float muI, float r, vec3 f0) {
  return kullaContyLobe(muO, muI, r) * kullaContyFresnel(msFavgSchlick(f0), r);
}

// ---- Fdez-Aguera 2019 (the single-table form Filament and three.js use) ----------------------
// From the split-sum pair alone: E_ss = A + B, FssEss = F0 A + B,
// F_ms = FssEss F_avg / (1 - (1 - E_ss) F_avg), E_ms = 1 - E_ss;
// the specular energy is FssEss (times prefiltered radiance) + F_ms E_ms (times irradiance).
// (Fdez-Aguera 2019, with Schlick's F90 = 1: the paper's roughness-dependent F_r variant is not
// used, the splitsum table being baked with F90 = 1.)
vec3 fdezAgueraSingle(float mu, float r, vec3 f0) {
  vec2 ab = lookupAB(mu, r);
  return f0 * ab.x + vec3(ab.y);
}

vec3 fdezAgueraMultiple(float mu, float r, vec3 f0) {
  vec2 ab = lookupAB(mu, r);
  vec3 fssEss = f0 * ab.x + vec3(ab.y);
  float ems = 1.0 - (ab.x + ab.y);
  ems = max(ems, MS_ZERO);
  vec3 fAvg = msFavgSchlick(f0);
  vec3 den = max(vec3(1.0) - fAvg * ems, vec3(MS_FLOOR));
  vec3 fms = fssEss * fAvg / den;
  return fms * ems;
}

// ---- Filament (Romain Guy and Mathias Agopian, "Physically Based Rendering in Filament",
// section "Energy loss in specular reflectance"): scale the single-scattering lobe by
// 1 + F0 (1/E_ss - 1), E_ss = A + B (Filament's dfg.y). Multiply f_ss (and the IBL specular) by it.
vec3 filamentEnergyCompensation(float mu, float r, vec3 f0) {
  vec2 ab = lookupAB(mu, r);
  float ess = ab.x + ab.y;
  float k = 1.0 / max(ess, MS_FLOOR) - 1.0;
  return vec3(1.0) + f0 * k;
}
