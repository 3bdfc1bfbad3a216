/* fresnel.h: Fresnel reflectance, MODELS.md "Fresnel". c is the cosine of the angle to the normal
 * of the reflecting facet (o.h for microfacets). */
/* Once per pass (compat.h "Passes"). */
#if defined(BRDF_SECOND_PASS) ? !defined(BRDF_FRESNEL_H_2) : !defined(BRDF_FRESNEL_H)
#ifdef BRDF_SECOND_PASS
#define BRDF_FRESNEL_H_2
#else
#define BRDF_FRESNEL_H
#endif
#include "brdf/ndf.h"
#ifndef BRDF_LANE_PASS
#define FRESNEL_ONE 0
#define FRESNEL_SCHLICK 1
#define FRESNEL_DIELECTRIC 2
#define FRESNEL_SCHLICK_TIR 3
#define FRESNEL_CONDUCTOR 4
#define FRESNEL_F82_TINT 5
#define FRESNEL_COUNT 6
#endif

/* (1 - c)^5, Schlick's weight, with two multiplications instead of pow. */
BRDF_FN real fresnel_schlick_weight(real c) {
  real m = RC(1.0) - c;
  real m2 = m * m;
  return m2 * m2 * m;
}

/* Schlick 1994: F0 + (1 - F0)(1 - c)^5 */
BRDF_FN real fresnel_schlick(param_t f0, real c) { return f0 + (RC(1.0) - f0) * fresnel_schlick_weight(c); }

/* eta^2 - 1 as (eta - 1)(eta + 1) + z. z: what eta's float rounding takes from eta^2 - 1 (0 in
 * double): near eta = 1 the Fresnel term depends on eta only through eta^2 - 1, which float eta
 * holds to 1.7e-5 of its value at eta = 0.9999 and to 6% at 1 - 1e-6. The albedo at eta = 0.9999,
 * ggx + smith-correlated, mu = 1/64, r = 3/64 is 0.2821800; at float(0.9999) it is 0.2823513, the
 * 1.7e-4 that a table without z missed by. The host passes z from the eta it was given, in double
 * (HemiWeight, host/cl/runner.h). */
#ifndef BRDF_LANE_PASS
BRDF_FN param_t fresnel_e2m1(param_t eta, param_t z) { return (eta - RC(1.0)) * (eta + RC(1.0)) + z; }
#endif

/* Exact unpolarised dielectric (Cook and Torrance 1982, with MODELS.md errata):
 * g^2 = eta^2 + c^2 - 1, F = 1/2 (g-c)^2/(g+c)^2 (1 + (c(g+c) - 1)^2/(c(g-c) + 1)^2); F = 1 when g^2 < 0.
 * g^2 as (eta - 1)(eta + 1) + c^2: eta^2 - 1 + c^2 loses c^2 next to 1 near eta = 1 (at eta = 1 and
 * c < 1e-8 in double it gave g = 0, F = 1 instead of 0; the rough dielectric's grazing corner).
 * fresnel_dielectric_g2 takes g^2 from the caller: the integrators form it next to the kink. */
BRDF_FN real fresnel_dielectric_g2(real c, real g2) {
  real g = sqrt(fmax(g2, RC(0.0)));
  real a = (g - c) / fmax(g + c, RC(1e-30)); /* eta = 1 at c = 0: 0, the limit of F = 0 */
  real b = (c * (g + c) - RC(1.0)) / (c * (g - c) + RC(1.0));
  real f = RC(0.5) * a * a * (RC(1.0) + b * b);
  return g2 < RC(0.0) ? RC(1.0) : f;
}
BRDF_FN real fresnel_dielectric_z(param_t eta, param_t z, real c) {
  c = fabs(c);
  return fresnel_dielectric_g2(c, fresnel_e2m1(eta, z) + c * c);
}
BRDF_FN real fresnel_dielectric(param_t eta, real c) { return fresnel_dielectric_z(eta, RC(0.0), c); }

/* Schlick on the transmitted angle where eta < 1 (Burley 2015, MODELS.md errata):
 * cos^2 t = 1 - (1 - c^2)/eta^2 = (c^2 + eta^2 - 1)/eta^2 (the second form: no cancellation near
 * the critical angle); F = 1 when that is negative. F0 = ((eta-1)/(eta+1))^2. z: fresnel_e2m1. */
