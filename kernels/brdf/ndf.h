/* ndf.h: normal distribution functions (MODELS.md "NDFs"), one verb set per model:
 *   ndf_p       raw shape p(h), peak 1 at h = n            (k_p normalises it)
 *   ndf_D       normalised D(h), integral of D (n.h) dw = 1
 *   ndf_cLambda cos(theta) * Smith Lambda: finite at grazing, so G/(n.o) never divides 0 by 0
 *   ndf_Lambda, ndf_G1, ndf_G   Smith Lambda, G1 = 1/(1+Lambda), height-correlated G2
 * plus the change of variables the integrators use (ndf_angle_v, ndf_tan2_diff, ndf_v_of_tan2).
 *
 * Angles are passed as (c, s2) = (cos theta, sin^2 theta), computed by the caller without
 * cancellation, so that near-mirror lobes (alpha = 1e-4, Blinn-Phong e = 2e8) keep full precision.
 * The model id is a compile-time constant on the device (prelude #define), so every switch folds.
 * The pointwise verbs are lane-generic (compat.h): branches only on the model id and per-texel
 * parameters, selects on values.
 */
/* Once per pass (compat.h "Passes"). */
#if defined(BRDF_SECOND_PASS) ? !defined(BRDF_NDF_H_2) : !defined(BRDF_NDF_H)
#ifdef BRDF_SECOND_PASS
#define BRDF_NDF_H_2
#else
#define BRDF_NDF_H
#endif
#include "brdf/compat.h"
#include "brdf/smith_tables.h"
#ifndef BRDF_LANE_PASS
#define NDF_GGX 0
#define NDF_BECKMANN 1
#define NDF_BLINN_PHONG 2
#define NDF_GAUSSIAN 3
/* the sheen NDF of Estevez and Kulla 2017 (MODELS.md "Sheen"): its lobe peaks at grazing h */
#define NDF_CHARLIE 4
#define NDF_COUNT 5

/* Per-texel parameters, derived once from perceptual roughness r (MODELS.md "Roughness axes"). */
typedef struct BrdfParams {
  real r;      /* perceptual roughness */
  real alpha;  /* r^2; every NDF parameter derives from it */
  real inv_kp; /* 1/k_p of the raw shape; needed by ndf_D only for the gaussian (numeric k_p) */
  real k;      /* Schlick's k for the schlick-* GAFs */
  /* The weight w(o.h) that splits the albedo integrand into two moments, B = int H w and
   * A = int H (1 - w) (kernels/integrate/integrand.h): Schlick's (1 - o.h)^5 (HEMI_SPLIT, the
   * split-sum pair), a Fresnel model (HEMI_FRESNEL: B is that Fresnel's albedo), or the F82
   * correction's shape (HEMI_F82C). */
  int moments;     /* HEMI_SPLIT, HEMI_FRESNEL, HEMI_F82C */
  int fresnel;     /* FRESNEL_* for HEMI_FRESNEL */
  real fr_x, fr_y; /* its parameters: F0 or eta; k (conductor) or b (f82-tint) */
  real fr_z;       /* eta's correction (fresnel.h fresnel_e2m1), 0 but for float etas near 1 */
  /* The view's c Lambda that the GAF uses (gaf_view_cLambda), when has_view: the estimators fix
   * the view per texel and set it once (hemi_view, integrate/integrand.h), so that gaf_G_over_no
   * does not recompute it at every node. has_view = 0: gaf_G_over_no computes it from its n.o. */
  int has_view;
  real view_cl;
  /* The tabulated exact Lambda's correction interpolated along its alpha^2 axis at this alpha
   * (smith_column, SMITH_NZ values), or 0: ndf_cLambda_exact then interpolates in both axes. */
  const float* smith_col;
} BrdfParams;
#define HEMI_SPLIT 0
#define HEMI_FRESNEL 1
#define HEMI_F82C 2

/* Angle of h on the (u -> v = -log(1-u)) grid, u = the NDF's CDF over theta_h. */
typedef struct BrdfAngle {
  real c;  /* cos theta */
  real s2; /* sin^2 theta */
  real t2; /* tan^2 theta */
} BrdfAngle;
#endif /* !BRDF_LANE_PASS */

