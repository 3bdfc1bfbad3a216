/* gaf.h: geometric attenuation (masking-shadowing) G(i,o,h), MODELS.md "Geometric attenuation".
 *
 * Each model is written as G/(n.o): finite at grazing view (n.o -> 0) for every model but `none`,
 * whose albedo truly diverges there. The estimators integrate D (G/(n.o)) F (o.h) dw_h, so the 1/(n.o)
 * of the BRDF never meets a zero. gaf_G multiplies back by n.o. All include chi+: G = 0 where
 * n.i <= 0 or o.h <= 0 (i.h = o.h for the half vector).
 *   ni, no, nh, oh: the cosines n.i, n.o, n.h, o.h; s2i, s2o: sin^2 of theta_i, theta_o.
 * The view (no, s2o) is param_t: one per call, also in the lane pass (compat.h).
 */
/* Once per pass (compat.h "Passes"). */
#if defined(BRDF_SECOND_PASS) ? !defined(BRDF_GAF_H_2) : !defined(BRDF_GAF_H)
#ifdef BRDF_SECOND_PASS
#define BRDF_GAF_H_2
#else
#define BRDF_GAF_H
#endif
#include "brdf/ndf.h"
#include "brdf/smith_tables.h"
#ifndef BRDF_LANE_PASS
#define GAF_NONE 0
#define GAF_IMPLICIT 1
#define GAF_COOK_TORRANCE 2
#define GAF_KELEMEN 3
#define GAF_NEUMANN 4
#define GAF_ASHIKHMIN_PREMOZE 5
#define GAF_SCHLICK_BECKMANN 6
#define GAF_SCHLICK_GGX 7
#define GAF_SCHLICK_GGX_DIRECT 8
#define GAF_SMITH 9
#define GAF_SMITH_CORRELATED 10
/* the same with the NDF's exact Smith Lambda (ndf_cLambda_exact): differs for Blinn-Phong and the
 * gaussian, whose `smith`/`smith-correlated` keep Beckmann's Lambda (MODELS.md "Exact Smith Lambda") */
#define GAF_SMITH_EXACT 11
#define GAF_SMITH_CORRELATED_EXACT 12
/* the sheen visibilities, for the charlie NDF only (MODELS.md "Sheen"; host/common/models.cpp
 * pairSupported): Estevez and Kulla 2017's fitted Smith Lambda, and Neubelt and Pettineo 2013 */
#define GAF_CHARLIE_SMITH 13
#define GAF_NEUBELT 14
#define GAF_COUNT 15

/* Schlick's k per convention (MODELS.md): schlick-beckmann k = alpha sqrt(2/pi) (Schlick 1994 with
 * m = alpha), schlick-ggx k = alpha/2 (Karis 2013, IBL), schlick-ggx-direct k = (r+1)^2/8 (Karis 2013,
 * analytic lights). 0 for the other models. */
BRDF_FN real gaf_schlick_k(int gaf, real r, real alpha) {
  if (gaf == GAF_SCHLICK_BECKMANN) return alpha * RC(0.79788456080286535588);
  if (gaf == GAF_SCHLICK_GGX) return RC(0.5) * alpha;
  if (gaf == GAF_SCHLICK_GGX_DIRECT) return (r + RC(1.0)) * (r + RC(1.0)) * RC(0.125);
  return RC(0.0);
}

/* The view's c Lambda = (n.o) Lambda(o) that the GAF's G uses, 0 for the GAFs without one: the
 * NDF's Smith Lambda, its exact one (ndf_cLambda_exact) or charlie's fit. */
BRDF_FN real gaf_view_cLambda(int gaf, int ndf, BrdfParams p, real no, real s2o) {
  if (gaf == GAF_CHARLIE_SMITH) return ndf_cLambda(NDF_CHARLIE, p, no, s2o);
  if (gaf == GAF_SMITH || gaf == GAF_SMITH_CORRELATED) return ndf_cLambda(ndf, p, no, s2o);
  if (gaf == GAF_SMITH_EXACT || gaf == GAF_SMITH_CORRELATED_EXACT) return ndf_cLambda_exact(ndf, p, no, s2o);
  return RC(0.0);
}

#endif /* !BRDF_LANE_PASS */

