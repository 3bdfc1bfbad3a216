/* bake.cl: one texel per work-item, no barriers. The host prepends a prelude that fixes the model
 * pair, e.g. "#define BRDF_NDF 0\n#define BRDF_GAF 10\n", so every model switch folds at compile
 * time, or (one program for many pairs, host/cl/runner.h) "#define BRDF_NDF sel_ndf" and the same
 * for the GAF, so that the pair is the kernels' last two arguments, then this file with what it
 * includes (host/cl/programs.cpp). The pair arguments are there in both forms (a specialised
 * program ignores them). */
#ifndef BRDF_NDF
#error "BRDF_NDF must be defined by the prelude"
#endif
#ifndef BRDF_GAF
#error "BRDF_GAF must be defined by the prelude"
#endif
#include "integrate/hemisphere_texel.h"
#include "integrate/albedo_avg.h"
#include "integrate/diffuse_albedo.h"

/* Texels whose quadrature bound exceeds this are recomputed with the refined budget: the default
 * accuracy is 1e-5 including the 1e-6 float allowance and storage rounding (host/bake). */
#define BAKE_TARGET ((float)HEMI_BAKE_TARGET)

/* Coordinate of sample i of n on [lo, hi]: texel centres (i + 0.5)/n, or nodes i/(n - 1). */
static inline float grid_coord(int i, int n, float lo, float hi, int node_grid) {
  float t = node_grid ? (n > 1 ? (float)i / (float)(n - 1) : 0.0f) : ((float)i + 0.5f) / (float)n;
  return lo + (hi - lo) * t;
}

/* The albedo's two moments over (mu, r), split by the weight w(o.h) that `moments` names (ndf.h
 * BrdfParams): A = int H (1 - w), B = int H w, E = A + B (the F = 1 albedo), and a bound on the
 * texel's largest error relative to max(1, |value|). HEMI_SPLIT gives the split-sum pair;
 * HEMI_FRESNEL with a Fresnel model and its parameters (fr_x, fr_y; fr_z: fresnel_e2m1) gives that model's albedo in B.
 * mu_list = 1: the quadrature nodes of the average albedo instead (host/cl/runner_avg.cpp): work-item
 * (i, j) takes (mu, r, refinement target) from nodes[j * nx + i], and out_e, out_err hold the value
 * the average needs (E for the split, else the weighted moment B, a Fresnel model's albedo) and its
 * absolute bound; mu_list = 2: the same with the rule's bare estimate (hemisphere_moments_chosen),
 * for the averages whose floor is measured on the average. One kernel
 * for both, with one call of the estimator, keeps the code a program compiles to one copy of it
 * (PoCL inlines every call site). */
kernel void bake_hemisphere(global float* out_a, global float* out_b, global float* out_e, global float* out_err,
                            int nx, int ny, float mu_lo, float mu_hi, float r_lo, float r_hi, int node_grid,
                            int moments, int fresnel, float fr_x, float fr_y, float fr_z, int level, int mu_list,
                            global const float4* nodes, int sel_ndf, int sel_gaf) {
  int i = get_global_id(0), j = get_global_id(1);
  if (i >= nx || j >= ny) return;
  int t = j * nx + i;
  /* node_grid bit 0: nodes, else texel centres; bit 1: the x axis is u = sqrt(mu) (mu = u^2, the
   * coordinate Unity HDRP's newer pre-integrated FGD samples), else mu itself */
  int nodes_on = node_grid & 1;
  float u = grid_coord(i, nx, mu_lo, mu_hi, nodes_on), r = grid_coord(j, ny, r_lo, r_hi, nodes_on);
  float mu = (node_grid & 2) ? u * u : u;
  float target = BAKE_TARGET;
  if (mu_list) {
    float4 q = nodes[t];
    mu = q.x;
    r = q.y;
    target = q.z;
  }
  BrdfParams p = hemisphere_texel_params(BRDF_NDF, BRDF_GAF, mu, r);
  p.moments = moments;
  p.fresnel = fresnel;
  p.fr_x = fr_x;
  p.fr_z = fr_z;
  p.fr_y = fr_y;
  /* level < 0: the bake's adaptive budget; else that one everywhere (brdfbake convergence: 0
   * default, 1 refined, more finer) */
  HemiResult h = hemisphere_moments_chosen(BRDF_NDF, BRDF_GAF, p, mu, level, target, mu_list == 2);
  out_a[t] = (float)h.a;
  out_b[t] = (float)h.b;
  if (mu_list) {
    int split = moments == HEMI_SPLIT;
    out_e[t] = (float)(split ? h.a + h.b : h.b);
    out_err[t] = (float)(split ? h.err_a + h.err_b : h.err_b);
  } else {
    out_e[t] = (float)(h.a + h.b);
    out_err[t] = hemi_rel_error(h);
  }
}

/* k_p of the NDF's raw shape over r. */
kernel void bake_kp(global float* out, global float* out_err, int n, float r_lo, float r_hi, int node_grid, int sel_ndf,
                    int sel_gaf) {
  int j = get_global_id(0);
  if (j >= n) return;
  float r = grid_coord(j, n, r_lo, r_hi, node_grid);
  BrdfParams p = brdf_params(BRDF_NDF, BRDF_GAF, r);
  float err = 0.0f;
  float v = p.alpha > 0.0f ? ndf_kp(BRDF_NDF, p, &err) : 0.0f;
  out[j] = v;
  out_err[j] = err / fmax(1.0f, fabs(v));
}

/* Directional albedo of a diffuse model (kernels/brdf/diffuse.h, DIFFUSE_*) over (mu, parameter):
 * the second axis is the model's parameter (shirley: F0, oren-nayar: sigma in radians, burley: r;
 * lambert ignores it). out_err: the bound relative to max(1, |E|). The same code in every pair's
 * program (it does not use the prelude's models). */
kernel void bake_diffuse_albedo(global float* out_e, global float* out_err, int nx, int ny, float mu_lo, float mu_hi,
                                float p_lo, float p_hi, int node_grid, int model) {
  int i = get_global_id(0), j = get_global_id(1);
  if (i >= nx || j >= ny) return;
  float mu = grid_coord(i, nx, mu_lo, mu_hi, node_grid);
  float p = grid_coord(j, ny, p_lo, p_hi, node_grid);
  float err = 0.0f;
  float e = diffuse_albedo(model, p, mu, &err);
  int t = j * nx + i;
  out_e[t] = e;
  out_err[t] = err / fmax(1.0f, fabs(e));
}
