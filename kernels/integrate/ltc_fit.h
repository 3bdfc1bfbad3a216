/* ltc_fit.h: fitting an LTC (brdf/ltc.h) to a cosine-weighted BRDF lobe, and the fit's distance.
 *
 * The lobe. For a view v = (sin theta_v, 0, mu), the normalised cosine-weighted lobe is
 *   p(w) = f(v, w) max(0, w_z) / E(mu),   E = int f(v, w) max(0, w_z) dw,
 * with f the specular lobe of the prelude's pair at F = 1 (brdf/brdf.h) or a diffuse model (rho =
 * 1).
 * E comes from the host (the integrators' exact value), so that p integrates to 1 up to E's claim.
 *
 * The distance. The fit's error is the total-variation distance
 *   TV = 1/2 int_S2 |p(w) - D(w)| dw,
 * over the whole sphere, so that the LTC's mass below the horizon counts (p is 0 there). For any
 * set A of directions (a polygon light, clipped or not), |int_A p - int_A D| <= TV: TV bounds the
 * shading integral's error as a fraction of the lobe's magnitude E, whatever the light.
 *
 * Estimator. Multiple importance sampling with the balance heuristic (Veach 1997, sec. 9.2.1) over
 * three strategies, n_s points each: the lobe's own (for microfacet NDFs the GGX visible normals of
 * the lobe's alpha reflected about v, Heitz 2018, "Sampling the GGX Distribution of Visible
 * Normals", pdf G1(v) D(h)/(4 mu); for charlie its half-vectors, ltc_pdf_sheen; none for diffuse
 * lobes), the clamped cosine (pdf w_z/pi), and the LTC itself (pdf D). Point k of strategy s
 * contributes
 *   |p - D|(w_k) / sum_s' n_s' pdf_s'(w_k),
 * and the sum over all points estimates int |p - D|. The D part of each term is at most 1/n_D and
 * the p part at most p/(n_v pdf_v + n_c pdf_c): bounded for every lobe here, so the estimate's
 * spread shrinks like a bounded integrand's. Points are a rank-1 lattice (k/n, frac(k g)), g the
 * golden ratio's fractional part, shifted modulo 1 (Cranley and Patterson 1976): R hashed shifts
 * give
 * R independent estimates whose mean is the distance and whose spread its error estimate (ltc_tv).
 *
 * The fit. Nelder and Mead 1965 on (log m11, log m22, m13, phi) minimising TV on the unshifted
 * lattice (a smooth objective in M: the LTC's own points move with M, continuously; the others' p
 * computed once, LtcFixed), restarted once from its best vertex with a smaller simplex. The start
 * is the best of the candidates the kernel is given
 * (the neighbouring texels' fits) and of a cosine about the lobe's mean direction.
 */
/* Once per pass (compat.h "Passes"). */
#if defined(BRDF_SECOND_PASS) ? !defined(BRDF_LTC_FIT_H_2) : !defined(BRDF_LTC_FIT_H)
#ifdef BRDF_SECOND_PASS
#define BRDF_LTC_FIT_H_2
#else
#define BRDF_LTC_FIT_H
#endif
#include "brdf/brdf.h"
#include "brdf/ltc.h"
#ifndef BRDF_LANE_PASS

#define LTC_GOLDEN RC(0.61803398874989484820)
/* the smallest alpha fitted: a mirror has no LTC; the 2016 table's r = 0 row is at alpha = 1e-5 too
 * (its texel at mu = 1 stores M^-1 = diag(1, 1, 2e-5)) */
#define LTC_MIN_ALPHA RC(1e-5)
#define LTC_LOBE_SPECULAR 0
#define LTC_LOBE_DIFFUSE 1

