/* ltc.cl: LTC fits (integrate/ltc_fit.h), one view angle per work-item, one roughness row per launch,
 * no barriers. Uses the prelude's pair (BRDF_NDF, BRDF_GAF) for specular lobes; diffuse lobes take
 * their model as an argument. Its program is its own (host/cl/programs.cpp), in float.
 *
 * Rows run from the roughest down (host/tables/ltc/ltc.cpp): each texel starts from the best of the
 * row above's fits at its own view and its two neighbours' (prev; has_prev = 0 on the first row)
 * and of a cosine about its lobe's mean direction, as the 2016 fit walks its table. The view axis is
 * x = sqrt(1 - mu) on nodes, x_i = i/(n - 1) (the engines' parameterisation); the host gives each view's
 * mu (mus), theta_v capped at 1.57 as the 2016 fit caps it.
 *
 * Per texel (planes of n floats each, in `out`): 0..3 the parameters (log m11, log m22, m13, phi),
 * 4..7 the stored M^-1 entries (ltc_store), 8 the distance TV, 9 its error estimate, 10 the LTC's
 * mass below the horizon, 11 the objective evaluations spent. */
#ifndef BRDF_NDF
#error "BRDF_NDF must be defined by the prelude"
#endif
#include "integrate/ltc_fit.h"

#define LTC_OUT_PLANES 12
#define LTC_RETRY_TV RC(0.1)
/* Below this magnitude a lobe carries no light worth an LTC: any LTC's shading error there is at most
 * E, so the texel states distance 1 (true of every LTC) and keeps its start. Charlie's E at r -> 0
 * away from grazing is 0 in float (sin^(1/alpha) underflows). */
#define LTC_NEGLIGIBLE_E 1e-6f

/* Nelder-Mead from x (ltc_fit.h): two rounds on the fit's points, the second from the first's best
 * with a quarter of the steps, then a polish on four times the points (the objective's own
 * quadrature error is what limits a fit to broad lobes: at r = 1 the 2016 fit is within 1e-5 of the
 * optimum). x ends at the result; returns its objective on the polish's points; *evals counts in
 * units of the fit's objective. */
static real ltc_fit_from(const LtcLobe* L, real* x, LtcFixed* F, int n_fit, int max_evals, int polish_evals,
                         int* evals) {
  /* steps: widths by 20%, the shear by a fifth of the smaller width, the angle by a tenth of the
   * width (a narrow lobe's direction matters to within its width) */
  real wmin = exp(fmin(x[0], x[1]));
  real step[LTC_NP] = {RC(0.2), RC(0.2), RC(0.2) * wmin, RC(0.1) * fmin(wmin, RC(1.0))};
  int budget = max_evals / 2, used = 0;
  if (F->n != n_fit) ltc_fixed_init(L, n_fit, F);
  ltc_nelder_mead(L, x, step, F, budget, RC(1e-3), &used);
  *evals += used;
  for (int j = 0; j < LTC_NP; ++j) step[j] *= RC(0.25);
  ltc_nelder_mead(L, x, step, F, max_evals - budget, RC(1e-5), &used);
  *evals += used;
  for (int j = 0; j < LTC_NP; ++j) step[j] *= RC(0.25);
  ltc_fixed_init(L, 4 * n_fit, F);
  real f = ltc_nelder_mead(L, x, step, F, polish_evals, RC(1e-7), &used);
  *evals += 4 * used;
  return f;
}