BRDF_FN real gaf_G_over_no(int gaf, int ndf, BrdfParams p, real ni, param_t no, real nh, real oh, real s2i,
                           param_t s2o) {
  real g;
  /* the view's Lambda: one value for every lane (param_t), set once per texel by the estimators */
  param_t clo = p.has_view ? p.view_cl : gaf_view_cLambda(gaf, ndf, p, no, s2o);
  if (gaf == GAF_NONE) {
    /* Ward: G = 1 */
    g = RC(1.0) / no;
  } else if (gaf == GAF_IMPLICIT) {
    /* Blinn-Phong's hidden G = (n.i)(n.o) */
    g = ni;
  } else if (gaf == GAF_COOK_TORRANCE) {
    /* Cook and Torrance 1982: min(1, 2(n.h)(n.o)/(o.h), 2(n.h)(n.i)/(o.h)) */
    real t = RC(2.0) * nh / oh;
    g = fmin(fmin(RC(1.0) / no, t), t * ni / no);
  } else if (gaf == GAF_KELEMEN) {
    /* Kelemen and Szirmay-Kalos 2001: (n.i)(n.o)/(o.h)^2 */
    g = ni / (oh * oh);
  } else if (gaf == GAF_NEUMANN) {
    /* Neumann et al. 1999: (n.i)(n.o)/max(n.i, n.o) */
    g = ni / fmax(ni, no);
  } else if (gaf == GAF_ASHIKHMIN_PREMOZE || gaf == GAF_NEUBELT) {
    /* Ashikhmin and Premoze 2007: (n.i)(n.o)/(n.i + n.o - (n.i)(n.o)); Neubelt and Pettineo 2013's
     * cloth visibility V = 1/(4 (n.l + n.v - (n.l)(n.v))) = G/(4 (n.i)(n.o)) is the same G */
    g = ni / (ni + no - ni * no);
  } else if (gaf == GAF_CHARLIE_SMITH) {
    /* Estevez and Kulla 2017: height-correlated 1/(1 + Lambda_i + Lambda_o) with their fitted
     * Lambda (ndf.h charlie_lambda), times ni/ni as smith-correlated */
    g = ni / (ni * no + no * ndf_cLambda(NDF_CHARLIE, p, ni, s2i) + ni * clo);
  } else if (gaf == GAF_SCHLICK_BECKMANN || gaf == GAF_SCHLICK_GGX || gaf == GAF_SCHLICK_GGX_DIRECT) {
    /* Schlick 1994: g(x) = x/(x(1-k)+k); G = g(n.i) g(n.o) */
    param_t k = p.k;
    g = ni / ((ni * (RC(1.0) - k) + k) * (no * (RC(1.0) - k) + k)); /* one division per node */
  } else if (ndf == NDF_GGX && (gaf == GAF_SMITH || gaf == GAF_SMITH_EXACT || gaf == GAF_SMITH_CORRELATED ||
                                gaf == GAF_SMITH_CORRELATED_EXACT)) {
    /* The Smith forms below with GGX's c Lambda(i) = x/(2q) (ggx_cLambda_q; its exact Lambda is the
     * same) and q multiplied through: one division per node instead of two.
     * With the integrand's 1/cos theta_h taken once per call too (integrand.h), one lane division
     * per node measured faster than three (docs/performance.md, "Kernel choices") */
    real x;
    real q = ggx_cLambda_q(p, ni, s2i, &x);
    if (gaf == GAF_SMITH || gaf == GAF_SMITH_EXACT)
      g = ni * q / ((ni * q + RC(0.5) * x) * (no + clo));
    else
      g = ni * q / (ni * q * (no + clo) + RC(0.5) * no * x);
  } else if (gaf == GAF_SMITH) {
    /* separable Smith: G1(i) G1(o), G1(v)/(n.v) = 1/(n.v + n.v Lambda(v)) */
    g = ni / ((ni + ndf_cLambda(ndf, p, ni, s2i)) * (no + clo));
  } else if (gaf == GAF_SMITH_EXACT) {
    g = ni / ((ni + ndf_cLambda_exact(ndf, p, ni, s2i)) * (no + clo));
  } else if (gaf == GAF_SMITH_CORRELATED_EXACT) {
    g = ni / (ni * no + no * ndf_cLambda_exact(ndf, p, ni, s2i) + ni * clo);
  } else {
    /* height-correlated Smith (Heitz 2014): 1/(1 + Lambda_i + Lambda_o), times ni/ni */
    g = ni / (ni * no + no * ndf_cLambda(ndf, p, ni, s2i) + ni * clo);
  }
  /* chi+: nothing where i is below the surface or h faces away from o (selected, not branched,
   * so that the same code serves one value and a lane vector) */
  return (ni <= RC(0.0) || oh <= RC(0.0)) ? RC(0.0) : g;
}