/* One texel's lobe: the view, the material and the magnitude E. */
typedef struct LtcLobe {
  int kind; /* LTC_LOBE_SPECULAR (the prelude's pair) or LTC_LOBE_DIFFUSE */
  BrdfMaterial m;
  real vx, vz;         /* v = (sin theta_v, 0, mu) */
  real alpha;          /* the visible-normal proposal's alpha (0: none) */
  real sheen_k;        /* the charlie proposal's exponent 1/alpha (0: none) */
  real g1_over_mu;     /* G1(v)/mu of GGX at that alpha, finite at mu = 0 */
  real inv_e;          /* 1/E */
  float col[SMITH_NZ]; /* the tabulated exact Lambda's column at this alpha (ltc_lobe_view) */
} LtcLobe;

/* The lobe of texel (mu, r): the pair's specular lobe at F = 1, or diffuse model `diffuse` with
 * parameter dparam; inv_kp for the gaussian (from the host, else 0). */
BRDF_FN LtcLobe ltc_lobe(int kind, int ndf, int gaf, int diffuse, real mu, real r, real dparam, real inv_kp, real e) {
  LtcLobe L;
  L.kind = kind;
  real rr = fmax(r, sqrt(LTC_MIN_ALPHA));
  L.m.ndf = ndf;
  L.m.gaf = gaf;
  L.m.p = brdf_params_kp(gaf, rr, inv_kp);
  L.m.fresnel = FRESNEL_ONE;
  L.m.diffuse = kind == LTC_LOBE_DIFFUSE ? diffuse : -1;
  L.m.dparam = dparam;
  L.vz = fmin(fmax(mu, RC(0.0)), RC(1.0));
  L.vx = sqrt(fmax((RC(1.0) - L.vz) * (RC(1.0) + L.vz), RC(0.0)));
  /* the sheen NDF's lobe is not a GGX-like peak: the cosine and the LTC's own points cover it */
  L.alpha = (kind == LTC_LOBE_SPECULAR && !(ndf == NDF_CHARLIE)) ? L.m.p.alpha : RC(0.0);
  /* GGX G1(v)/mu = 2/(mu + sqrt(mu^2 + alpha^2 (1 - mu^2))) (Smith's Lambda for GGX, Walter et al. 2007) */
  L.g1_over_mu = RC(2.0) / (L.vz + sqrt(L.vz * L.vz + L.alpha * L.alpha * L.vx * L.vx));
  L.sheen_k = (kind == LTC_LOBE_SPECULAR && ndf == NDF_CHARLIE) ? RC(1.0) / L.m.p.alpha : RC(0.0);
  L.inv_e = e > RC(0.0) ? RC(1.0) / e : RC(0.0);
  return L;
}

/* The view's GAF term and the exact Lambda's column, set once for the texel (as the integrators'
 * hemi_view does): p then evaluates Lambda at the light's direction only. Call it on the lobe
 * where it
 * stays (smith_col points into L->col). Setting them per evaluation instead made the fit measurably
 * slower, most for the exact Lambda (docs/performance.md, "Kernel choices"). */
BRDF_FN void ltc_lobe_view(LtcLobe* L) {
  if (L->kind != LTC_LOBE_SPECULAR) return;
  if (gaf_lambda_tabulated(L->m.ndf, L->m.gaf)) L->m.p.smith_col = smith_column(L->m.ndf, L->m.p, L->col);
  L->m.p.view_cl = gaf_view_cLambda(L->m.gaf, L->m.ndf, L->m.p, L->vz, L->vx * L->vx);
  L->m.p.has_view = 1;
}