BRDF_FN real fresnel_schlick_tir_g2(param_t eta, param_t z, real c, real g2) {
  param_t f0 = (eta - RC(1.0)) / (eta + RC(1.0));
  f0 *= f0;
  param_t d = fresnel_e2m1(eta, z);
  real ct2 = g2 / (eta * eta);
  real f = fresnel_schlick(f0, d >= RC(0.0) ? c : sqrt(fmax(ct2, RC(0.0))));
  return (d < RC(0.0) && ct2 < RC(0.0)) ? RC(1.0) : f;
}
BRDF_FN real fresnel_schlick_tir_z(param_t eta, param_t z, real c) {
  return fresnel_schlick_tir_g2(eta, z, c, c * c + fresnel_e2m1(eta, z));
}
BRDF_FN real fresnel_schlick_tir(param_t eta, real c) { return fresnel_schlick_tir_z(eta, RC(0.0), c); }

/* Exact unpolarised reflectance of a conductor with complex relative IOR eta + i k (Born and Wolf
 * 1999, sec. 14.2, in the real form of e.g. Lagarde 2013): with s2 = 1 - c^2,
 *   a^2 + b^2 = sqrt((eta^2 - k^2 - s2)^2 + 4 eta^2 k^2),  a = sqrt((a^2 + b^2 + eta^2 - k^2 - s2)/2),
 *   Rs = (a^2 + b^2 - 2 a c + c^2)/(a^2 + b^2 + 2 a c + c^2),
 *   Rp = Rs (c^2 (a^2 + b^2) - 2 a c s2 + s2^2)/(c^2 (a^2 + b^2) + 2 a c s2 + s2^2),  F = (Rs + Rp)/2.
 * k = 0 gives the dielectric (eta >= 1). At c = 0, Rs = Rp = 1. */
BRDF_FN real fresnel_conductor_z(param_t eta, param_t k, param_t z, real c) {
  c = fmin(fabs(c), RC(1.0));
  real s2 = (RC(1.0) - c) * (RC(1.0) + c);
  param_t e2 = eta * eta, k2 = k * k;
  real t = fresnel_e2m1(eta, z) + c * c - k2; /* e2 - k2 - s2 without cancellation near eta = 1 */
  real ab2 = sqrt(t * t + RC(4.0) * e2 * k2);
  real a = sqrt(fmax(RC(0.5) * (ab2 + t), RC(0.0)));
  real c2 = c * c, ac = RC(2.0) * a * c;
  real rs = (ab2 - ac + c2) / (ab2 + ac + c2);
  real u = c2 * ab2 + s2 * s2, v = ac * s2;
  real rp = rs * (u - v) / (u + v);
  return RC(0.5) * (rs + rp);
}
BRDF_FN real fresnel_conductor(param_t eta, param_t k, real c) { return fresnel_conductor_z(eta, k, RC(0.0), c); }

#ifndef BRDF_LANE_PASS
/* F82-tint (Hoffman 2019, "Fresnel equations considered harmful"; Kutz et al. 2021; OpenPBR 1.1):
 * F = F_schlick(c) - b c (1 - c)^6 with b = F_schlick(1/7) (1 - tint)/((1/7)(1 - 1/7)^6), so that
 * F(1/7) = tint F_schlick(1/7): the reflectance near 82 degrees is the tint times Schlick's. */
#define F82_MU_BAR RC(0.142857142857142857143)
BRDF_FN real fresnel_f82_b(real f0, real tint) {
  real m = RC(1.0) - F82_MU_BAR;
  real m2 = m * m, m6 = m2 * m2 * m2;
  real fs = f0 + (RC(1.0) - f0) * m2 * m2 * m;
  return fs * (RC(1.0) - tint) / (F82_MU_BAR * m6);
}
#endif

/* c (1 - c)^6: the F82 correction's shape. */
BRDF_FN real fresnel_f82_weight(real c) {
  real m = RC(1.0) - c;
  real m2 = m * m;
  return c * m2 * m2 * m2;
}

