/* bake.cl: one texel per work-item, no barriers. The host prepends a prelude that fixes the model
 * pair, e.g. "#define BRDF_NDF 0\n#define BRDF_GAF 10\n", so every model switch folds at compile
 * time, then compat.h, the pointwise headers twice (one value, then lanes) and the integrators:
 * kernelSource() in host/cl/runner.cpp. */
#ifndef BRDF_NDF
#error "BRDF_NDF must be defined by the prelude"
#endif
#ifndef BRDF_GAF
#error "BRDF_GAF must be defined by the prelude"
#endif

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
 * HEMI_FRESNEL with a Fresnel model and its parameters (fr_x, fr_y) gives that model's albedo in B. */
kernel void bake_hemisphere(global float* out_a, global float* out_b, global float* out_e,
                            global float* out_err, int nx, int ny, float mu_lo, float mu_hi,
                            float r_lo, float r_hi, int node_grid, int moments, int fresnel,
                            float fr_x, float fr_y, int level) {
  int i = get_global_id(0), j = get_global_id(1);
  if (i >= nx || j >= ny) return;
  float mu = grid_coord(i, nx, mu_lo, mu_hi, node_grid);
  float r = grid_coord(j, ny, r_lo, r_hi, node_grid);
  HemiResult h;
  if (level < 0) {
    h = hemisphere_texel_weighted(BRDF_NDF, BRDF_GAF, mu, r, BAKE_TARGET, moments, fresnel, fr_x, fr_y);
  } else { /* one budget everywhere (brdfbake convergence): level 0 default, 1 refined, more finer */
    BrdfParams p = hemisphere_texel_params(BRDF_NDF, BRDF_GAF, mu, r);
    p.moments = moments;
    p.fresnel = fresnel;
    p.fr_x = fr_x;
    p.fr_y = fr_y;
    h = hemisphere_moments(BRDF_NDF, BRDF_GAF, p, mu, level);
  }
  int t = j * nx + i;
  out_a[t] = (float)h.a;
  out_b[t] = (float)h.b;
  out_e[t] = (float)(h.a + h.b);
  out_err[t] = hemi_rel_error(h);
}

/* Average albedo E_avg(r), first step: E (or a Fresnel model's albedo, see bake_hemisphere) at the rule's nodes, E(AVG_MU[i], r_j) and its bound
 * (absolute), one node per work-item, out[j * AVG_NODES + i]. The host forms each r's weighted
 * sums and bound (kernels/integrate/hemisphere.h, AVG_MU). A 2D range (AVG_NODES x n) fills a
 * device as the albedo table does, where one work-item per r ran its ~100 nodes in series. */
kernel void bake_albedo_nodes(global float* out_e, global float* out_err, int n, float r_lo, float r_hi,
                              int node_grid, int moments, int fresnel, float fr_x, float fr_y) {
  int i = get_global_id(0), j = get_global_id(1);
  if (i >= AVG_NODES || j >= n) return;
  float r = grid_coord(j, n, r_lo, r_hi, node_grid);
  BrdfParams p = brdf_params(BRDF_NDF, BRDF_GAF, r);
  p.moments = moments;
  p.fresnel = fresnel;
  p.fr_x = fr_x;
  p.fr_y = fr_y;
  HemiResult h = hemisphere_moments_to(BRDF_NDF, BRDF_GAF, p, AVG_MU[i], avg_node_target(i));
  int t = j * AVG_NODES + i;
  /* E (F = 1) for the split, else the weighted moment B (a Fresnel model's albedo) */
  int split = moments == HEMI_SPLIT;
  out_e[t] = (float)(split ? h.a + h.b : h.b);
  out_err[t] = (float)(split ? h.err_a + h.err_b : h.err_b);
}

/* k_p of the NDF's raw shape over r. */
kernel void bake_kp(global float* out, global float* out_err, int n, float r_lo, float r_hi, int node_grid) {
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
kernel void bake_diffuse_albedo(global float* out_e, global float* out_err, int nx, int ny, float mu_lo,
                                float mu_hi, float p_lo, float p_hi, int node_grid, int model) {
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