/* p(w) of the lobe at a unit direction w. */
BRDF_FN real ltc_lobe_p(const LtcLobe* L, real x, real y, real z) {
  if (z <= RC(0.0)) return RC(0.0);
  BrdfGeometry g;
  g.ni = z;
  g.no = L->vz;
  g.s2i = x * x + y * y;
  g.s2o = L->vx * L->vx;
  real hx = x + L->vx, hy = y, hz = z + L->vz;
  real len2 = hx * hx + hy * hy + hz * hz;
  if (len2 > RC(1e-20)) {
    real len = sqrt(len2);
    g.nh = hz / len;
    g.s2h = (hx * hx + hy * hy) / len2;
    g.oh = RC(0.5) * len;
  } else {
    g.nh = RC(1.0);
    g.s2h = RC(0.0);
    g.oh = RC(0.0);
  }
  real sio = sqrt(g.s2i * g.s2o);
  g.cphi = sio > RC(0.0) ? (x * L->vx) / sio : RC(1.0);
  real f;
  if (L->kind == LTC_LOBE_DIFFUSE) {
    real ni = fmax(z, BRDF_MIN_COS), no = fmax(L->vz, BRDF_MIN_COS);
    f = diffuse_f(L->m.diffuse, L->m.dparam, ni, sqrt(g.s2i), no, L->vx, g.cphi);
  } else {
    f = brdf_f(L->m, g, RC(0.0), RC(0.0), RC(0.0));
  }
  return f * z * L->inv_e;
}

/* The visible-normal proposal's pdf at w: G1(v) D(h)/(4 mu) for h = (v + w)/|v + w| in v's hemisphere. */
BRDF_FN real ltc_pdf_vndf(const LtcLobe* L, real x, real y, real z) {
  real hx = x + L->vx, hy = y, hz = z + L->vz;
  real len2 = hx * hx + hy * hy + hz * hz;
  if (len2 <= RC(1e-20) || hz <= RC(0.0)) return RC(0.0);
  real c2 = hz * hz / len2, s2 = (hx * hx + hy * hy) / len2;
  real a2 = L->alpha * L->alpha;
  real den = c2 * a2 + s2;
  real d = a2 / (BRDF_PI * den * den);
  return L->g1_over_mu * d * RC(0.25);
}

/* A reflected visible normal of GGX at the lobe's alpha from (u1, u2) (Heitz 2018, sec. 3: the
 * visible hemisphere of the stretched view, its projected disk warped toward the view). */
BRDF_FN void ltc_sample_vndf(const LtcLobe* L, real u1, real u2, real* out) {
  real a = L->alpha;
  /* the stretched view (a vx, 0, vz); y is the view plane's normal, so T1 = (0, 1, 0) */
  real sx = a * L->vx, sz = L->vz, sl = sqrt(sx * sx + sz * sz);
  sx /= sl;
  sz /= sl;
  real rad = sqrt(u1), ph = RC(2.0) * BRDF_PI * u2;
  real t1 = rad * cos(ph), t2 = rad * sin(ph);
  real s = RC(0.5) * (RC(1.0) + sz);
  t2 = (RC(1.0) - s) * sqrt(fmax(RC(1.0) - t1 * t1, RC(0.0))) + s * t2;
  real tn = sqrt(fmax(RC(1.0) - t1 * t1 - t2 * t2, RC(0.0)));
  /* N = t1 T1 + t2 T2 + tn V, T1 = (0, 1, 0), T2 = V x T1 = (-sz, 0, sx) */
  real nx = -t2 * sz + tn * sx, ny = t1, nz = t2 * sx + tn * sz;
  real hx = a * nx, hy = a * ny, hz = fmax(nz, RC(0.0));
  real hl = sqrt(hx * hx + hy * hy + hz * hz);
  hx /= hl;
  hy /= hl;
  hz /= hl;
  real vh = L->vx * hx + L->vz * hz;
  out[0] = RC(2.0) * vh * hx - L->vx;
  out[1] = RC(2.0) * vh * hy;
  out[2] = RC(2.0) * vh * hz - L->vz;
}

/* The charlie proposal: half-vectors with density D(h) (n.h) (Estevez and Kulla 2017's D =
 * (2 + k) sin^k(theta_h)/(2 pi), k = 1/alpha: the CDF of theta_h is sin^(k+2), so sin theta_h =
 * u1^(1/(k+2))), reflected about v; the reflection's pdf is D(h) (n.h)/(4 |v.h|), h the upper
 * half-vector of (v, w). Without it the cosine alone meets the lobe's sliver at small alpha once in
 * thousands of points (a 16^2 table's distance estimate read 1.5 at r = 0). */