/* Raw shapes, MODELS.md table. GGX: c^2(alpha^2-1)+1 = c^2 alpha^2 + s2 (no cancellation). */
BRDF_FN real ndf_p(int ndf, BrdfParams p, real c, real s2) {
  param_t a2 = p.alpha * p.alpha;
  real v;
  if (ndf == NDF_GGX) {
    real den = c * c * a2 + s2;
    v = (a2 / den) * (a2 / den);
  } else if (ndf == NDF_CHARLIE) {
    /* Estevez and Kulla 2017: sin(theta)^(1/alpha), peak 1 on the horizon (s2 = 1), 0 at h = n;
     * alpha = 0: 0 off the horizon. In log space: log sin = log(s2)/2. */
    if (p.alpha <= RC(0.0)) return s2 >= RC(1.0) ? RC(1.0) : RC(0.0);
    return exp(RC(0.5) / p.alpha * log(s2));
  } else if (a2 <= RC(0.0)) {
    v = RC(0.0); /* a delta at h = n: 0 off the normal */
  } else if (ndf == NDF_BECKMANN) {
    /* exp(-tan^2/alpha^2)/c^4; its limit 0 on the horizon (c = 0), where the quotient is 0/0 */
    real c2 = c * c;
    v = c2 > RC(0.0) ? exp(-s2 / (c2 * a2)) / (c2 * c2) : RC(0.0);
  } else if (ndf == NDF_BLINN_PHONG) {
    /* c^e with e = 2/alpha^2 - 2 (Walter 2007), in log space: log c = log1p(-s2)/2 */
    real e = RC(2.0) / a2 - RC(2.0);
    v = exp(e * RC(0.5) * log1p(-s2));
  } else {
    /* Torrance-Sparrow gaussian exp(-c_g^2 theta^2), c_g = 1/alpha */
    real th = atan2(sqrt(s2), c) / p.alpha;
    v = exp(-th * th);
  }
  return s2 <= RC(0.0) ? RC(1.0) : v;
}

/* Normalised D. GGX: Walter 2007 eq. 33; Beckmann: Walter eq. 25; Blinn-Phong: (e+2)/(2 pi) c^e
 * = c^e/(pi alpha^2) since (e+2)/2 = 1/alpha^2; gaussian: p/k_p. */
BRDF_FN real ndf_D(int ndf, BrdfParams p, real c, real s2) {
  param_t a2 = p.alpha * p.alpha;
  if (ndf == NDF_GGX) {
    real den = c * c * a2 + s2;
    return a2 / (BRDF_PI * den * den);
  } else if (ndf == NDF_GAUSSIAN) {
    return ndf_p(ndf, p, c, s2) * p.inv_kp;
  } else if (ndf == NDF_CHARLIE) {
    /* Estevez and Kulla 2017 eq. 2: D = (2 + 1/alpha) sin^(1/alpha)/(2 pi), i.e. p/k_p with the
     * closed-form k_p = 2 pi alpha/(1 + 2 alpha) (ndf_p_over_D_grid) */
    return (RC(2.0) + RC(1.0) / p.alpha) * ndf_p(ndf, p, c, s2) / (RC(2.0) * BRDF_PI);
  } else {
    /* Beckmann: p/(pi alpha^2); Blinn-Phong: c^e/(pi alpha^2) */
    return ndf_p(ndf, p, c, s2) / (BRDF_PI * a2);
  }
}

/* Charlie's Smith Lambda as fitted by Estevez and Kulla 2017 (section 3, table 1; the same in
 * KHR_materials_sheen's implementation notes): with t = (1 - alpha)^2 each coefficient is
 * p = t p(alpha=0) + (1 - t) p(alpha=1), L(x) = a/(1 + b x^c) + d x + e, and
 *   Lambda(cos) = exp(L(cos)) for cos < 1/2,  exp(2 L(1/2) - L(1 - cos)) above
 * (continuous at 1/2). Finite at grazing (exp(a + e), ~7.7e8 at alpha = 0), so cos Lambda -> 0 there.
 * The paper's terminator softening (Lambda^(1 + 2(1 - cos)^8) for the light) is not applied: glTF's
 * and Filament's shading do not apply it either. x^c = exp(c log x), 0 at x = 0. */