/* F82-tint with b from fresnel_f82_b. */
BRDF_FN real fresnel_f82_tint(param_t f0, param_t b, real c) {
  return fresnel_schlick(f0, c) - b * fresnel_f82_weight(c);
}

/* Any model by id (a uniform branch: model, x, y and z are the same for every lane). x: F0
 * (schlick, f82-tint) or eta (dielectric, schlick-tir, conductor); y: k (conductor) or b
 * (f82-tint); z: eta's correction (fresnel_e2m1) for the models of eta. */
BRDF_FN real fresnel_Fz(int model, param_t x, param_t y, param_t z, real c) {
  if (model == FRESNEL_SCHLICK) return fresnel_schlick(x, c);
  if (model == FRESNEL_DIELECTRIC) return fresnel_dielectric_z(x, z, c);
  if (model == FRESNEL_SCHLICK_TIR) return fresnel_schlick_tir_z(x, z, c);
  if (model == FRESNEL_CONDUCTOR) return fresnel_conductor_z(x, y, z, c);
  if (model == FRESNEL_F82_TINT) return fresnel_f82_tint(x, y, c);
  return RC(1.0) + RC(0.0) * c;
}
BRDF_FN real fresnel_F(int model, param_t x, param_t y, real c) { return fresnel_Fz(model, x, y, RC(0.0), c); }

/* A model with a kink (dielectric, schlick-tir; fresnel_kink > 0) at o.h = c, given
 * g^2 = c^2 - ck^2 computed without cancellation (integrand.h). */
BRDF_FN real fresnel_F_g2(int model, param_t x, param_t z, real c, real g2) {
  return model == FRESNEL_DIELECTRIC ? fresnel_dielectric_g2(c, g2) : fresnel_schlick_tir_g2(x, z, c, g2);
}

#ifndef BRDF_LANE_PASS
/* Where F has a kink: total internal reflection sets in at o.h = sqrt(1 - eta^2) for eta < 1
 * (dielectric, schlick-tir); the integrators split there. -1: nowhere. */
BRDF_FN real fresnel_kink(int moments, int model, real x, real z) {
  if (moments != HEMI_FRESNEL || (model != FRESNEL_DIELECTRIC && model != FRESNEL_SCHLICK_TIR)) return RC(-1.0);
  real d = fresnel_e2m1(x, z);
  return d < RC(0.0) ? sqrt(-d) : RC(-1.0);
}
/* The same kink to about twice float precision, as its return value plus *lo. Beside the kink F
 * depends on o.h through g^2 = (o.h)^2 - ck^2, whose float value keeps the rounding of (o.h)^2 and
 * of ck^2 = 1 - eta^2 while g^2 itself is small, and F's slope there amplifies it: at eta = 0.2,
 * 128^2, mu = 0.98046875 (6.7e-4 above ck), r = 1/256 to 7/256, the albedo was up to 53 u off the
 * reference over the 52 pairs, and is within 1.39 u with o.h - ck formed from the node's geometry
 * (integrand.h hemi_kink_offset; docs/accuracy.md, "The whole sweep"). That needs ck itself beyond
 * float: eta^2 = p + pe exactly (fma), p - 1 = s + e exactly (Fast2Sum, |p| < 1 where there is a
 * kink), so eta^2 - 1 + z = s + (e + pe + z) and ck^2 - hi^2 = -(s + hi^2) - (e + pe + z), the
 * first term exact in one fma. */
BRDF_FN real fresnel_kink_split(int moments, int model, real x, real z, real* lo) {
  *lo = RC(0.0);
  real hi = fresnel_kink(moments, model, x, z);
  if (hi <= RC(0.0)) return hi;
  real p = x * x, pe = fma(x, x, -p);
  real s = p - RC(1.0), e = p - (s + RC(1.0));
  *lo = (fma(-hi, hi, -s) - (e + pe + z)) / (RC(2.0) * hi);
  return hi;
}
/* The scale of o.h on which a dielectric (or schlick-tir) of eta slightly above 1 falls from 1 at
 * grazing to its F0: sqrt(eta^2 - 1). 0 where no such layer needs resolving (eta >= 1.5, or other
 * weights). */
