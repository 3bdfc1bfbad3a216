/* btdf.h: the rough dielectric interface, reflection and transmission (docs/MODELS.md "Rough
 * dielectric"): Walter, Marschner, Li and Torrance 2007, "Microfacet models for refraction through
 * rough surfaces" (below: Walter eq. N), with the exact dielectric Fresnel of fresnel.h and the
 * Smith functions of ndf.h. Needs ndf.h and fresnel.h before it. One value, no lanes.
 *
 * Convention. i is the direction the albedo belongs to (the view, Walter's i), on the side of the
 * normal n; o the scattered direction; both point away from the surface. eta = eta_t/eta_i, the
 * refractive index beyond the surface over the index on i's side: eta > 1 enters glass, eta < 1
 * leaves it (total internal reflection where 1 - (i.h)^2 > eta^2). Walter's (eta_i, eta_o) are
 * (1, eta) in these units. Cosines come in as computed by the caller without cancellation.
 */
/* Once per pass (compat.h "Passes"). */
#if defined(BRDF_SECOND_PASS) ? !defined(BRDF_BTDF_H_2) : !defined(BRDF_BTDF_H)
#ifdef BRDF_SECOND_PASS
#define BRDF_BTDF_H_2
#else
#define BRDF_BTDF_H
#endif
#include "brdf/ndf.h"
#include "brdf/gaf.h"
#include "brdf/fresnel.h"
#ifndef BRDF_LANE_PASS

/* eta^2 - 1 without cancellation near eta = 1. */
BRDF_FN real btdf_eta2m1(real eta) { return (eta - RC(1.0)) * (eta + RC(1.0)); }

/* eta^2 cos^2(theta_t) = eta^2 - 1 + (i.h)^2, Snell's law for the facet h (Walter eq. 40's square
 * root times eta): negative under total internal reflection. */
BRDF_FN real btdf_eta_ct2(real eta, real x) { return btdf_eta2m1(eta) + x * x; }

/* k = i.h - eta cos(theta_t) = -(eta^2 - 1)/(i.h + eta cos(theta_t)), cancellation-free, so that
 * the refracted direction is o_t = (k h - i)/eta (Walter eq. 40 with eta_i/eta_t = 1/eta). */
BRDF_FN real btdf_k(real eta, real x) {
  real ect = sqrt(fmax(btdf_eta_ct2(eta, x), RC(0.0)));
  return -btdf_eta2m1(eta) / (x + ect);
}

/* Generalised half-vector of transmission, unnormalised (Walter eq. 16): h_t = -(eta_i i + eta_o o)
 * = -(i + eta o); the caller normalises it and turns it to n's side. */
BRDF_FN void btdf_ht(real eta, real ix, real iy, real iz, real ox, real oy, real oz, real* hx, real* hy, real* hz) {
  *hx = -(ix + eta * ox);
  *hy = -(iy + eta * oy);
  *hz = -(iz + eta * oz);
}

/* The Jacobian of the refraction map (Walter eq. 17): dw_h/dw_o = eta_o^2 |o.h|/(eta_i (i.h) + eta_o (o.h))^2. */
BRDF_FN real btdf_jacobian(real eta, real ih, real oh) {
  real den = ih + eta * oh;
  return eta * eta * fabs(oh) / (den * den);
}

/* ln Gamma(1 + a) - ln Gamma(2 + a + b) for a, b >= 0; for a > 1e6 the ratio's large-argument form
 * Gamma(z + 1)/Gamma(z + 2 + b) ~ (z + 1 + b/2)^-(1 + b) (Tricomi and Erdelyi 1951, relative
 * error O((1 + b)^3/a^2)), where the two lgammas would cancel. */
BRDF_FN real btdf_lgamma_ratio(real a, real b) {
  return a > RC(1e6) ? -(RC(1.0) + b) * log(a + RC(1.0) + RC(0.5) * b) : lgamma(RC(1.0) + a) - lgamma(RC(2.0) + a + b);
}