BRDF_FN real ltc_pdf_sheen(const LtcLobe* L, real x, real y, real z) {
  real hx = x + L->vx, hy = y, hz = z + L->vz;
  real len2 = hx * hx + hy * hy + hz * hz;
  if (len2 <= RC(1e-20)) return RC(0.0);
  real len = sqrt(len2);
  if (hz < RC(0.0)) len = -len;
  hx /= len;
  hy /= len;
  hz /= len;
  real s2 = fmax(RC(1.0) - hz * hz, RC(0.0));
  real d = (RC(2.0) + L->sheen_k) * exp(RC(0.5) * L->sheen_k * log(fmax(s2, RC(1e-30)))) / (RC(2.0) * BRDF_PI);
  real vh = fabs(L->vx * hx + L->vz * hz);
  return vh > RC(0.0) ? d * hz / (RC(4.0) * vh) : RC(0.0);
}
BRDF_FN void ltc_sample_sheen(const LtcLobe* L, real u1, real u2, real* out) {
  real st = exp(log(fmax(u1, RC(1e-30))) / (L->sheen_k + RC(2.0)));
  real ct = sqrt(fmax(RC(1.0) - st * st, RC(0.0))), ph = RC(2.0) * BRDF_PI * u2;
  real hx = st * cos(ph), hy = st * sin(ph), hz = ct;
  real vh = L->vx * hx + L->vz * hz;
  out[0] = RC(2.0) * vh * hx - L->vx;
  out[1] = RC(2.0) * vh * hy;
  out[2] = RC(2.0) * vh * hz - L->vz;
}

/* The lobe's own proposal: visible normals, or charlie's half-vectors; whether it has one. */
BRDF_FN int ltc_has_lobe_proposal(const LtcLobe* L) { return L->alpha > RC(0.0) || L->sheen_k > RC(0.0); }
BRDF_FN real ltc_pdf_lobe(const LtcLobe* L, real x, real y, real z) {
  return L->alpha > RC(0.0) ? ltc_pdf_vndf(L, x, y, z) : ltc_pdf_sheen(L, x, y, z);
}
BRDF_FN void ltc_sample_lobe(const LtcLobe* L, real u1, real u2, real* out) {
  if (L->alpha > RC(0.0))
    ltc_sample_vndf(L, u1, u2, out);
  else
    ltc_sample_sheen(L, u1, u2, out);
}

BRDF_FN real ltc_frac(real x) { return x - floor(x); }

/* One shift's estimate of int |p - D| (and in *below, of D's mass below the horizon): n points per
 * strategy, the visible normals' left out where the lobe has no alpha. */
BRDF_FN real ltc_l1(const LtcLobe* L, Ltc l, int n, real su, real sv, real* below) {
  int nv = ltc_has_lobe_proposal(L) ? n : 0, nc = n, nq = n;
  real sum = RC(0.0), under = RC(0.0);
  real inv_n = RC(1.0) / (real)n;
  for (int strat = 0; strat < 3; ++strat) {
    int cnt = strat == 0 ? nv : n;
    for (int k = 0; k < cnt; ++k) {
      real u1 = ltc_frac(((real)k + RC(0.5)) * inv_n + su), u2 = ltc_frac((real)k * LTC_GOLDEN + sv);
      real w[3];
      if (strat == 0) {
        ltc_sample_lobe(L, u1, u2, w);
      } else if (strat == 1) {
        ltc_sample_cosine(u1, u2, w);
      } else {
        ltc_sample(l, u1, u2, w);
      }
      real p = ltc_lobe_p(L, w[0], w[1], w[2]);
      real q = ltc_D(l, w[0], w[1], w[2]);
      real den = (real)nq * q + (real)nc * fmax(w[2], RC(0.0)) * BRDF_INV_PI;
      if (nv > 0) den += (real)nv * ltc_pdf_lobe(L, w[0], w[1], w[2]);
      if (den > RC(0.0)) {
        sum += fabs(p - q) / den;
        if (w[2] < RC(0.0)) under += q / den;
      }
    }
  }
  *below = under;
  return sum;
}