BRDF_FN real fresnel_soft_scale(int moments, int model, real x, real z) {
  if (moments != HEMI_FRESNEL || (model != FRESNEL_DIELECTRIC && model != FRESNEL_SCHLICK_TIR)) return RC(0.0);
  real d = fresnel_e2m1(x, z);
  return d > RC(0.0) && x < RC(1.5) ? sqrt(d) : RC(0.0);
}
/* The o.h layer over which a Fresnel of refractive index near 1 falls from 1 to its F0: F is
 * singular where g^2 = n^2 - 1 + c^2 = 0, at c* = sqrt(1 - n^2) (n = eta + i k; real for a
 * dielectric, the critical cosine when eta < 1, 0 when eta > 1), and changes on the scale
 * w = |c*| = |1 - n^2|^(1/2) beside x0 = Re c* (on both sides for a conductor, whose singularity
 * sits off the real axis at Im c*). The integrators break at the graded levels
 * fresnel_layer_levels gives. Measured at eta = 0.9999, ggx + smith-correlated, mu = 1/64: without
 * them the values still hold their claims (the estimates see the layer and the texel is refined),
 * but the refined budget's estimate rises to 2.0e-7 against below 2e-9 with them
 * (tests/tables/microfacet/fresnel_edge_test.cpp, tools/bite.sh fresnel-layer). Returns w (0: no layer to resolve,
 * w >= FRESNEL_GRADE_MAX or a weight without one) and x0 in *x0; *both: graded on both sides. */
#define FRESNEL_NGRADES 8
BRDF_CONST real FRESNEL_GRADES[FRESNEL_NGRADES] = {RC(0.015625), RC(0.0625), RC(0.25), RC(1.0),
                                                   RC(4.0),      RC(16.0),   RC(64.0), RC(256.0)};
#define FRESNEL_GRADE_MAX RC(0.5)
BRDF_FN real fresnel_layer(int moments, int model, real x, real y, real z, real* x0, int* both) {
  *x0 = RC(0.0);
  *both = 0;
  if (moments != HEMI_FRESNEL) return RC(0.0);
  real w = RC(0.0);
  if (model == FRESNEL_DIELECTRIC || model == FRESNEL_SCHLICK_TIR) {
    real d = -fresnel_e2m1(x, z); /* 1 - eta^2 */
    w = sqrt(fabs(d));
    *x0 = d > RC(0.0) ? w : RC(0.0);
  } else if (model == FRESNEL_CONDUCTOR) {
    real a = y * y - fresnel_e2m1(x, z), b = RC(2.0) * x * y; /* 1 - n^2 = a - i b */
    real m = sqrt(a * a + b * b);
    w = sqrt(m);
    *x0 = sqrt(fmax(RC(0.5) * (m + a), RC(0.0)));
    *both = 1;
  }
  return w < FRESNEL_GRADE_MAX ? w : RC(0.0);
}
/* The layer's graded o.h levels inside (0, 1), into lv: x0 + w FRESNEL_GRADES[j], and for a
 * conductor x0 itself and x0 - w FRESNEL_GRADES[j] (a dielectric's x0 is its kink, a break
 * already, and F = 1 below it). Returns how many, at most FRESNEL_MAX_LEVELS; 0 without a layer. */
#define FRESNEL_MAX_LEVELS (2 * FRESNEL_NGRADES + 1)
BRDF_FN int fresnel_layer_levels(int moments, int model, real x, real y, real z, real* lv) {
  real x0;
  int both, n = 0;
  real w = fresnel_layer(moments, model, x, y, z, &x0, &both);
  if (w <= RC(0.0)) return 0;
  if (both && x0 > RC(0.0) && x0 < RC(1.0)) lv[n++] = x0;
  for (int j = 0; j < FRESNEL_NGRADES; ++j) {
    real up = x0 + w * FRESNEL_GRADES[j], down = x0 - w * FRESNEL_GRADES[j];
    if (up < RC(1.0)) lv[n++] = up;
    if (both && down > RC(0.0)) lv[n++] = down;
  }
  return n;
}
#endif
#endif /* BRDF_FRESNEL_H */