BRDF_FN real charlie_L(param_t alpha, real x) {
  param_t t = (RC(1.0) - alpha) * (RC(1.0) - alpha);
  param_t a = RC(21.5473) + t * (RC(25.3245) - RC(21.5473));
  param_t b = RC(3.82987) + t * (RC(3.32435) - RC(3.82987));
  param_t cc = RC(0.19823) + t * (RC(0.16801) - RC(0.19823));
  param_t d = RC(-1.97760) + t * (RC(-1.27393) - RC(-1.97760));
  param_t e = RC(-4.32054) + t * (RC(-4.85967) - RC(-4.32054));
  return a / (RC(1.0) + b * exp(cc * log(x))) + d * x + e;
}
BRDF_FN real charlie_lambda(param_t alpha, real c) {
  /* one L per value, its argument chosen first (lanes compute both sides of a select): two
   * transcendental calls per lane instead of eight, measured faster (docs/performance.md, "Kernel choices") */
  real l = charlie_L(alpha, c < RC(0.5) ? c : RC(1.0) - c);
  param_t lh = RC(2.0) * charlie_L(alpha, (param_t)RC(0.5));
  return exp(c < RC(0.5) ? l : lh - l);
}

/* cos(theta_v) * Lambda(v) for a direction v with cos c >= 0, sin^2 s2.
 * GGX (Heitz 2014 eq. 72): Lambda = (sqrt(1 + alpha^2 tan^2) - 1)/2, so
 *   c Lambda = (sqrt(c^2 + alpha^2 s2) - c)/2, written as a quotient to avoid cancellation.
 * Beckmann (Heitz 2014 eq. 71), a = c/(alpha sin): Lambda = (exp(-a^2)/(a sqrt(pi)) - erfc(a))/2, so
 *   c Lambda = (alpha sin exp(-a^2)/sqrt(pi) - c erfc(a))/2.
 * Blinn-Phong and the gaussian use the Beckmann Lambda with alpha = sqrt(2/(e+2)) resp. 1/c_g, which
 * both equal our alpha (MODELS.md). */
/* L(a) = 1/sqrt(pi) - a erfcx(a) for a >= 0 (erfcx(a) = exp(a^2) erfc(a)), so that the Beckmann
 * c Lambda is (alpha sin) exp(-a^2) L(a)/2 with one exp and no erfc. In float (the device): on
 * [0, 4] L = t^2 P(z), t = 1/(1 + a), z = 2.5 (t - 0.2) - 1 in [-1, 1], P of degree 12 fitted to
 * L (1 + a)^2 by least squares on Chebyshev nodes against mpmath (relative error 8.8e-9 in exact
 * arithmetic, tools/fit_polynomials.py lambda); above 4 the asymptotic series of erfc (Abramowitz and
 * Stegun 7.1.23) to 1/a^8, within 7.4e-4 of L where L exp(-a^2) a < 2e-9 of c. In double (the
 * host's reference-precision models, device programs in double) libm's erfc, as written above.
 * Faster than exp and erfc in float (docs/performance.md, "Kernel choices");
 * tests/float_forms_test.cpp holds its error. */
#ifndef BRDF_LANE_PASS
BRDF_CONST real BECKMANN_L_P[13] = {
    RC(0.56851845943975654),     RC(0.064183925545320347),   RC(-0.091686504761588697),   RC(0.022163713757722109),
    RC(0.0054156855707045374),   RC(-0.0065984713561946578), RC(0.0026617913558159866),   RC(-0.00036876549343904598),
    RC(-0.00029416865548266227), RC(0.00033866774672450619), RC(-0.00015410818099682579), RC(-2.1187884427822688e-05),
    RC(3.0550201079807072e-05)};
