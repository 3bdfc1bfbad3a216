/* brdf3d.cl: the isotropic BRDF as a 3D table (docs/MODELS.md "Isotropic BRDF textures"), one texel
 * per work-item, no barriers. Uses the prelude's pair (BRDF_NDF, BRDF_GAF) and kernels/brdf/brdf.h.
 *
 * Axes, each sampled at a fraction t of its range (the grid convention):
 *   angles        x = theta_i in [0, pi/2], y = theta_o in [0, pi/2], z = phi_i - phi_o in [0, pi]
 *   rusinkiewicz  x = theta_h in [0, pi/2] (theta_h = pi/2 t, or pi/2 t^2: MERL's index
 *                 t = sqrt(theta_h/(pi/2))), y = theta_d in [0, pi/2], z = phi_d in [0, pi]
 * Grid: texel centres t = (i + 0.5)/n, nodes t = i/(n - 1), or cell starts t = i/n (MERL).
 *
 * Precision. The host tabulates each axis's cosines and sines in double
 * (host/common/brdf3d_grid.cpp
 * axisTrig: from the exact grid fraction and its complement formed from integers, so that cos theta
 * near grazing keeps full relative precision); the kernel forms the directions from them, no trig
 * of its own. Its program is its own (host/cl/programs.cpp): this file and the models it
 * includes, with `real` = double where the device has cl_khr_fp64 (float otherwise); the texel is
 * rounded to float once, at the end.
 */
#include "brdf/brdf.h"
typedef real geo_t;

/* |i + o|^2 below this: i = -o up to rounding (both directions on the horizon, opposite) */
#define BRDF3D_OPPOSITE 1e-24
#define B3_PARAM_ANGLES 0
#define B3_PARAM_RUSINKIEWICZ 1

/* The geometry of texel (x, y, z) as brdf.h takes it, from the axes' cosines and sines: trig[2 k]
 * and trig[2 k + 1] for sample k of x, then of y (offset nx), then of z (offset nx + ny). */
static inline BrdfGeometry b3_geometry(int x, int y, int z, int nx, int ny, int param, global const geo_t* trig) {
  geo_t c0 = trig[2 * x], s0 = trig[2 * x + 1];
  geo_t c1 = trig[2 * (nx + y)], s1 = trig[2 * (nx + y) + 1];
  geo_t cp = trig[2 * (nx + ny + z)], sp = trig[2 * (nx + ny + z) + 1];
  geo_t ix, iy, iz, ox, oy, oz;
  geo_t h_c = (geo_t)1, h_s = (geo_t)0, d_c = (geo_t)1;
  if (param == B3_PARAM_ANGLES) {
    /* i = (sin ti cos phi, sin ti sin phi, cos ti), o = (sin to, 0, cos to) */
    ix = s0 * cp;
    iy = s0 * sp;
    iz = c0;
    ox = s1;
    oy = (geo_t)0;
    oz = c1;
  } else {
    /* h = (sin th, 0, cos th); d = (sin td cos pd, sin td sin pd, cos td) in the frame
     * (t, b, h) = ((cos th, 0, -sin th), (0, 1, 0), h); i = d there, o = 2 (d.h) h - i */
    geo_t ch = c0, sh = s0, cd = c1, sd = s1;
    ix = sd * cp * ch + cd * sh;
    iy = sd * sp;
    iz = cd * ch - sd * cp * sh;
    ox = cd * sh - sd * cp * ch;
    oy = -iy;
    oz = cd * ch + sd * cp * sh;
    h_c = ch;
    h_s = sh;
    d_c = cd;
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
 * planes one after another; trig: the axes' cosines and sines (b3_geometry), in `real`. value 0:
 * f; 1: f (n.i). The material: roughness r, 1/k_p of the
 * gaussian's raw shape (inv_kp, from the host; 0 otherwise), channel c's Fresnel parameters
 * (fx.c, fy.c) and diffuse albedo rho.c. Parameters arrive as float: the table is the BRDF of
 * those float values (host/common/brdf3d_grid.cpp evaluates the same). */
kernel void bake_brdf3d(global float* out, global const real* trig, int nx, int ny, int z0, int zn, int param,
                        int value, float r, float inv_kp, int fresnel, float4 fx, float4 fy, int diffuse, float dparam,
                        float4 rho, int nchan) {
  int x = get_global_id(0), yz = get_global_id(1);
  if (x >= nx || yz >= ny * zn) return;
  int y = yz % ny, zl = yz / ny;
  BrdfGeometry g = b3_geometry(x, y, z0 + zl, nx, ny, param, trig);
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