BRDF_FN real gaf_G(int gaf, int ndf, BrdfParams p, real ni, param_t no, real nh, real oh, real s2i, param_t s2o) {
  return no * gaf_G_over_no(gaf, ndf, p, ni, no, nh, oh, s2i, s2o);
}

#ifndef BRDF_LANE_PASS
/* Whether the pair's Lambda is the tabulated exact one (smith_tables.h): blinn-phong and the
 * gaussian with smith-exact or smith-correlated-exact (ggx's and beckmann's are closed forms). */
BRDF_FN int gaf_lambda_tabulated(int ndf, int gaf) {
  return (gaf == GAF_SMITH_EXACT || gaf == GAF_SMITH_CORRELATED_EXACT) &&
         (ndf == NDF_BLINN_PHONG || ndf == NDF_GAUSSIAN);
}

/* The GAF that computes the same G for this NDF: ggx's and beckmann's exact Smith Lambda is their
 * closed form (ndf_cLambda_exact returns ndf_cLambda), so smith-exact is smith and
 * smith-correlated-exact is smith-correlated there, to the bit (the same operations). A bake
 * that holds both computes the model once (host/cl/runner.h setReuse). */
BRDF_FN int gaf_canonical(int ndf, int gaf) {
  if (ndf != NDF_GGX && ndf != NDF_BECKMANN) return gaf;
  if (gaf == GAF_SMITH_EXACT) return GAF_SMITH;
  if (gaf == GAF_SMITH_CORRELATED_EXACT) return GAF_SMITH_CORRELATED;
  return gaf;
}

/* Where G has a kink as a function of the azimuth phi of h (fixed theta_h), as values of cos(phi).
 * The integrators split their phi panels there so Gauss rules see only smooth pieces.
 * With o = (s, 0, mu) and h at (theta, phi): o.h = s sin cos(phi) + mu c, n.i = 2 (o.h) c - mu.
 *   n.i = n.o          <=> o.h = mu/c                      (neumann, cook-torrance)
 *   2 c mu = o.h       <=> cook-torrance's masking term reaches 1
 *   2 c n.i = o.h      <=> o.h (4c^2 - 1) = 2 c mu (shadowing term reaches 1)
 *   n.i = 1/2          <=> o.h = (1/2 + mu)/(2 c)          (charlie-smith: the fitted Lambda
 *     switches branch at cos = 1/2, ndf.h charlie_lambda; continuous with its slope, its second
 *     derivative jumps)
 * Returns the number of kinks written to cosphi[] (at most 3). */
BRDF_FN int gaf_kinks(int gaf, real mu, real s, real c, real sn, real* cosphi) {
  int n = 0;
  if (gaf != GAF_NEUMANN && gaf != GAF_COOK_TORRANCE && gaf != GAF_CHARLIE_SMITH) return 0;
  if (s <= RC(0.0) || sn <= RC(0.0) || c <= RC(0.0)) return 0;
  real inv = RC(1.0) / (s * sn);
  if (gaf == GAF_CHARLIE_SMITH) {
    cosphi[n++] = ((RC(0.5) + mu) / (RC(2.0) * c) - mu * c) * inv;
    return n;
  }
  cosphi[n++] = (mu / c - mu * c) * inv;
  if (gaf == GAF_COOK_TORRANCE) {
    cosphi[n++] = (RC(2.0) * c * mu - mu * c) * inv;
    real q = RC(4.0) * c * c - RC(1.0);
    if (q > RC(0.0)) cosphi[n++] = (RC(2.0) * c * mu / q - mu * c) * inv;
  }
  return n;
}