#endif
BRDF_FN real beckmann_cLambda(real c, real as) {
  real a = c / as;
  if (sizeof(real) == 8) return RC(0.5) * (as * exp(-a * a) / BRDF_SQRT_PI - c * erfc(a));
  real aa = fabs(a), s1 = RC(1.0) + aa;
  /* 1 + a rounds to a grid of 2^-23 whatever a's own precision. So t^2 is corrected to first
   * order: e1, the sum's rounding error, exactly (Fast2Sum, the larger operand first), and the
   * division's residual by fma. The rms error of c Lambda over a in [0, 1] falls from 9.9e-8 to
   * 6.9e-8 (tests/float_forms_test.cpp). */
  real e1 = aa < RC(1.0) ? aa - (s1 - RC(1.0)) : RC(1.0) - (s1 - aa);
  real t = RC(1.0) / s1, z = RC(2.5) * (t - RC(0.2)) - RC(1.0);
  real d = fma(-t, s1, RC(1.0)) - e1 * t; /* t (1 + d) = 1/(1 + a) */
  real poly = BECKMANN_L_P[12];
  for (int k = 11; k >= 0; --k) poly = poly * z + BECKMANN_L_P[k];
  real ia2 = RC(1.0) / (aa * aa);
  real asym = RC(0.5) / BRDF_SQRT_PI * ia2 * (RC(1.0) - ia2 * (RC(1.5) - ia2 * (RC(3.75) - RC(13.125) * ia2)));
  real l = aa > RC(4.0) ? asym : poly * (t * t) * (RC(1.0) + RC(2.0) * d);
  /* c < 0 (a direction below the surface): erfc(a) = 2 - erfc(-a) gives the same form minus c */
  return RC(0.5) * as * exp(-a * a) * l - (c < RC(0.0) ? c : RC(0.0));
}

/* GGX's c Lambda = x/(2q) in its parts: q = sqrt(c^2 + x) + c, returned, and x = alpha^2 sin^2 in *x.
 * ndf_cLambda divides them; the Smith GAFs multiply q through their own division (gaf.h). */
BRDF_FN real ggx_cLambda_q(BrdfParams p, real c, real s2, real* x) {
  param_t a2 = p.alpha * p.alpha;
  *x = a2 * s2;
  return sqrt(c * c + *x) + c;
}

BRDF_FN real ndf_cLambda(int ndf, BrdfParams p, real c, real s2) {
  if (ndf == NDF_GGX) {
    real x;
    real q = ggx_cLambda_q(p, c, s2, &x);
    return RC(0.5) * x / q;
  } else if (ndf == NDF_CHARLIE) {
    return c * charlie_lambda(p.alpha, c); /* the paper's fit (below), not an exact Smith Lambda */
  } else {
    real as = p.alpha * sqrt(s2);
    real v = beckmann_cLambda(c, as);
    return as <= RC(0.0) ? RC(0.0) : v;
  }
}

/* c Lambda with the NDF's exact Smith Lambda (MODELS.md "Exact Smith Lambda"; Smith 1967, Heitz
 * 2014 eq. 17-18): c Lambda = s F(a), F(a) = int_{q > a} (q - a) P22(q, p) dq dp, a = cot theta.
 * GGX and Beckmann: ndf_cLambda, already exact. Blinn-Phong and the gaussian: Beckmann's plus a
 * tabulated correction (kernels/brdf/smith_tables.h, generated by tools/smith_tables.cpp),
 *   c Lambda = c Lambda_beckmann + alpha^3 s V(z, alpha^2),  z = c/(c + alpha s) = b/(1 + b),
 * b = c/(alpha s) Beckmann's variable; V by 4-point Lagrange interpolation in both axes (the alpha^2
 * axis per texel, z per lane). The correction vanishes as alpha -> 0, where Beckmann's is exact. */
