/* brdf3d.cl: the isotropic BRDF as a 3D table (docs/MODELS.md "Isotropic BRDF textures"), one texel
 * per work-item, no barriers. Appended after bake.cl; uses the prelude's pair (BRDF_NDF, BRDF_GAF)
 * and kernels/brdf/brdf.h.
 *
 * Axes, each sampled at a fraction t of its range (the grid convention):
 *   angles        x = theta_i in [0, pi/2], y = theta_o in [0, pi/2], z = phi_i - phi_o in [0, pi]
 *   rusinkiewicz  x = theta_h in [0, pi/2] (theta_h = pi/2 t, or pi/2 t^2: MERL's index
 *                 t = sqrt(theta_h/(pi/2))), y = theta_d in [0, pi/2], z = phi_d in [0, pi]
 * Grid: 0 texel centres t = (i + 0.5)/n, 1 nodes t = i/(n - 1), 2 cell starts t = i/n (MERL).
 *
 * Precision. Every angle is a multiple of pi, so cos and sin come from cospi/sinpi of the exact
 * grid fraction, and of its complement 1 - t formed from integers, so that cos theta near grazing
 * keeps full relative precision. Its program is its own (host/cl/runner.cpp volumeKernelSource):
 * compat.h, the models and this file, with `real` = double where the device has cl_khr_fp64 (float
 * otherwise); the texel is rounded to float once, at the end.
 */
typedef real geo_t;

/* |i + o|^2 below this: i = -o up to rounding (both directions on the horizon, opposite) */
#define BRDF3D_OPPOSITE 1e-24
#define B3_PARAM_ANGLES 0
#define B3_PARAM_RUSINKIEWICZ 1
#define B3_PARAM_RUSINKIEWICZ_SQRT 2

/* The grid fraction of sample i of n, as t and 1 - t, each one rounding from exact integers. */
static inline void b3_fraction(int i, int n, int grid, geo_t* t, geo_t* tc) {
  geo_t num, den;
  if (grid == 0) {
    num = (geo_t)(2 * i + 1);
    den = (geo_t)(2 * n);
  } else if (grid == 1) {
    num = (geo_t)i;
    den = (geo_t)(n > 1 ? n - 1 : 1);
  } else {
    num = (geo_t)i;
    den = (geo_t)n;
  }
  *t = num / den;
  *tc = (den - num) / den;
}

/* cos and sin of theta = pi/2 t, from t and its complement: cos = sin(pi/2 (1 - t)). */
static inline void b3_half_angle(geo_t t, geo_t tc, geo_t* c, geo_t* s) {
  *c = sinpi((geo_t)0.5 * tc);
  *s = sinpi((geo_t)0.5 * t);
}

