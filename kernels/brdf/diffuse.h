/* diffuse.h: diffuse BRDFs f_d(i, o) with albedo rho = 1, MODELS.md "Diffuse models" (docs/MODELS.md
 * "Diffuse models" for the conventions and errata). Without the (n.i) cosine.
 *   ni, si: cos and sin of theta_i (the lane argument); no, so: cos and sin of theta_o (param_t, one
 *   per call); cphi: cos of the azimuth difference phi_i - phi_o (lane argument).
 * Branch-free in the lane arguments (fmin/fmax and selects), so that the lane pass compiles them
 * for float16 (compat.h). Needs fresnel.h (fresnel_schlick_weight) before it.
 * Parameters: shirley, ashikhmin-shirley and shirley-as-printed take F0 (Rs); oren-nayar (and its
 * as-printed form) take sigma in radians; burley takes the roughness r in [0, 1]; lambert none.
 */
/* Once per pass (compat.h "Passes"). */
#if defined(BRDF_SECOND_PASS) ? !defined(BRDF_DIFFUSE_H_2) : !defined(BRDF_DIFFUSE_H)
#ifdef BRDF_SECOND_PASS
#define BRDF_DIFFUSE_H_2
#else
#define BRDF_DIFFUSE_H
#endif
#include "brdf/fresnel.h"
#ifndef BRDF_LANE_PASS
#define DIFFUSE_LAMBERT 0
#define DIFFUSE_SHIRLEY 1
#define DIFFUSE_ASHIKHMIN_SHIRLEY 2
#define DIFFUSE_OREN_NAYAR 3
#define DIFFUSE_BURLEY 4
#define DIFFUSE_SHIRLEY_AS_PRINTED 5
#define DIFFUSE_OREN_NAYAR_AS_PRINTED 6
#define DIFFUSE_COUNT 7
#define DIFFUSE_DEFAULT_F0 0.04
/* Floor of 1 - F0 in shirley-as-printed (and of n.o in the albedo of oren-nayar-as-printed): keeps
 * the errata's infinite values finite (about 1e30), never Inf or NaN. */
#define DIFFUSE_TINY RC(1e-30)

/* Oren and Nayar 1994, qualitative model: A = 1 - 0.5 s^2/(s^2 + 0.33), B = 0.45 s^2/(s^2 + 0.09) */
BRDF_FN real diffuse_on_a(real sigma) {
  real s2 = sigma * sigma;
  return RC(1.0) - RC(0.5) * s2 / (s2 + RC(0.33));
}
BRDF_FN real diffuse_on_b(real sigma) {
  real s2 = sigma * sigma;
  return RC(0.45) * s2 / (s2 + RC(0.09));
}
#endif /* !BRDF_LANE_PASS */

/* Lambert: rho/pi */
BRDF_FN real diffuse_lambert(real ni) {
  (void)ni;
  return (real)BRDF_INV_PI;
}

/* Shirley et al. 1997: 21/(20 pi) (1 - F0) (1 - (1 - n.i)^5)(1 - (1 - n.o)^5) */
BRDF_FN real diffuse_shirley(param_t f0, real ni, param_t no) {
  return RC(0.33422538049298023) * (RC(1.0) - f0) * (RC(1.0) - fresnel_schlick_weight(ni)) *
         (RC(1.0) - fresnel_schlick_weight(no));
}

/* Shirley as printed in seed 000 (erratum): (1 - F0) divides, 21/(20 pi) (...)(...)/(1 - F0);
 * 1 - F0 floored at DIFFUSE_TINY (the printed form is infinite at F0 = 1). */
BRDF_FN real diffuse_shirley_as_printed(param_t f0, real ni, param_t no) {
  return RC(0.33422538049298023) * (RC(1.0) - fresnel_schlick_weight(ni)) * (RC(1.0) - fresnel_schlick_weight(no)) /
         fmax(RC(1.0) - f0, DIFFUSE_TINY);
}

