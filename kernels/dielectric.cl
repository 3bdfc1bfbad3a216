/* dielectric.cl: the rough dielectric's albedos (kernels/integrate/dielectric.h), one texel or one
 * quadrature node per work-item, no barriers. Its program is its own (host/cl/programs.cpp): this
 * file and what it includes, with `real` = double where the device has cl_khr_fp64.
 * The eta of each slice comes from the host (computed in double from the axis coordinate). */
#include "integrate/dielectric.h"

/* Coordinate of sample i of n on [0, 1]: texel centres (i + 0.5)/n, or nodes i/(n - 1). */
static inline real diel_grid(int i, int n, int node_grid) {
  return node_grid ? (n > 1 ? (real)i / (real)(n - 1) : RC(0.0)) : ((real)i + RC(0.5)) / (real)n;
}

/* One slab of the 3D table: slices z0 .. z0 + zn - 1, x = mu, y = r; planes E_R, E_T and the
 * bound one after another, [((c * zn + z - z0) * ny + y) * nx + x]. The bound is the two lobes'
 * estimates summed: it covers E_R, E_T and E_R + E_T (the table's third channel), all <= 1, so
 * absolute and relative to max(1, |value|) coincide.
 * etas[z - z0]: the slice's eta. */
kernel void bake_dielectric(global float* out, global const real* etas, int nx, int ny, int zn, int node_grid,
                            float target) {
  int x = get_global_id(0), yz = get_global_id(1);
  if (x >= nx || yz >= ny * zn) return;
  int y = yz % ny, zl = yz / ny;
  DielResult d =
      diel_texel(BRDF_NDF, BRDF_GAF, diel_grid(x, nx, node_grid), diel_grid(y, ny, node_grid), etas[zl], (real)target);
  size_t plane = (size_t)nx * ny * zn, at = ((size_t)zl * ny + y) * nx + x;
  out[at] = (float)d.er;
  out[plane + at] = (float)d.et;
  out[2 * plane + at] = (float)(d.err_r + d.err_t);
}

/* Points (mu[k], r[k], eta[k]), k < n: the averages' nodes (host/bake/dielectric_avg.cpp chooses them
 * per (r, eta)); planes E_R, E_T, E_R's bound, E_T's bound (absolute) one after another, [c * n + k],
 * as `real`: the host forms the averages from the nodes unrounded, so only the stored entries round. */
kernel void bake_dielectric_points(global real* out, global const real* mus, global const real* rs,
                                   global const real* etas, int n, float target) {
  int k = get_global_id(0);
  if (k >= n) return;
  DielResult d = diel_texel(BRDF_NDF, BRDF_GAF, mus[k], rs[k], etas[k], (real)target);
  out[k] = d.er;
  out[n + k] = d.et;
  out[2 * n + k] = d.err_r;
  out[3 * n + k] = d.err_t;
}