/* The geometry of texel (x, y, z) as brdf.h takes it. */
static inline BrdfGeometry b3_geometry(int x, int y, int z, int nx, int ny, int nz, int param, int grid) {
  geo_t tx, txc, ty, tyc, tz, tzc;
  b3_fraction(x, nx, grid, &tx, &txc);
  b3_fraction(y, ny, grid, &ty, &tyc);
  b3_fraction(z, nz, grid, &tz, &tzc);
  geo_t cp = cospi(tz), sp = sinpi(tz);
  geo_t ix, iy, iz, ox, oy, oz;
  geo_t h_c = (geo_t)1, h_s = (geo_t)0, d_c = (geo_t)1;
  if (param == B3_PARAM_ANGLES) {
    /* i = (sin ti cos phi, sin ti sin phi, cos ti), o = (sin to, 0, cos to) */
    geo_t ci, si, co, so;
    b3_half_angle(tx, txc, &ci, &si);
    b3_half_angle(ty, tyc, &co, &so);
    ix = si * cp; iy = si * sp; iz = ci;
    ox = so; oy = (geo_t)0; oz = co;
  } else {
    /* h = (sin th, 0, cos th); d = (sin td cos pd, sin td sin pd, cos td) in the frame
     * (t, b, h) = ((cos th, 0, -sin th), (0, 1, 0), h); i = d there, o = 2 (d.h) h - i */
    geo_t u = tx, uc = txc;
    if (param == B3_PARAM_RUSINKIEWICZ_SQRT) {
      u = tx * tx;
      uc = txc * ((geo_t)1 + tx); /* 1 - t^2 = (1 - t)(1 + t) */
    }
    geo_t ch, sh, cd, sd;
    b3_half_angle(u, uc, &ch, &sh);
    b3_half_angle(ty, tyc, &cd, &sd);
    ix = sd * cp * ch + cd * sh; iy = sd * sp; iz = cd * ch - sd * cp * sh;
    ox = cd * sh - sd * cp * ch; oy = -iy; oz = cd * ch + sd * cp * sh;
    h_c = ch; h_s = sh; d_c = cd;
  }
  geo_t s2i = ix * ix + iy * iy, s2o = ox * ox + oy * oy;
  geo_t sio = sqrt(s2i * s2o);
  BrdfGeometry g;
  g.ni = iz;
  g.no = oz;
  g.s2i = s2i;
  g.s2o = s2o;
  if (param != B3_PARAM_ANGLES) {
    /* the half-vector is an axis: n.h = cos th, o.h = cos td, exactly */
    g.nh = h_c;
    g.s2h = h_s * h_s;
    g.oh = d_c;
  } else {
    /* h = (i + o)/|i + o|; |i + o|^2 = 2 (1 + i.o) */
    geo_t hx = ix + ox, hy = iy + oy, hz = iz + oz;
    geo_t len2 = hx * hx + hy * hy + hz * hz;
    if (len2 > (geo_t)BRDF3D_OPPOSITE) {
      g.nh = hz / sqrt(len2);
      g.s2h = (hx * hx + hy * hy) / len2;
      g.oh = (geo_t)0.5 * sqrt(len2);
    } else { /* i = -o, both on the horizon: no half-vector, o.h = 0 (brdf.h: no specular) */
      g.nh = RC(1.0);
      g.s2h = RC(0.0);
      g.oh = RC(0.0);
    }
  }
  g.cphi = sio > (geo_t)0 ? (ix * ox + iy * oy) / sio : RC(1.0);
  return g;
}

/* out[((c * zn + z - z0) * ny + y) * nx + x] for z in [z0, z0 + zn): one slab of slices, channel
 * planes one after another. value 0: f; 1: f (n.i). The material: roughness r, 1/k_p of the
 * gaussian's raw shape (inv_kp, from the host; 0 otherwise), channel c's Fresnel parameters
 * (fx.c, fy.c) and diffuse albedo rho.c. Parameters arrive as float: the table is the BRDF of
 * those float values (host/common/brdf3d_grid.cpp evaluates the same). */
kernel void bake_brdf3d(global float* out, int nx, int ny, int nz, int z0, int zn, int param, int grid, int value,
                        float r, float inv_kp, int fresnel, float4 fx, float4 fy, int diffuse, float dparam, float4 rho,
                        int nchan) {
  int x = get_global_id(0), yz = get_global_id(1);
  if (x >= nx || yz >= ny * zn) return;
  int y = yz % ny, zl = yz / ny;
  BrdfGeometry g = b3_geometry(x, y, z0 + zl, nx, ny, nz, param, grid);
  BrdfMaterial m;
  m.ndf = BRDF_NDF;
  m.gaf = BRDF_GAF;
  m.p = brdf_params_kp(BRDF_GAF, (real)r, (real)inv_kp);
  m.fresnel = fresnel;
  m.diffuse = diffuse;
  m.dparam = (real)dparam;
  float fxs[4] = {fx.x, fx.y, fx.z, fx.w}, fys[4] = {fy.x, fy.y, fy.z, fy.w}, rhos[4] = {rho.x, rho.y, rho.z, rho.w};
  real cosi = value ? fmax(g.ni, BRDF_MIN_COS) : RC(1.0); /* f = 0 below the horizon anyway */
  size_t plane = (size_t)nx * ny * zn, at = ((size_t)zl * ny + y) * nx + x;
  for (int c = 0; c < nchan; ++c)
    out[c * plane + at] = (float)(brdf_f(m, g, (real)fxs[c], (real)fys[c], (real)rhos[c]) * cosi);
}