/* The theta_h at which the phi-integral itself is singular in theta_h, so the outer quadrature
 * splits there too (and substitutes beside them: hemisphere.h). First where a kink of gaf_kinks
 * enters or leaves the phi range (cos phi = +-1); the piece between kink and range end then grows
 * like sqrt(theta_h - theta_b), and the integral like its 3/2 power.
 * With t = tan theta_h and theta_o the view angle (tan theta_o = s/mu):
 *   n.i = n.o:        tan theta_h = s/mu                         => theta_h = theta_o
 *   masking = 1:      s t = mu                                    => theta_h = pi/2 - theta_o
 *   shadowing = 1:    (mu +- s t)(3 - t^2) = 2 mu (1 + t^2), i.e. tan 3 theta_h = -+ mu/s
 *                                                                 => theta_h = (pi/2 +- theta_o)/3
 * Then cook-torrance's triple point: its three kink curves o.h = mu/c, o.h = 2 c mu and
 * o.h (4 c^2 - 1) = 2 c mu meet where c^2 = 1/2, theta_h = pi/4, at cos phi = mu/s: on the arc
 * for views mu < s (theta_o > pi/4); there the branch of the min between them changes. Without
 * this break, the panel holding pi/4 missed by up to 1.3e-6 of the value (ggx, mu = 0.51, r = 1),
 * with it by 4e-10 (double, against the reference).
 * charlie-smith's n.i = 1/2: i lies in the plane of o at angle 2 theta_h - theta_o from n at
 * phi = 0 and 2 theta_h + theta_o at phi = pi, so theta_h = (theta_o +- pi/3)/2 and
 * (pi/3 - theta_o)/2. Its kink is C1, so the phi integral goes as a 5/2 power there. Without
 * these breaks (and the kink in phi) the charlie-smith albedo at the default budget was off by up
 * to 5.5e-7 of the value (mu = 0.7, r = 1), and 4 times its rescaled estimate (mu = 1, r = 0.8,
 * where the kink is the circle theta_h = pi/6); with them by 1.1e-7 (double, against
 * host/reference/sheen_reference.cpp, 11 r x 13 mu).
 * Writes tan^2 of each to t2[] (at most 5) and returns the count. */
#define GAF_MAX_THETA_BREAKS 5
BRDF_FN int gaf_theta_breaks(int gaf, real mu, real s, real* t2) {
  if (gaf != GAF_NEUMANN && gaf != GAF_COOK_TORRANCE && gaf != GAF_CHARLIE_SMITH) return 0;
  real th_o = atan2(s, mu);
  real half_pi = RC(0.5) * BRDF_PI;
  real th[GAF_MAX_THETA_BREAKS] = {RC(0.0)}; /* (GCC cannot see that only th[0 .. n) is read) */
  int n = 0;
  if (gaf == GAF_CHARLIE_SMITH) {
    real third = BRDF_PI / RC(3.0);
    th[n++] = RC(0.5) * (th_o + third);
    th[n++] = RC(0.5) * (th_o - third);
    th[n++] = RC(0.5) * (third - th_o);
  } else {
    th[n++] = th_o;
  }
  if (gaf == GAF_COOK_TORRANCE) {
    th[n++] = half_pi - th_o;
    th[n++] = (half_pi + th_o) / RC(3.0);
    th[n++] = (half_pi - th_o) / RC(3.0);
    if (mu < s) th[n++] = RC(0.5) * half_pi;
  }
  int m = 0;
  for (int k = 0; k < n; ++k) {
    if (th[k] > RC(0.0) && th[k] < half_pi) {
      real t = tan(th[k]);
      t2[m++] = t * t;
    }
  }
  return m;
}

/* Whether the phi-integral has a square-root end at theta_h = 0 (v = 0): neumann's max(n.i, n.o)
 * switches where n.i - n.o = 2 sn (s c cos phi - mu sn) changes sign, and the part of the circle on
 * either side differs by O(sn) = O(sqrt(v)) near h = n (cook-torrance's min is 1 there). Missed
 * without the substitution: 2.3e-6 of the value (ggx, mu = 0.82, r = 0.32); with it 1.4e-8. */
BRDF_FN int gaf_root_at_normal(int gaf) { return gaf == GAF_NEUMANN; }

/* Whether G is singular (not analytic) at i's horizon, n.i -> 0: charlie-smith, whose fitted
 * Lambda(x) = exp(a/(1 + b x^c) + d x + e) with c = 0.17 to 0.20 (ndf.h charlie_L) makes G a
 * function of x^c there. The azimuth arc's last panel, which ends at n.i = 0, substitutes
 * phi = phimax - L (1 - y)^2 (azimuth.h). Without it the charlie-smith albedo missed by up to
 * 8e-8 of the value at the default budget and 5.5e-8 at the refined one (r = 1/256, mu = 1/256 to
 * 0.01, where n.i stays in the x^c layer over much of the arc), with it by 3e-12. */
BRDF_FN int gaf_root_at_horizon(int gaf) { return gaf == GAF_CHARLIE_SMITH; }

