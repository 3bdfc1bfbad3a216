/* diffuse_albedo.h: directional albedo E(mu) = int f_d(i, o) (n.i) dw_i of the diffuse models
 * (kernels/brdf/diffuse.h), with an error bound. Needs quadrature.h (GK15 tables).
 *
 * Derivation. With o = (so, 0, mu) and i at (theta, phi) from the normal and o's azimuth,
 * dw_i = sin(theta) dtheta dphi and n.i = cos(theta). f_d depends on phi only through cos(phi)
 * (even, 2 pi-periodic), so
 *   E(mu) = 2 int_0^{pi/2} dtheta sin(theta) cos(theta) int_0^pi f_d dphi.
 * Lambert and the two Shirley forms do not depend on phi: the inner integral is pi f_d.
 * Oren-Nayar has max(0, cos phi) (a kink at phi = pi/2) and its max/min of theta_i, theta_o switch at
 * theta = theta_o (a kink in theta); Burley is a quadratic in cos(phi) (smooth). So:
 *   theta: the pieces [0, theta_o] and [theta_o, pi/2], each in DIFFUSE_PANELS equal GK15 panels;
 *   phi:   GK15 on [0, pi/2] and on [pi/2, pi] (15 nodes, one lane vector each on the device).
 * On each piece the integrand is smooth in theta (sin^2, tan(theta_o) sin^2 cos, polynomials in
 * cos and sin), so GK15 converges fast; the bound is the sum of |K15 - G7| over the theta panels
 * plus the Kronrod-weighted inner |K15 - G7| (pessimistic for smooth integrands).
 * Accuracy near grazing: each node's cos(theta) is computed as sin(pi/2 - theta) from the
 * complement, carried separately from theta (pi/2 - theta_o = atan2(mu, so)), so that n.i keeps
 * its relative accuracy on the piece [theta_o, pi/2], whose width is ~mu when mu -> 0. mu = 0
 * exactly is then the piece [0, pi/2] alone (the second has width 0), which is the limit from inside
 * for every model whose albedo is continuous there (all but oren-nayar-as-printed).
 * Divergent cases (errata, docs/MODELS.md): oren-nayar-as-printed diverges like B/(n.o) at grazing
 * (E ~ 2B/(3 pi mu)); it is evaluated at max(mu, DIFFUSE_MU_FLOOR), so E stays finite (~1e29 at
 * mu = 0), and where mu < DIFFUSE_MU_FLOOR and B > 0 (true value +inf) the bound is DIFFUSE_HUGE.
 * shirley-as-printed divides by 1 - F0, floored at DIFFUSE_TINY in the model: where 1 - F0 is below
 * that (true value +inf for mu > 0) the bound is DIFFUSE_HUGE. The result is never NaN or Inf.
 */
/* Once per pass (compat.h "Passes"). */
#if defined(BRDF_SECOND_PASS) ? !defined(BRDF_DIFFUSE_ALBEDO_H_2) : !defined(BRDF_DIFFUSE_ALBEDO_H)
#ifdef BRDF_SECOND_PASS
#define BRDF_DIFFUSE_ALBEDO_H_2
#else
#define BRDF_DIFFUSE_ALBEDO_H
#endif
#include "integrate/lanes.h"
#include "integrate/quadrature.h"
#define DIFFUSE_PANELS 2
#define DIFFUSE_MU_FLOOR DIFFUSE_TINY
#define DIFFUSE_HUGE RC(1e38)

/* Whether the model's f_d depends on the azimuth difference. */
BRDF_FN int diffuse_depends_on_phi(int model) {
  return model == DIFFUSE_OREN_NAYAR || model == DIFFUSE_BURLEY || model == DIFFUSE_OREN_NAYAR_AS_PRINTED;
}

/* int_0^pi f_d dphi at one theta (ni, si): GK15 on [0, pi/2] and [pi/2, pi], whose node cosines
 * c1, c2 the caller computes once; |K15 - G7| of both to *err. */