/* The 4-point Lagrange weights at t in [0, 3] (nodes 0, 1, 2, 3); per lane in the lane pass. */
BRDF_FN void lagrange4(real t, real* w) {
  w[0] = -(t - RC(1.0)) * (t - RC(2.0)) * (t - RC(3.0)) / RC(6.0);
  w[1] = t * (t - RC(2.0)) * (t - RC(3.0)) / RC(2.0);
  w[2] = -t * (t - RC(1.0)) * (t - RC(3.0)) / RC(2.0);
  w[3] = t * (t - RC(1.0)) * (t - RC(2.0)) / RC(6.0);
}
#ifndef BRDF_LANE_PASS
/* The alpha^2 axis's first node and weights at p.alpha. */
BRDF_FN int smith_row_weights(BrdfParams p, real* wy) {
  real y = fmin(p.alpha * p.alpha, RC(1.0));
  real uy = y * (SMITH_NY - 1);
  real fy = fmin(fmax(floor(uy) - RC(1.0), RC(0.0)), (real)(SMITH_NY - 4));
  lagrange4(uy - fy, wy);
  return (int)fy;
}
/* The correction V(z, alpha^2) interpolated along alpha^2 at p.alpha, for every z node: the
 * estimators fix alpha per texel, so each lane then interpolates in z alone (4 gathers instead
 * of 16), measured faster than without the column (docs/performance.md, "Kernel choices"). Returns col, or 0
 * where the pair's Lambda is not tabulated. */
BRDF_FN const float* smith_column(int ndf, BrdfParams p, float* col) {
  if (ndf != NDF_BLINN_PHONG && ndf != NDF_GAUSSIAN) return 0;
  BRDF_TABLE float* tab = ndf == NDF_BLINN_PHONG ? smith_tab_blinn_phong : smith_tab_gaussian;
  real wy[4];
  int fy = smith_row_weights(p, wy);
  for (int i = 0; i < SMITH_NZ; ++i) {
    real v = RC(0.0);
    for (int j = 0; j < 4; ++j) v += wy[j] * (real)tab[(fy + j) * SMITH_NZ + i];
    col[i] = (float)v;
  }
  return col;
}
#endif

BRDF_FN real ndf_cLambda_exact(int ndf, BrdfParams p, real c, real s2) {
  real beck = ndf_cLambda(ndf, p, c, s2);
  if (ndf != NDF_BLINN_PHONG && ndf != NDF_GAUSSIAN) return beck;
  param_t y = fmin(p.alpha * p.alpha, RC(1.0));
  real s = sqrt(s2);
  real den = c + p.alpha * s;
  real z = den > RC(0.0) ? c / den : RC(1.0);
  z = fmin(fmax(z, RC(0.0)), RC(1.0));
  real uz = z * (SMITH_NZ - 1);
  real fz = fmin(fmax(floor(uz) - RC(1.0), RC(0.0)), (real)(SMITH_NZ - 4));
  real wz[4];
  lagrange4(uz - fz, wz);
  real v;
  if (p.smith_col) {
    const float* col = p.smith_col;
    v = wz[0] * tab_at(col, fz) + wz[1] * tab_at(col, fz + RC(1.0)) + wz[2] * tab_at(col, fz + RC(2.0)) +
        wz[3] * tab_at(col, fz + RC(3.0));
  } else {
    BRDF_TABLE float* tab = ndf == NDF_BLINN_PHONG ? smith_tab_blinn_phong : smith_tab_gaussian;
    param_t wy[4];
    int fy = smith_row_weights(p, wy);
    v = RC(0.0);
    for (int j = 0; j < 4; ++j) {
      real k = fz + (real)((fy + j) * SMITH_NZ);
      v += wy[j] * (wz[0] * tab_at(tab, k) + wz[1] * tab_at(tab, k + RC(1.0)) + wz[2] * tab_at(tab, k + RC(2.0)) +
                    wz[3] * tab_at(tab, k + RC(3.0)));
    }
  }
  return beck + p.alpha * y * s * v;
}

BRDF_FN real ndf_Lambda(int ndf, BrdfParams p, real c, real s2) { return ndf_cLambda(ndf, p, c, s2) / c; }