/* Whether (G/n.o) (o.h) is a polynomial in n.i and o.h on each piece between the kinks of
 * gaf_kinks: none (1/n.o), implicit (n.i), neumann (n.i/n.o or 1), cook-torrance (o.h, 2 c n.o or
 * 2 c n.i, over n.o). Both are linear in cos(phi), so with a polynomial weight (Schlick's, F82's)
 * the azimuth integrand is a polynomial of degree <= 8 in cos(phi) on each piece, which GK15
 * integrates to rounding on any arc of length <= pi: nothing changes on the scale n.i ~ mu at i's
 * horizon and the arcs need no grading there (azimuth.h hemi_phi). */
BRDF_FN int gaf_polynomial_arc(int gaf) {
  return gaf == GAF_NONE || gaf == GAF_IMPLICIT || gaf == GAF_NEUMANN || gaf == GAF_COOK_TORRANCE;
}

/* Whether H = (G/n.o) F (o.h)/(n.h) stays large at i's horizon on the scale of the view's own
 * cut: `none` (G/n.o = 1/n.o) and kelemen (1/(o.h)^2, with o.h = mu/(2 c) at the horizon). Where
 * mu << alpha, the arc of h with n.i > 0 shrinks from the whole circle (theta_h <= theta_1, tan
 * theta_1 = mu/(1 + s)) to two thirds of it at tan theta_h = 2 tan theta_1 (cos phi_max = -1/2 for
 * small mu) and to half further out, a layer the outer panels
 * must resolve (hemisphere.h grades them from there); where H vanishes with n.i (every other GAF)
 * that layer carries little. */
BRDF_FN int gaf_horizon_layer(int gaf) { return gaf == GAF_NONE || gaf == GAF_KELEMEN; }

/* The views mu at which the average albedo's rule over mu splits: where two of gaf_theta_breaks
 * coincide in theta_h, or one meets the visible domain's limits theta_1,2 = (pi/2 -+ theta_o)/2
 * (hemisphere.h). neumann: theta_o = theta_1 at theta_o = pi/6. cook-torrance: theta_o = pi/4
 * (four breaks and the triple point at once), pi/8 ((pi/2 - theta_o)/3 = theta_o), pi/6
 * (theta_o = theta_1, pi/2 - theta_o = theta_2) and pi/10 ((pi/2 + theta_o)/3 = theta_1).
 * E(mu) is surely singular where two features meet at the same (theta_h, phi): cook-torrance's
 * pi/4 and pi/6 (both at phi = 0). The others pair a feature at phi = 0 with one at phi = pi and
 * may be smooth; splitting there costs one panel each, and is what was measured: without any
 * split the rescaled bound of cook-torrance's E_avg missed by 4.1e-7 (ggx, r = 1) and neumann's
 * by 1.5e-8 (r = 0.17), with them by at most 5.2e-10 (tests/tables/microfacet/avg_rule_test.cpp).
 * charlie-smith: the view's own Lambda switches branch at mu = 1/2 (E(mu) has a kink there), and
 * its theta breaks meet theta_1 at theta_o = pi/12 ((theta_o + pi/3)/2 = (pi/2 - theta_o)/2) and
 * 5 pi/12 ((theta_o - pi/3)/2 = theta_1). Measured against the sheen reference (E_avg by
 * Gauss-Legendre 20 and 30 on panels graded towards mu = 0 and split at 1/2, agreeing to 4e-9),
 * 8 r from 1/64 to 1: with the splits the rescaled rule is off by at most 1.1e-9 of E_avg, without
 * them by up to 4.8e-8, at times beyond its bound.
 * Writes them to mu[] (at most 4, ascending) and returns the count. */
#define GAF_MAX_VIEW_BREAKS 4
BRDF_FN int gaf_view_breaks(int gaf, real* mu) {
  if (gaf == GAF_CHARLIE_SMITH) {
    mu[0] = RC(0.25881904510252076235); /* cos(5 pi/12) */
    mu[1] = RC(0.5);                    /* cos(pi/3) */
    mu[2] = RC(0.96592582628906828675); /* cos(pi/12) */
    return 3;
  }
  if (gaf == GAF_NEUMANN) {
    mu[0] = RC(0.86602540378443864676); /* cos(pi/6) */
    return 1;
  }
  if (gaf != GAF_COOK_TORRANCE) return 0;
  mu[0] = RC(0.70710678118654752440); /* cos(pi/4) */
  mu[1] = RC(0.86602540378443864676); /* cos(pi/6) */
  mu[2] = RC(0.92387953251128675613); /* cos(pi/8) */
  mu[3] = RC(0.95105651629515357212); /* cos(pi/10) */
  return 4;
}
#endif /* !BRDF_LANE_PASS */
#endif /* BRDF_GAF_H */