BRDF_FN real diffuse_phi_integral(int model, real param, real ni, real si, real no, real so, const real* c1,
                                  const real* c2, real* err) {
  real s = RC(0.0), d1 = RC(0.0), d2 = RC(0.0);
  for (int k = 0; k + BRDF_LANES <= HEMI_GK_N; k += BRDF_LANES) {
    lane_t wk = lane_load(GK15_WKL, k), wd = lane_load(GK15_WDL, k);
    lane_t f1 = diffuse_f(model, param, (lane_t)ni, (lane_t)si, no, so, lane_load(c1, k));
    lane_t f2 = diffuse_f(model, param, (lane_t)ni, (lane_t)si, no, so, lane_load(c2, k));
    s += lane_sum(wk * (f1 + f2));
    d1 += lane_sum(wd * f1);
    d2 += lane_sum(wd * f2);
  }
  real hw = RC(0.25) * BRDF_PI;
  *err = (fabs(d1) + fabs(d2)) * hw;
  return s * hw;
}

/* E(mu) of diffuse model `model` with parameter `param` (diffuse.h), mu in [0, 1]; *err: a bound
 * on |E - exact| (absolute). */
BRDF_FN real diffuse_albedo(int model, real param, real mu, real* err) {
  mu = fmin(fmax(mu, RC(0.0)), RC(1.0));
  int on_printed = model == DIFFUSE_OREN_NAYAR_AS_PRINTED;
  int sh_printed = model == DIFFUSE_SHIRLEY_AS_PRINTED;
  int infinite = (on_printed && mu < DIFFUSE_MU_FLOOR && diffuse_on_b(param) > RC(0.0)) ||
                 (sh_printed && RC(1.0) - param < DIFFUSE_MU_FLOOR);
  real no = on_printed ? fmax(mu, DIFFUSE_MU_FLOOR) : mu;
  real so = sqrt((RC(1.0) - no) * (RC(1.0) + no));
  real tho = atan2(so, no), cho = atan2(no, so); /* theta_o and pi/2 - theta_o */
  int phi = diffuse_depends_on_phi(model);
  /* the phi nodes' cosines on [0, pi/2] and [pi/2, pi] */
  real c1[16], c2[16];
  for (int k = 0; k + BRDF_LANES <= HEMI_GK_N; k += BRDF_LANES) {
    lane_t x = lane_load(GK15_XL, k);
    lane_store(cos(RC(0.25) * BRDF_PI * (RC(1.0) + x)), c1, k);
    lane_store(cos(RC(0.25) * BRDF_PI * (RC(3.0) + x)), c2, k);
  }
  acc_t sum = 0, bound = 0;
  for (int piece = 0; piece < 2; ++piece) {
    /* [a0, a0 + w] in theta, complement ac0 - [0, w] */
    real a0 = piece == 0 ? RC(0.0) : tho;
    real ac0 = piece == 0 ? RC(0.5) * BRDF_PI : cho;
    real w = piece == 0 ? tho : cho;
    if (!(w > RC(0.0))) continue;
    real hw = RC(0.5) * w / (real)DIFFUSE_PANELS;
    for (int j = 0; j < DIFFUSE_PANELS; ++j) {
      real a = a0 + w * (real)j / (real)DIFFUSE_PANELS;
      real ac = ac0 - w * (real)j / (real)DIFFUSE_PANELS;
      real s = RC(0.0), d = RC(0.0), e = RC(0.0);
      if (phi) {
        for (int k = 0; k < 15; ++k) {
          real x = GK15_XL[k];
          real si = sin(a + hw * (RC(1.0) + x)), ni = sin(ac - hw * (RC(1.0) + x));
          real ie = RC(0.0);
          real g = ni * si * diffuse_phi_integral(model, param, ni, si, no, so, c1, c2, &ie);
          s += GK15_WKL[k] * g;
          d += GK15_WDL[k] * g;
          e += GK15_WKL[k] * ni * si * ie;
        }
      } else {
        for (int k = 0; k + BRDF_LANES <= HEMI_GK_N; k += BRDF_LANES) {
          lane_t x = lane_load(GK15_XL, k);
          lane_t si = sin(a + hw * (RC(1.0) + x)), ni = sin(ac - hw * (RC(1.0) + x));
          lane_t g = BRDF_PI * ni * si * diffuse_f(model, param, ni, si, no, so, (lane_t)RC(1.0));
          s += lane_sum(lane_load(GK15_WKL, k) * g);
          d += lane_sum(lane_load(GK15_WDL, k) * g);
        }
      }
      sum += (acc_t)(RC(2.0) * hw * s);
      bound += (acc_t)(RC(2.0) * hw * (fabs(d) + e));
    }
  }
  *err = infinite ? DIFFUSE_HUGE : (real)bound;
  return (real)sum;
}
#endif /* BRDF_DIFFUSE_ALBEDO_H */