/* Smith G1 = 1/(1 + Lambda) = c/(c + c Lambda). */
BRDF_FN real ndf_G1(int ndf, BrdfParams p, real c, real s2) { return c / (c + ndf_cLambda(ndf, p, c, s2)); }

/* Height-correlated Smith G2 = 1/(1 + Lambda_i + Lambda_o) (Heitz 2014 eq. 99). */
BRDF_FN real ndf_G(int ndf, BrdfParams p, real ci, real s2i, real co, real s2o) {
  return ci * co / (ci * co + co * ndf_cLambda(ndf, p, ci, s2i) + ci * ndf_cLambda(ndf, p, co, s2o));
}

/* ---- change of variables: v = -log(1 - CDF(theta_h)) ----------------------------------------
 * With u = CDF(theta) of the measure D(h)(n.h) dw_h, D sin dtheta dphi = du dphi/(2 pi cos), and
 * du = exp(-v) dv. v is the natural coordinate of each NDF's tail:
 *   GGX:         1-u = alpha^2/(alpha^2+t2)   => t2 = alpha^2 expm1(v),  v = log1p(t2/alpha^2)
 *   Beckmann:    1-u = exp(-t2/alpha^2)       => t2 = alpha^2 v,         v = t2/alpha^2
 *   Blinn-Phong: 1-u = c^(e+2) = c^(2/alpha^2) => c^2 = exp(-alpha^2 v),  v = log1p(t2)/alpha^2
 * The gaussian has no closed-form CDF: it is integrated on the GGX grid of the same alpha, with the
 * weight D_gauss/D_ggx (ndf_weight), which is bounded because GGX has the heavier tail.
 * Charlie peaks on the horizon of h and vanishes at h = n, so its coordinate counts from the other
 * end, v = -log(CDF), decreasing in theta_h. Its CDF in closed form: D (n.h) dw = (2 + 1/alpha)
 * sin^(1/alpha + 1) cos dtheta (dphi/2 pi), and with x = sin theta, dx = cos dtheta,
 *   u = int_0^sin (2 + 1/alpha) x^(1/alpha + 1) dx = sin^(2 + 1/alpha) = s2^e,  e = 1 + 1/(2 alpha)
 *   => v = -e log1p(-c^2),  c^2 = -expm1(-v/e),  s2 = exp(-v/e),  t2 = 1/expm1(v/e),  v = e log1p(1/t2)
 * and |du| = e^-v dv as for the others. v = 0 is the horizon (D's peak; 1/(n.h) there is a
 * v^(-1/2) end, which the square-root substitution at the visible limit removes), v -> inf is h = n
 * (D's tail, sin^(1/alpha) -> 0). As alpha -> 0 the lobe's width is c^2 ~ 1/e ~ 2 alpha, v ~ 1: the
 * coordinate scales with the lobe. kernels/integrate/sheen.h lays its panels out. */
#ifndef BRDF_LANE_PASS
BRDF_FN int ndf_grid_model(int ndf) { return ndf == NDF_GAUSSIAN ? NDF_GGX : ndf; }
/* Charlie's 1/e = 2 alpha/(1 + 2 alpha). */
BRDF_FN param_t ndf_charlie_inv_e(BrdfParams p) { return RC(2.0) * p.alpha / (RC(1.0) + RC(2.0) * p.alpha); }
#endif

/* The angle at v: cos, sin^2 and tan^2 of theta_h. */
BRDF_FN void ndf_angle_v(int ndf, BrdfParams p, real v, real* c, real* s2, real* t2) {
  param_t a2 = p.alpha * p.alpha;
  int g = ndf_grid_model(ndf);
  if (g == NDF_CHARLIE) {
    param_t ie = ndf_charlie_inv_e(p);
    real c2 = -expm1(-v * ie);
    *c = sqrt(c2);
    *s2 = exp(-v * ie);
    *t2 = RC(1.0) / expm1(v * ie);
  } else if (g == NDF_BLINN_PHONG) {
    real c2 = exp(-a2 * v);
    *c = sqrt(c2);
    *s2 = -expm1(-a2 * v);
    *t2 = *s2 / c2;
  } else {
    *t2 = a2 * (g == NDF_GGX ? expm1(v) : v);
    *c = RC(1.0) / sqrt(RC(1.0) + *t2);
    *s2 = *t2 / (RC(1.0) + *t2);
  }
}