/* G(i, o, h)/(n.i) of the Smith models, o on either side (no = |n.o|, s2o its sin^2); cli = (n.i)
 * Lambda(i) from ndf_cLambda. The chi+ factors are the caller's (it knows o's side).
 *   separable (Walter eq. 23, Smith 1967): G1(i) G1(o), G1(v) = |n.v|/(|n.v| + |n.v| Lambda(v));
 *   height-correlated reflection (Heitz 2014 eq. 99): 1/(1 + Lambda_i + Lambda_o);
 *   height-correlated transmission (Heitz 2014, the height-correlated form for transmission): the
 * point must be
 *   visible from above for i and from below for o, int_0^1 u^Lambda_i (1 - u)^Lambda_o du
 *   = B(1 + Lambda_i, 1 + Lambda_o) = Gamma(1 + Lambda_i) Gamma(1 + Lambda_o)/Gamma(2 + Lambda_i +
 * Lambda_o).
 * Divided by n.i so that it stays finite at grazing views (as gaf.h's G/(n.o)); at ni = 0 the
 * limit: separable and correlated reflection 1/cli (times G1(o)); correlated transmission
 * B ~ Gamma(1 + b) (cli/ni)^-(1 + b), so G/ni ~ ni^b -> 0 wherever b = Lambda_o > 0: E_T of
 * smith-correlated vanishes at mu = 0, but like mu^Lambda_o, which is slow (MODELS.md). */
BRDF_FN real btdf_G_over_ni(int ndf, int gaf, BrdfParams p, real ni, real cli, real no, real s2o, int transmit) {
  real clo = ndf_cLambda(ndf, p, no, s2o);
  if (gaf == GAF_SMITH) return no / ((ni + cli) * (no + clo));
  if (!transmit) return no / (ni * no + no * cli + ni * clo);
  if (ni <= RC(0.0)) return RC(0.0); /* b = 0 only on a set of measure zero */
  real b = no > RC(0.0) ? clo / no : RC(1.0) / RC(0.0);
  real a = cli / ni;
  real lg = btdf_lgamma_ratio(a, b) + (b > RC(0.0) ? lgamma(RC(1.0) + b) : RC(0.0));
  return no > RC(0.0) ? exp(lg - log(ni)) : RC(0.0);
}

/* The BSDF at one pair of directions, given the facet normal h of the pair (the mirror half-vector
 * for reflection, the normalised h_t turned to n's side for transmission) and the cosines
 * ni = n.i > 0, no = n.o (either sign), ih = i.h, oh = o.h, nh = n.h, s2h, s2o:
 *   reflection (Walter eq. 20):   f_r = F(i.h) D(h) G / (4 |n.i| |n.o|)
 *   transmission (Walter eq. 21): f_t = |i.h| |o.h|/(|n.i| |n.o|) eta_o^2 (1 - F(i.h)) D(h) G /
 *     (eta_i (i.h) + eta_o (o.h))^2
 * with chi+ (Walter eq. 23): i.h and o.h on the sides of n.i and n.o. f_t carries eta_o^2 (the
 * radiance scaling of the transmitted side), so that int f (n.o) dw_o is the fraction of energy
 * scattered, at most 1 (MODELS.md). */
BRDF_FN real btdf_f(int ndf, int gaf, BrdfParams p, real eta, real ni, real s2i, real no, real s2o, real ih, real oh,
                    real nh, real s2h) {
  int transmit = no < RC(0.0);
  real ano = fabs(no);
  int ok = ni > RC(0.0) && ano > RC(0.0) && nh > RC(0.0) && ih > RC(0.0) && (transmit ? oh < RC(0.0) : oh > RC(0.0));
  if (!ok) return RC(0.0);
  real f = fresnel_dielectric(eta, ih);
  real g = btdf_G_over_ni(ndf, gaf, p, ni, ndf_cLambda(ndf, p, ni, s2i), ano, s2o, transmit) * ni;
  real d = ndf_D(ndf, p, nh, s2h);
  if (!transmit) return f * d * g / (RC(4.0) * ni * ano);
  return ih * btdf_jacobian(eta, ih, oh) * (RC(1.0) - f) * d * g / (ni * ano);
}

#endif /* !BRDF_LANE_PASS */
#endif /* BRDF_BTDF_H */
