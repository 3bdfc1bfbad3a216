/* integrand.h: the integrand of the hemisphere estimators at one node (or one lane vector of
 * nodes: compiled in both passes, see compat.h). hemisphere.h holds the derivation; in its
 * variables, with o = (s, 0, mu) and h at (theta_h, phi):
 *   o.h = s sin(theta_h) cos(phi) + mu cos(theta_h),  n.i = 2 (o.h) cos(theta_h) - mu,
 *   H = (G/(n.o)) (o.h)/(n.h), split by Schlick's weight into the F0 and F90 moments.
 * Only cos(phi) varies across lanes: the view and theta_h are param_t, so the view's Lambda is
 * computed once per call, not once per lane.
 */
/* Once per pass (compat.h "Passes"). */
#if defined(BRDF_SECOND_PASS) ? !defined(BRDF_INTEGRAND_H_2) : !defined(BRDF_INTEGRAND_H)
#ifdef BRDF_SECOND_PASS
#define BRDF_INTEGRAND_H_2
#else
#define BRDF_INTEGRAND_H
#endif
#include "brdf/ndf.h"
#include "brdf/gaf.h"
#include "brdf/fresnel.h"
#ifndef BRDF_LANE_PASS
/* p with the view's GAF term set (BrdfParams.has_view): every node of a texel shares the view
 * o = (s, 0, mu), so its Lambda is computed once here instead of at every hemi_node call. With
 * the Beckmann Lambda (erfc and exp), recomputing it at each call took a third of the kernel time
 * of beckmann + smith's 128^2 split sum (perf, 2 cores). */
/* col: room for SMITH_NZ values, the tabulated exact Lambda's column at this alpha
 * (ndf.h smith_column), which p then points to for the texel's lifetime. */
BRDF_FN BrdfParams hemi_view(int ndf, int gaf, BrdfParams p, param_t mu, param_t s, float* col) {
  if (gaf_lambda_tabulated(ndf, gaf)) p.smith_col = smith_column(ndf, p, col);
  p.view_cl = gaf_view_cLambda(gaf, ndf, p, mu, s * s);
  p.has_view = 1;
  return p;
}
#endif

/* o.h - ck less its phi term s sn cos(phi), at theta_h (c, s2 = sin^2 theta_h): for a Fresnel
 * weight with a kink at o.h = ck (ck + ck_lo: fresnel_kink_split),
 *   o.h - ck = s sn cos(phi) + (mu - ck) - mu (1 - c),  1 - c = s2/(1 + c),
 * each term to its own float precision, where o.h's float value is within about u of o.h, not of
 * o.h - ck. g^2 = (o.h - ck)(o.h + ck) then keeps a relative precision next to the kink (fresnel.h
 * fresnel_kink_split says what that is worth), and the integrators put the kink's panel breaks
 * where this offset says it is (azimuth.h hemi_phi_plan). */
BRDF_FN real hemi_kink_offset(param_t mu, real c, real s2, param_t ck, param_t ck_lo) {
  return ((mu - ck) - ck_lo) - mu * (s2 / (RC(1.0) + c));
}

/* The Fresnel weight (model and x, y, z: BrdfParams' fresnel, fr_*) at o.h = oh, sp = s sn cos(phi),
 * at theta_h (c, s2): next to a kink from o.h - ck, hemi_kink_offset plus sp. With theta_h one value
 * for every lane (c, s2 param_t): its offset is formed once, not per lane (hemi_fresnel_weight_c
 * takes them per lane). Out of line, with scalar arguments: written into hemi_node the kink's code
 * slowed the split sum, which never takes it, and passing BrdfParams slowed the weights that do
 * (docs/performance.md, "Kernel choices"). */