/* p / D_grid, the integrand of k_p on the v grid (k_p = integral of e^-v p/D_grid dv):
 * pi alpha^2 for GGX, Beckmann and Blinn-Phong (p/D is that constant), and for the gaussian
 * p / D_ggx = p pi (c^2 alpha^2 + s2)^2 / alpha^2. Charlie: k_p = 2 pi int sin^(1/alpha + 1) cos
 * dtheta = 2 pi/(2 + 1/alpha) = 2 pi alpha/(1 + 2 alpha) (Estevez and Kulla 2017's normalisation). */
BRDF_FN real ndf_p_over_D_grid(int ndf, BrdfParams p, real c, real s2) {
  param_t a2 = p.alpha * p.alpha;
  if (ndf == NDF_CHARLIE) return RC(2.0) * BRDF_PI * p.alpha / (RC(1.0) + RC(2.0) * p.alpha);
  if (ndf != NDF_GAUSSIAN) return BRDF_PI * a2;
  real den = c * c * a2 + s2;
  return ndf_p(NDF_GAUSSIAN, p, c, s2) * BRDF_PI * (den / p.alpha) * (den / p.alpha);
}

/* D / D_grid: 1 where the grid is the NDF's own CDF, D_gauss/D_ggx for the gaussian. */
BRDF_FN real ndf_weight(int ndf, BrdfParams p, real c, real s2) {
  if (ndf != NDF_GAUSSIAN) return RC(1.0);
  return p.inv_kp * ndf_p_over_D_grid(ndf, p, c, s2);
}

/* tan^2(theta(v1 + dv)) - tan^2(theta(v1)), exact in dv (no cancellation when dv is small):
 *   GGX: alpha^2 e^{v1} expm1(dv);  Beckmann: alpha^2 dv;  Blinn-Phong: e^{alpha^2 v1} expm1(alpha^2 dv);
 *   Charlie, with A = v1/e, d = dv/e: 1/expm1(A + d) - 1/expm1(A) = -expm1(d)/(expm1(A + d) (-expm1(-A))). */
BRDF_FN real ndf_tan2_diff(int ndf, BrdfParams p, param_t v1, real dv) {
  param_t a2 = p.alpha * p.alpha;
  int g = ndf_grid_model(ndf);
  if (g == NDF_CHARLIE) {
    param_t ie = ndf_charlie_inv_e(p);
    return -expm1(dv * ie) / (expm1((v1 + dv) * ie) * -expm1(-v1 * ie));
  }
  if (g == NDF_GGX) return a2 * exp(v1) * expm1(dv);
  if (g == NDF_BECKMANN) return a2 * dv;
  return exp(a2 * v1) * expm1(a2 * dv);
}

#ifndef BRDF_LANE_PASS
BRDF_FN BrdfAngle ndf_angle_of_v(int ndf, BrdfParams p, real v) {
  BrdfAngle a;
  ndf_angle_v(ndf, p, v, &a.c, &a.s2, &a.t2);
  return a;
}

/* v of the angle with tan^2 = t2 (may be +inf: the whole tail). */
BRDF_FN real ndf_v_of_tan2(int ndf, BrdfParams p, real t2) {
  real a2 = p.alpha * p.alpha;
  int g = ndf_grid_model(ndf);
  if (g == NDF_CHARLIE) return log1p(RC(1.0) / t2) / ndf_charlie_inv_e(p); /* decreasing in t2 */
  if (a2 <= RC(0.0)) return t2 > RC(0.0) ? RC(1.0) / RC(0.0) : RC(0.0);
  if (g == NDF_GGX) return log1p(t2 / a2);
  if (g == NDF_BECKMANN) return t2 / a2;
  return log1p(t2) / a2;
}
#endif /* !BRDF_LANE_PASS */
#endif /* BRDF_NDF_H */