/* The fit's points that do not move with M: the lobe's own and the cosine's, with p and the two
 * strategies' share of the balance heuristic's denominator, computed once per texel (the objective
 * then evaluates the BRDF at the LTC's n points only, not at 3n, which measured slower
 * (docs/performance.md, "Kernel choices")). n per strategy, at most LTC_MAX_FIXED / 2. */
#define LTC_MAX_FIXED 768
typedef struct LtcFixed {
  int count, n;
  real x[LTC_MAX_FIXED], y[LTC_MAX_FIXED], z[LTC_MAX_FIXED];
  real p[LTC_MAX_FIXED], den[LTC_MAX_FIXED];
} LtcFixed;

BRDF_FN void ltc_fixed_init(const LtcLobe* L, int n, LtcFixed* F) {
  int nv = ltc_has_lobe_proposal(L) ? n : 0;
  real inv_n = RC(1.0) / (real)n;
  F->count = 0;
  F->n = n;
  for (int strat = 0; strat < 2; ++strat) {
    int cnt = strat == 0 ? nv : n;
    for (int k = 0; k < cnt && F->count < LTC_MAX_FIXED; ++k) {
      real u1 = ((real)k + RC(0.5)) * inv_n, u2 = ltc_frac((real)k * LTC_GOLDEN);
      real w[3];
      if (strat == 0) {
        ltc_sample_lobe(L, u1, u2, w);
      } else {
        ltc_sample_cosine(u1, u2, w);
      }
      int c = F->count++;
      F->x[c] = w[0];
      F->y[c] = w[1];
      F->z[c] = w[2];
      F->p[c] = ltc_lobe_p(L, w[0], w[1], w[2]);
      real den = (real)n * fmax(w[2], RC(0.0)) * BRDF_INV_PI;
      if (nv > 0) den += (real)nv * ltc_pdf_lobe(L, w[0], w[1], w[2]);
      F->den[c] = den;
    }
  }
}

/* The fit's objective: TV on the unshifted lattice of F's n points per strategy, the same sum as
 * ltc_l1's with the fixed points' values taken from F. */
BRDF_FN real ltc_objective(const LtcLobe* L, const real* x, const LtcFixed* F) {
  Ltc l = ltc_from_params(x[0], x[1], x[2], x[3]);
  int n = F->n, nv = ltc_has_lobe_proposal(L) ? n : 0;
  real sum = RC(0.0);
  for (int c = 0; c < F->count; ++c) {
    real q = ltc_D(l, F->x[c], F->y[c], F->z[c]);
    real den = F->den[c] + (real)n * q;
    if (den > RC(0.0)) sum += fabs(F->p[c] - q) / den;
  }
  real inv_n = RC(1.0) / (real)n;
  for (int k = 0; k < n; ++k) {
    real u1 = ((real)k + RC(0.5)) * inv_n, u2 = ltc_frac((real)k * LTC_GOLDEN);
    real w[3];
    ltc_sample(l, u1, u2, w);
    real p = ltc_lobe_p(L, w[0], w[1], w[2]);
    real q = ltc_D(l, w[0], w[1], w[2]);
    real den = (real)n * (q + fmax(w[2], RC(0.0)) * BRDF_INV_PI);
    if (nv > 0) den += (real)nv * ltc_pdf_lobe(L, w[0], w[1], w[2]);
    if (den > RC(0.0)) sum += fabs(p - q) / den;
  }
  return RC(0.5) * sum;
}