/* Ashikhmin and Shirley 2000: 28/(23 pi) (1 - Rs) (1 - (1 - n.i/2)^5)(1 - (1 - n.o/2)^5) */
BRDF_FN real diffuse_ashikhmin_shirley(param_t rs, real ni, param_t no) {
  return RC(0.38750768752809300) * (RC(1.0) - rs) * (RC(1.0) - fresnel_schlick_weight(RC(0.5) * ni)) *
         (RC(1.0) - fresnel_schlick_weight(RC(0.5) * no));
}

/* Oren and Nayar 1994: 1/pi (A + B max(0, cos phi) sin(max(theta_i, theta_o)) tan(min(theta_i, theta_o))).
 * On [0, pi/2] sin and tan increase, so sin(max) = max(sin) and tan(min) = min(tan); tan theta_o is
 * infinite at no = 0 and then not the min (n.i > 0 inside the integrals). */
BRDF_FN real diffuse_oren_nayar(param_t sigma, real ni, real si, param_t no, param_t so, real cphi) {
  param_t a = diffuse_on_a(sigma), b = diffuse_on_b(sigma);
  return BRDF_INV_PI * (a + b * fmax(cphi, RC(0.0)) * fmax(si, so) * fmin(si / ni, so / no));
}

/* Oren-Nayar as printed in the seed 000 slides (erratum): sin(min(theta_i, theta_o)) tan(max(...)).
 * Infinite at no = 0 where B > 0 (and si > 0); the albedo diverges like 1/(n.o) at grazing. */
BRDF_FN real diffuse_oren_nayar_as_printed(param_t sigma, real ni, real si, param_t no, param_t so, real cphi) {
  param_t a = diffuse_on_a(sigma), b = diffuse_on_b(sigma);
  return BRDF_INV_PI * (a + b * fmax(cphi, RC(0.0)) * fmin(si, so) * fmax(si / ni, so / no));
}

/* Burley 2012: 1/pi (1 + (F_D90 - 1)(1 - n.i)^5)(1 + (F_D90 - 1)(1 - n.o)^5), F_D90 = 0.5 + 2 r cos^2 theta_d,
 * with cos^2 theta_d = (i.h)^2 = (1 + i.o)/2 and i.o = (n.i)(n.o) + sin theta_i sin theta_o cos phi. */
BRDF_FN real diffuse_burley(param_t r, real ni, real si, param_t no, param_t so, real cphi) {
  real fd90m1 = r * (RC(1.0) + ni * no + si * so * cphi) - RC(0.5);
  return BRDF_INV_PI * (RC(1.0) + fd90m1 * fresnel_schlick_weight(ni)) *
         (RC(1.0) + fd90m1 * fresnel_schlick_weight(no));
}

/* f_d of model `model` (one of DIFFUSE_*), uniform in a call; `param` as above. */
BRDF_FN real diffuse_f(int model, param_t param, real ni, real si, param_t no, param_t so, real cphi) {
  if (model == DIFFUSE_SHIRLEY) return diffuse_shirley(param, ni, no);
  if (model == DIFFUSE_ASHIKHMIN_SHIRLEY) return diffuse_ashikhmin_shirley(param, ni, no);
  if (model == DIFFUSE_OREN_NAYAR) return diffuse_oren_nayar(param, ni, si, no, so, cphi);
  if (model == DIFFUSE_BURLEY) return diffuse_burley(param, ni, si, no, so, cphi);
  if (model == DIFFUSE_SHIRLEY_AS_PRINTED) return diffuse_shirley_as_printed(param, ni, no);
  if (model == DIFFUSE_OREN_NAYAR_AS_PRINTED) return diffuse_oren_nayar_as_printed(param, ni, si, no, so, cphi);
  return diffuse_lambert(ni);
}
#endif /* BRDF_DIFFUSE_H */