BRDF_FN_OUTLINE real hemi_fresnel_weight(int model, param_t x, param_t y, param_t z, param_t mu, real sp, param_t c,
                                         param_t s2, real oh) {
  param_t ck_lo, ck = fresnel_kink_split(HEMI_FRESNEL, model, x, z, &ck_lo);
  if (ck > RC(0.0)) {
    param_t off = hemi_kink_offset(mu, c, s2, ck, ck_lo);
    return fresnel_F_g2(model, x, z, oh, (sp + off) * (oh + ck));
  }
  return fresnel_Fz(model, x, y, z, oh);
}
BRDF_FN_OUTLINE real hemi_fresnel_weight_c(int model, param_t x, param_t y, param_t z, param_t mu, real sp, real c,
                                           real s2, real oh) {
  param_t ck_lo, ck = fresnel_kink_split(HEMI_FRESNEL, model, x, z, &ck_lo);
  if (ck > RC(0.0)) return fresnel_F_g2(model, x, z, oh, (sp + hemi_kink_offset(mu, c, s2, ck, ck_lo)) * (oh + ck));
  return fresnel_Fz(model, x, y, z, oh);
}

/* The integrand H split by the weight w(o.h) that p.moments names (ndf.h BrdfParams): fb = H w,
 * fa = H (1 - w); Schlick's (1 - o.h)^5 for the split-sum pair. At the angle h (sn = sin theta_h)
 * and cphi = cos phi: one theta_h for every lane, cphi per lane. */
BRDF_FN void hemi_node(int ndf, int gaf, BrdfParams p, param_t mu, param_t s, BrdfAngle h, param_t sn, real cphi,
                       real* fa, real* fb) {
  real oh = fmin(s * sn * cphi + mu * h.c, RC(1.0)); /* rounding can push it past 1 */
  /* n.i <= 1 exactly, but not always after rounding: clamp so sin^2 theta_i never goes negative */
  real ni = fmin(RC(2.0) * oh * h.c - mu, RC(1.0));
  real s2i = (RC(1.0) - ni) * (RC(1.0) + ni);
  param_t s2o = s * s;
  /* 1/cos theta_h once per call, not a lane division per node */
  param_t ic = RC(1.0) / h.c;
  real H = gaf_G_over_no(gaf, ndf, p, ni, mu, h.c, oh, s2i, s2o) * oh * ic;
  real w;
  if (p.moments == HEMI_FRESNEL)
    w = hemi_fresnel_weight(p.fresnel, p.fr_x, p.fr_y, p.fr_z, mu, s * sn * cphi, h.c, h.s2, oh);
  else if (p.moments == HEMI_F82C)
    w = fresnel_f82_weight(oh);
  else
    w = fresnel_schlick_weight(oh);
  *fb = H * w;
  *fa = H - *fb;
}

/* The same with theta_h per lane (c = cos theta_h, sn = sin theta_h) at one azimuth: hemisphere.h
 * batches the trapezoids' phi = pi nodes so. Written out rather than shared with hemi_node: with
 * hemi_node calling it (theta_h a lane vector there too), or with a shared weight-and-split helper,
 * the split-sum kernel measured slower (docs/performance.md, "Kernel choices"). */
BRDF_FN void hemi_node_c(int ndf, int gaf, BrdfParams p, param_t mu, param_t s, real c, real sn, real cphi, real* fa,
                         real* fb) {
  real oh = fmin(s * sn * cphi + mu * c, RC(1.0));
  real ni = fmin(RC(2.0) * oh * c - mu, RC(1.0));
  real s2i = (RC(1.0) - ni) * (RC(1.0) + ni);
  param_t s2o = s * s;
  /* written as hemi_node forms it (1/c, then the product), so the two differ only in where c varies */
  real H = gaf_G_over_no(gaf, ndf, p, ni, mu, c, oh, s2i, s2o) * oh * (RC(1.0) / c);
  real w;
  if (p.moments == HEMI_FRESNEL)
    w = hemi_fresnel_weight_c(p.fresnel, p.fr_x, p.fr_y, p.fr_z, mu, s * sn * cphi, c, sn * sn, oh);
  else if (p.moments == HEMI_F82C)
    w = fresnel_f82_weight(oh);
  else
    w = fresnel_schlick_weight(oh);
  *fb = H * w;
  *fa = H - *fb;
}
#endif /* BRDF_INTEGRAND_H */