/* Shift k's coordinate d in [0, 1): an integer hash (Mueller's 32-bit finaliser) of (k, d), fixed,
 * so the same input gives the same table. Shifts from a Weyl sequence (k sqrt(2), k sqrt(3)) form a
 * lattice themselves: their estimates are correlated, and at r = 1, mu = 0.56 eight of them spread
 * 3.6
 * times less than the mean's true error (against Ltc.DistanceEstimateHoldsAgainstAQuadrature's
 * quadrature). */
BRDF_FN real ltc_shift(int k, int d) {
  unsigned int h = (unsigned int)(2 * k + d + 1) * 0x9E3779B9u;
  h = ((h >> 16) ^ h) * 0x45d9f3bu;
  h = ((h >> 16) ^ h) * 0x45d9f3bu;
  h = (h >> 16) ^ h;
  return (real)(h >> 8) * RC(5.9604644775390625e-8); /* 2^-24 */
}

/* TV over `reps` independently shifted lattices of n points per strategy: the mean in out[0], the
 * error estimate in out[1], the mass below the horizon in out[2]. The estimate is four standard
 * errors of the mean (with 16 shifts, Student's t with 15 degrees of freedom puts 99.9% within 4.07
 * for normal errors) plus a tenth of the mean: a lattice of n points misses features under 1/n of a
 * proposal's mass, which the shifts' spread does not show. Measured against the reference
 * quadrature
 * (tables/ltc/ltc_reference.h) at every second row of the default 64^2 GGX fit: with four standard
 * errors alone 32 of 2048 texels were off by more (r = 10/63, mu = 0.91 by 14 standard errors, the
 * estimate 6% low); with the tenth added, every texel is within half its estimate. */
BRDF_FN void ltc_tv(const LtcLobe* L, Ltc l, int n, int reps, real* out) {
  /* Welford's running mean and sum of squared deviations: the one-pass mean of squares minus the
   * squared mean cancels in float (at 64^2, r = 24/63, mu = 0.6 the shifts' spread of 1e-6 under a
   * mean of 0.04 came out 0) */
  real mean = RC(0.0), m2 = RC(0.0), sb = RC(0.0);
  for (int k = 0; k < reps; ++k) {
    real below;
    real t = RC(0.5) * ltc_l1(L, l, n, ltc_shift(k, 0), ltc_shift(k, 1), &below);
    real d = t - mean;
    mean += d / (real)(k + 1);
    m2 += d * (t - mean);
    sb += below;
  }
  real var = m2 / (real)(reps > 1 ? reps - 1 : 1);
  out[0] = mean;
  out[1] = RC(4.0) * sqrt(fmax(var, RC(0.0)) / (real)reps) + RC(0.1) * fabs(mean);
  out[2] = sb / (real)reps;
}

/* The lobe's mean direction's angle from the normal (toward +x), from the cosine and visible-normal
 * points alone (the LTC's are not there yet). */
BRDF_FN real ltc_mean_angle(const LtcLobe* L, int n) {
  real sx = RC(0.0), sz = RC(0.0);
  int nv = ltc_has_lobe_proposal(L) ? n : 0;
  for (int strat = 0; strat < 2; ++strat) {
    int cnt = strat == 0 ? nv : n;
    for (int k = 0; k < cnt; ++k) {
      real u1 = ((real)k + RC(0.5)) / (real)n, u2 = ltc_frac((real)k * LTC_GOLDEN);
      real w[3];
      if (strat == 0) {
        ltc_sample_lobe(L, u1, u2, w);
      } else {
        ltc_sample_cosine(u1, u2, w);
      }
      real den = (real)n * fmax(w[2], RC(0.0)) * BRDF_INV_PI;
      if (nv > 0) den += (real)nv * ltc_pdf_lobe(L, w[0], w[1], w[2]);
      if (den > RC(0.0)) {
        real p = ltc_lobe_p(L, w[0], w[1], w[2]) / den;
        sx += p * w[0];
        sz += p * w[2];
      }
    }
  }
  return atan2(sx, sz);
}