kernel void ltc_fit_row(global float* out, global const float* prev, global const float* mus, global const float* e,
                        global const float* in_double, int n, int has_prev, float r, float inv_kp, int kind,
                        int diffuse, float dparam, int n_fit, int max_evals, int polish_evals, int n_final, int reps) {
  int i = get_global_id(0);
  if (i >= n) return;
  real mu = (real)mus[i];
  LtcLobe L = ltc_lobe(kind, BRDF_NDF, BRDF_GAF, diffuse, mu, (real)r, (real)dparam, (real)inv_kp, (real)e[i]);
  ltc_lobe_view(&L);

  /* candidates: a cosine about the mean direction, widths from alpha (2 alpha: the reflected
   * lobe's width at normal view) or 1 for broad lobes; the row above's fits */
  real guess[LTC_NP], best[LTC_NP], cand[LTC_NP];
  real w0 = L.alpha > RC(0.0) ? log(fmin(RC(2.0) * L.alpha, RC(1.0))) : RC(0.0);
  guess[0] = w0;
  guess[1] = w0;
  guess[2] = RC(0.0);
  guess[3] = ltc_mean_angle(&L, n_fit);
  for (int j = 0; j < LTC_NP; ++j) best[j] = guess[j];
  LtcFixed F;
  ltc_fixed_init(&L, n_fit, &F);
  real fbest = ltc_objective(&L, best, &F);
  int evals = 1, from_guess = 1;
  if (has_prev) {
    for (int d = -1; d <= 1; ++d) {
      int k = i + d;
      if (k < 0 || k >= n) continue;
      for (int j = 0; j < LTC_NP; ++j) cand[j] = (real)prev[j * n + k];
      real fc = ltc_objective(&L, cand, &F);
      ++evals;
      if (fc < fbest) {
        fbest = fc;
        from_guess = 0;
        for (int j = 0; j < LTC_NP; ++j) best[j] = cand[j];
      }
    }
  }
  if (e[i] < LTC_NEGLIGIBLE_E) {
    if (has_prev)
      for (int j = 0; j < LTC_NP; ++j) best[j] = (real)prev[j * n + i];
    Ltc l0 = ltc_from_params(best[0], best[1], best[2], best[3]);
    real st0[4];
    ltc_store(l0, st0);
    for (int j = 0; j < LTC_NP; ++j) out[j * n + i] = (float)best[j];
    for (int j = 0; j < 4; ++j) out[(4 + j) * n + i] = (float)st0[j];
    out[8 * n + i] = 1.0f;
    out[9 * n + i] = 0.0f;
    out[10 * n + i] = 0.0f;
    out[11 * n + i] = (float)evals;
    return;
  }
  real fit = ltc_fit_from(&L, best, &F, n_fit, max_evals, polish_evals, &evals);
  /* a fit that ends far from its lobe (a narrow lobe cut by the horizon: r -> 0 at grazing views)
   * is tried again from the other start, and the closer kept: from the row above's fit alone, the
   * 64^2 GGX table ended at TV 0.98 at r = 0, theta_v = 1.57, against 0.45 with the second start */
  if (fit > LTC_RETRY_TV) {
    real other[LTC_NP];
    for (int j = 0; j < LTC_NP; ++j) other[j] = guess[j];
    if (from_guess) {
      if (has_prev)
        for (int j = 0; j < LTC_NP; ++j) other[j] = (real)prev[j * n + i];
      else
        other[3] = -asin(L.vx); /* the mirror direction */
    }
    real fo = ltc_fit_from(&L, other, &F, n_fit, max_evals, polish_evals, &evals);
    if (fo < fit)
      for (int j = 0; j < LTC_NP; ++j) best[j] = other[j];
  }

  Ltc l = ltc_from_params(best[0], best[1], best[2], best[3]);
  real st[4], tv[3];
  ltc_store(l, st);
  /* the distance of the LTC the table holds: its stored entries, rounded to float (near-singular
   * matrices at r = 1 moved the distance by 7e-5 between the parameters and the stored entries);
   * not for the texels the host measures in double (in_double[i] != 0: lobes too narrow for float),
   * whose distance it replaces */
  tv[0] = tv[1] = tv[2] = RC(0.0);
  if (in_double[i] == 0.0f)
    ltc_tv(&L, ltc_from_stored((float)st[0], (float)st[1], (float)st[2], (float)st[3]), n_final, reps, tv);
  for (int j = 0; j < LTC_NP; ++j) out[j * n + i] = (float)best[j];
  for (int j = 0; j < 4; ++j) out[(4 + j) * n + i] = (float)st[j];
  out[8 * n + i] = (float)tv[0];
  out[9 * n + i] = (float)tv[1];
  out[10 * n + i] = (float)tv[2];
  out[11 * n + i] = (float)evals;
}

/* The distance of given LTCs (stored entries s, as ltc_store writes them) to the lobes of a row: for
 * measuring other fits (the 2016 table) the same way. out: TV, its error estimate, mass below. */
kernel void ltc_measure_row(global float* out, global const float* stored, global const float* mus,
                            global const float* e, int n, float r, float inv_kp, int kind, int diffuse, float dparam,
                            int n_final, int reps) {
  int i = get_global_id(0);
  if (i >= n) return;
  real mu = (real)mus[i];
  LtcLobe L = ltc_lobe(kind, BRDF_NDF, BRDF_GAF, diffuse, mu, (real)r, (real)dparam, (real)inv_kp, (real)e[i]);
  ltc_lobe_view(&L);
  Ltc l = ltc_from_stored((real)stored[i], (real)stored[n + i], (real)stored[2 * n + i], (real)stored[3 * n + i]);
  real tv[3] = {RC(1.0), RC(0.0), RC(0.0)};
  if (e[i] >= LTC_NEGLIGIBLE_E) ltc_tv(&L, l, n_final, reps, tv);
  out[i] = (float)tv[0];
  out[n + i] = (float)tv[1];
  out[2 * n + i] = (float)tv[2];
}
