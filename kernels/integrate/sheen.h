/* sheen.h: the directional albedo E(mu) (and the split-sum moments) of the charlie NDF (Estevez and
 * Kulla 2017), whose lobe peaks on the horizon of h instead of at h = n. Shared by the device and the
 * host tests; hemisphere_moments (hemisphere.h) hands charlie here, so every table kind that
 * integrates E (splitsum, albedo, albedo-avg) uses it.
 *
 * Derivation. As in hemisphere.h, E = (1/pi) int e^-v w dv int_0^phimax H dphi with
 * H = (G/no) F (o.h)/(n.h), on charlie's own coordinate v = -log(CDF) (ndf.h: CDF = s2^e,
 * e = 1 + 1/(2 alpha), v = -e log1p(-c^2)), which DEcreases as theta_h grows: v = 0 on the horizon of
 * h (D's peak), v -> inf at h = n (D's tail). In v the visible domain of hemisphere.h reads
 *   v >= v1 = e log1p(1/t1^2): the whole circle (theta_h <= theta1 = (pi/2 - theta_o)/2),
 *   v2 <= v <= v1, v2 = e log1p(t1^2): the arc ends at phimax(v) (t2 = 1/t1: theta2 = pi/2 - theta1),
 *   v < v2: nothing (n.i < 0 on the whole circle),
 * with t1 = mu/(1 + s); at mu = 0, v2 = 0 and v1 = inf (all of it partial, phimax = pi/2).
 * Panels, all GK15 through hemisphere.h's hemi_outer_panel (whose geometry is the same in any
 * coordinate that ndf_angle_v and ndf_tan2_diff describe):
 *  - partial region [v2, min(v1, v2 + HEMI_VCAP)]: widths HEMI_BREAKS counted from v2 (e^-v decays
 *    from there), square-root ends substituted at v2 (phimax ~ sqrt(v - v2)) and at v1 (pi - phimax
 *    ~ sqrt(v1 - v)); panels graded x4 away from v = 0, where 1/(n.h) ~ (v/e)^(-1/2): at grazing
 *    views v2 ~ e mu^2/4 is tiny and H changes on that scale (n.i, n.o ~ mu), so the panels after the
 *    first are kept within 3 times their distance from both v = 0 and v2; and graded towards v1;
 *  - full region [v1, v1 + HEMI_VCAP]: widths HEMI_BREAKS counted from v1 (smooth at v1: the whole
 *    circle's integrand is smooth there, as in hemisphere.h);
 *  - both cut at the GAF's theta breaks (gaf.h gaf_theta_breaks: charlie-smith's n.i = 1/2), with
 *    the square substitution on the panels beside them, as in hemisphere.h.
 * The estimate is hemisphere.h's: gk_error of the outer rule plus the inner rules' estimates.
 * alpha = 0: the lobe lies on the horizon, where n.i = 2 (o.h) c - mu = -mu < 0, so E = 0 for mu > 0
 * (the corner mu = 0 is evaluated at HEMI_CORNER_R, hemisphere_texel.h).
 */
/* Once per pass (compat.h "Passes"). */
#if defined(BRDF_SECOND_PASS) ? !defined(BRDF_SHEEN_H_2) : !defined(BRDF_SHEEN_H)
#ifdef BRDF_SECOND_PASS
#define BRDF_SHEEN_H_2
#else
#define BRDF_SHEEN_H
#endif
#include "integrate/hemisphere.h"
/* The first of the theta breaks' v[0 .. n) inside (cur, end), or end. */
BRDF_FN real sheen_next_break(const real* v, int n, real cur, real end) {
  for (int q = 0; q < n; ++q)
    if (v[q] > cur && v[q] < end) end = v[q];
  return end;
}
BRDF_FN int sheen_is_break(const real* v, int n, real x) {
  int hit = 0;
  for (int q = 0; q < n; ++q) hit |= v[q] == x;
  return hit;
}

BRDF_FN HemiResult sheen_moments(int gaf, BrdfParams p, real mu, int refine) {
  HemiResult res;
  res.a = 0;
  res.b = 0;
  res.err_a = 0;
  res.err_b = 0;
  if (p.alpha <= RC(0.0)) return res;
  const int ndf = NDF_CHARLIE;
  real s = sqrt((RC(1.0) - mu) * (RC(1.0) + mu));
  p = hemi_view(ndf, gaf, p, mu, s, 0); /* charlie's Lambda is not tabulated */
  real t1 = mu / (RC(1.0) + s);
  real ie = ndf_charlie_inv_e(p);
  real v2 = log1p(t1 * t1) / ie;
  real v1 = t1 > RC(0.0) ? log1p(RC(1.0) / (t1 * t1)) / ie : RC(1.0) / RC(0.0);
  real pend = fmin(v1, v2 + HEMI_VCAP);
  real gt2[GAF_MAX_THETA_BREAKS], gv[GAF_MAX_THETA_BREAKS];
  int ng = gaf_theta_breaks(gaf, mu, s, gt2);
  for (int q = 0; q < ng; ++q) gv[q] = ndf_v_of_tan2(ndf, p, gt2[q]);
  real cur = v2;
  int k = 0;
  while (cur < pend) {
    while (k < HEMI_NBREAKS && v2 + HEMI_BREAKS[k] <= cur) ++k;
    real next = k < HEMI_NBREAKS ? v2 + HEMI_BREAKS[k] : pend;
    if (cur > RC(0.0)) next = fmin(next, RC(4.0) * cur);
    if (cur > v2) next = fmin(next, v2 + RC(4.0) * (cur - v2));
    next = fmin(next, sheen_next_break(gv, ng, cur, pend));
    if (pend == v1 && next < v1 && next - cur > RC(3.0) * (v1 - next)) {
      real d = v1 - next;
      while (v1 - RC(4.0) * d > cur) d *= RC(4.0);
      next = v1 - d;
    }
    hemi_panel(ndf, gaf, p, mu, s, t1, v1, cur, next, 1, cur == v2 || sheen_is_break(gv, ng, cur),
               next == v1 || sheen_is_break(gv, ng, next), refine, &res);
    cur = next;
  }
  if (v1 < v2 + HEMI_VCAP) {
    cur = v1;
    for (k = 0; k < HEMI_NBREAKS;) {
      real end = v1 + HEMI_BREAKS[k], next = sheen_next_break(gv, ng, cur, end);
      hemi_panel(ndf, gaf, p, mu, s, t1, v1, cur, next, 0, sheen_is_break(gv, ng, cur), sheen_is_break(gv, ng, next),
                 refine, &res);
      if (next == end) ++k;
      cur = next;
    }
  }
  res.a *= BRDF_INV_PI;
  res.b *= BRDF_INV_PI;
  res.err_a *= BRDF_INV_PI;
  res.err_b *= BRDF_INV_PI;
  return res;
}
#endif /* BRDF_SHEEN_H */