#define LTC_NP 4
/* Nelder-Mead on x (LTC_NP parameters) from the simplex x + step_i e_i, at most max_evals objective
 * values (*used: how many it took); x ends at the best vertex, its value returned. Reflection 1,
 * expansion 2, contraction 1/2,
 * shrink 1/2 (the paper's coefficients). */
BRDF_FN real ltc_nelder_mead(const LtcLobe* L, real* x, const real* step, const LtcFixed* F, int max_evals, real ftol,
                             int* used) {
  real v[LTC_NP + 1][LTC_NP];
  real f[LTC_NP + 1];
  for (int i = 0; i <= LTC_NP; ++i) {
    for (int j = 0; j < LTC_NP; ++j) v[i][j] = x[j] + (i == j + 1 ? step[j] : RC(0.0));
    f[i] = ltc_objective(L, v[i], F);
  }
  int evals = LTC_NP + 1;
  while (evals < max_evals) {
    /* order: best lo, worst hi, second worst nh */
    int lo = 0, hi = 0;
    for (int i = 1; i <= LTC_NP; ++i) {
      if (f[i] < f[lo]) lo = i;
      if (f[i] > f[hi]) hi = i;
    }
    int nh = lo;
    for (int i = 0; i <= LTC_NP; ++i)
      if (i != hi && f[i] > f[nh]) nh = i;
    if (f[hi] - f[lo] <= ftol * (fabs(f[lo]) + RC(1e-12))) break;
    real c[LTC_NP], xr[LTC_NP], xe[LTC_NP];
    for (int j = 0; j < LTC_NP; ++j) {
      c[j] = RC(0.0);
      for (int i = 0; i <= LTC_NP; ++i)
        if (i != hi) c[j] += v[i][j];
      c[j] /= (real)LTC_NP;
      xr[j] = c[j] + (c[j] - v[hi][j]);
    }
    real fr = ltc_objective(L, xr, F);
    ++evals;
    if (fr < f[lo]) {
      for (int j = 0; j < LTC_NP; ++j) xe[j] = c[j] + RC(2.0) * (c[j] - v[hi][j]);
      real fe = ltc_objective(L, xe, F);
      ++evals;
      for (int j = 0; j < LTC_NP; ++j) v[hi][j] = fe < fr ? xe[j] : xr[j];
      f[hi] = fe < fr ? fe : fr;
    } else if (fr < f[nh]) {
      for (int j = 0; j < LTC_NP; ++j) v[hi][j] = xr[j];
      f[hi] = fr;
    } else {
      /* contract toward the better of the worst vertex and its reflection */
      int outside = fr < f[hi];
      for (int j = 0; j < LTC_NP; ++j) xe[j] = c[j] + RC(0.5) * ((outside ? xr[j] : v[hi][j]) - c[j]);
      real fc = ltc_objective(L, xe, F);
      ++evals;
      if (fc < (outside ? fr : f[hi])) {
        for (int j = 0; j < LTC_NP; ++j) v[hi][j] = xe[j];
        f[hi] = fc;
      } else {
        for (int i = 0; i <= LTC_NP; ++i) {
          if (i == lo) continue;
          for (int j = 0; j < LTC_NP; ++j) v[i][j] = v[lo][j] + RC(0.5) * (v[i][j] - v[lo][j]);
          f[i] = ltc_objective(L, v[i], F);
          ++evals;
        }
      }
    }
  }
  int lo = 0;
  for (int i = 1; i <= LTC_NP; ++i)
    if (f[i] < f[lo]) lo = i;
  for (int j = 0; j < LTC_NP; ++j) x[j] = v[lo][j];
  *used = evals;
  return f[lo];
}

#endif /* !BRDF_LANE_PASS */
#endif /* BRDF_LTC_FIT_H */
