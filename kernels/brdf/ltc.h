/* ltc.h: linearly transformed cosines (Heitz, Dupuy, Hill and Neubelt 2016, "Real-Time Polygonal-Light
 * Shading with Linearly Transformed Cosines"), the distribution area-light shading integrates.
 *
 * A clamped cosine D_o(w_o) = max(0, z_o)/pi, transformed by a 3x3 matrix M: w = M w_o/|M w_o|. Its
 * density (paper eq. 1, the Jacobian of w_o = M^-1 w/|M^-1 w|):
 *   D(w) = D_o(M^-1 w/|M^-1 w|) |det M^-1| / |M^-1 w|^3.
 * It integrates to 1 over the sphere for every invertible M, and puts mass below the horizon when M
 * tilts the cosine's hemisphere across it.
 *
 * Isotropic lobes lie in the plane of the normal (z) and the view (x, with y = 0 for the view): M
 * keeps y apart. The shape used here and by the 2016 fit (its fitLTC.cpp parameterisation, as
 * published):
 *   M = R_y(phi) [[m11, 0, m13], [0, m22, 0], [0, 0, 1]],  R_y(phi) turning z to (sin phi, 0, cos phi),
 * held as (log m11, log m22, m13, phi): every value is an invertible M (det = m11 m22 > 0), and
 * scaling M does not change D, so four numbers are all of an isotropic LTC. Engines store M^-1
 * divided by its (1,1) entry (= 1/m22): ltc_store.
 */
/* Once per pass (compat.h "Passes"). */
#if defined(BRDF_SECOND_PASS) ? !defined(BRDF_LTC_H_2) : !defined(BRDF_LTC_H)
#ifdef BRDF_SECOND_PASS
#define BRDF_LTC_H_2
#else
#define BRDF_LTC_H
#endif
#include "brdf/compat.h"
#ifndef BRDF_LANE_PASS

/* An LTC ready to evaluate and sample: M and M^-1 row by row, |det M^-1|. */
typedef struct Ltc {
  real m[9];
  real inv[9];
  real det_inv;
} Ltc;

/* The LTC of parameters (log m11, log m22, m13, phi). */
BRDF_FN Ltc ltc_from_params(real lm11, real lm22, real m13, real phi) {
  real m11 = exp(lm11), m22 = exp(lm22), c = cos(phi), s = sin(phi);
  Ltc l;
  /* M = R_y(phi) U, U = [[m11, 0, m13], [0, m22, 0], [0, 0, 1]], R_y = [[c, 0, s], [0, 1, 0], [-s, 0, c]] */
  l.m[0] = c * m11;
  l.m[1] = RC(0.0);
  l.m[2] = c * m13 + s;
  l.m[3] = RC(0.0);
  l.m[4] = m22;
  l.m[5] = RC(0.0);
  l.m[6] = -s * m11;
  l.m[7] = RC(0.0);
  l.m[8] = -s * m13 + c;
  /* M^-1 = U^-1 R_y(-phi), U^-1 = [[1/m11, 0, -m13/m11], [0, 1/m22, 0], [0, 0, 1]] */
  real a = RC(1.0) / m11, b = -m13 / m11;
  l.inv[0] = a * c + b * s;
  l.inv[1] = RC(0.0);
  l.inv[2] = -a * s + b * c;
  l.inv[3] = RC(0.0);
  l.inv[4] = RC(1.0) / m22;
  l.inv[5] = RC(0.0);
  l.inv[6] = s;
  l.inv[7] = RC(0.0);
  l.inv[8] = c;
  l.det_inv = RC(1.0) / (m11 * m22);
  return l;
}

/* D(w) of the LTC (paper eq. 1) at a unit direction (x, y, z). */
BRDF_FN real ltc_D(Ltc l, real x, real y, real z) {
  real ox = l.inv[0] * x + l.inv[1] * y + l.inv[2] * z;
  real oy = l.inv[3] * x + l.inv[4] * y + l.inv[5] * z;
  real oz = l.inv[6] * x + l.inv[7] * y + l.inv[8] * z;
  real len2 = ox * ox + oy * oy + oz * oz;
  if (oz <= RC(0.0) || len2 <= RC(0.0)) return RC(0.0);
  real len = sqrt(len2);
  return (oz / len) * BRDF_INV_PI * l.det_inv / (len2 * len);
}

/* A clamped-cosine direction (density z/pi) from (u1, u2) in [0, 1)^2 (Malley's method: a uniform
 * point of the unit disk lifted to the hemisphere); out[0..2]. */
BRDF_FN void ltc_sample_cosine(real u1, real u2, real* out) {
  real rad = sqrt(u1), ph = RC(2.0) * BRDF_PI * u2;
  out[0] = rad * cos(ph);
  out[1] = rad * sin(ph);
  out[2] = sqrt(fmax(RC(1.0) - u1, RC(0.0)));
}

/* A direction distributed as D from (u1, u2): a cosine-distributed w_o, then w = M w_o/|M w_o|. */
BRDF_FN void ltc_sample(Ltc l, real u1, real u2, real* out) {
  real o[3];
  ltc_sample_cosine(u1, u2, o);
  real ox = o[0], oy = o[1], oz = o[2];
  real x = l.m[0] * ox + l.m[1] * oy + l.m[2] * oz;
  real y = l.m[3] * ox + l.m[4] * oy + l.m[5] * oz;
  real z = l.m[6] * ox + l.m[7] * oy + l.m[8] * oz;
  real len = sqrt(x * x + y * y + z * z);
  out[0] = x / len;
  out[1] = y / len;
  out[2] = z / len;
}

/* The four entries engines store (three.js's LTC_MAT_1, the 2016 fit's ltc_1, Blender's ltc_mat):
 * M^-1 divided by its (1,1) entry, in the order (inv00, inv20, inv02, inv22) that a shader rebuilds as
 * mat3(vec3(s0, 0, s1), vec3(0, 1, 0), vec3(s2, 0, s3)) (GLSL columns). */
BRDF_FN void ltc_store(Ltc l, real* s) {
  real k = RC(1.0) / l.inv[4];
  s[0] = l.inv[0] * k;
  s[1] = l.inv[6] * k;
  s[2] = l.inv[2] * k;
  s[3] = l.inv[8] * k;
}

/* The LTC of stored entries (ltc_store's order): M^-1 = [[s0, 0, s2], [0, 1, 0], [s1, 0, s3]], and M its
 * inverse, 1/det [[s3, 0, -s2], [0, det, 0], [-s1, 0, s0]] with det = s0 s3 - s1 s2 (D uses |det|). */
BRDF_FN Ltc ltc_from_stored(real s0, real s1, real s2, real s3) {
  Ltc l;
  real det = s0 * s3 - s1 * s2;
  real id = det != RC(0.0) ? RC(1.0) / det : RC(0.0);
  l.inv[0] = s0;
  l.inv[1] = RC(0.0);
  l.inv[2] = s2;
  l.inv[3] = RC(0.0);
  l.inv[4] = RC(1.0);
  l.inv[5] = RC(0.0);
  l.inv[6] = s1;
  l.inv[7] = RC(0.0);
  l.inv[8] = s3;
  l.m[0] = s3 * id;
  l.m[1] = RC(0.0);
  l.m[2] = -s2 * id;
  l.m[3] = RC(0.0);
  l.m[4] = RC(1.0);
  l.m[5] = RC(0.0);
  l.m[6] = -s1 * id;
  l.m[7] = RC(0.0);
  l.m[8] = s0 * id;
  l.det_inv = fabs(det);
  return l;
}

#endif /* !BRDF_LANE_PASS */
#endif /* BRDF_LTC_H */
