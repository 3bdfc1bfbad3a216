/* brdf.h: a whole material's BRDF at one pair of directions, the models of ndf.h, gaf.h,
 * fresnel.h and diffuse.h put together (docs/MODELS.md "Isotropic BRDF textures"):
 *   f(i, o) = F(o.h) D(h) G(i, o, h) / (4 (n.i)(n.o))  +  rho f_d(i, o)
 * (Cook and Torrance 1982's microfacet form with Walter et al. 2007's 1/4; the diffuse lobe added,
 * Ashikhmin and Shirley 2000's "sum" coupling). One value, not lanes: the 3D tables evaluate f
 * once per texel, nothing is integrated. Needs ndf.h, gaf.h, fresnel.h and diffuse.h before it.
 *
 * The geometry comes in as cosines and sines computed by the caller without cancellation (the
 * kernel from exact grid fractions with cospi/sinpi, the host from GLM vectors in double).
 * Grazing policy: n.i and n.o are floored at BRDF_MIN_COS. f then stays finite for every model:
 * it is the limit approached from inside for the GAFs whose G/((n.i)(n.o)) stays bounded (the
 * Smith family, schlick-*, implicit, kelemen, cook-torrance) and a large finite value (~1/cos)
 * for those where it does not (none; neumann and ashikhmin-premoze with both directions grazing).
 * Directions below the horizon give f = 0; n.i or n.o within BRDF_HORIZON of 0 counts as on it (an
 * exact 0 that the directions' rounding moved by an ulp, to either side) and takes the floor.
 */
/* Once per pass (compat.h "Passes"). */
#if defined(BRDF_SECOND_PASS) ? !defined(BRDF_BRDF_H_2) : !defined(BRDF_BRDF_H)
#ifdef BRDF_SECOND_PASS
#define BRDF_BRDF_H_2
#else
#define BRDF_BRDF_H
#endif
#include "brdf/ndf.h"
#include "brdf/gaf.h"
#include "brdf/fresnel.h"
#include "brdf/diffuse.h"
#ifndef BRDF_LANE_PASS
#define BRDF_MIN_COS RC(1e-6)
#define BRDF_HORIZON RC(1e-9)

typedef struct BrdfGeometry {
  real ni, no;   /* n.i, n.o */
  real s2i, s2o; /* sin^2 theta_i, sin^2 theta_o */
  real nh, s2h;  /* n.h, sin^2 theta_h */
  real oh;       /* o.h = i.h */
  real cphi;     /* cos(phi_i - phi_o) (1 where either direction is the normal) */
} BrdfGeometry;

/* The material apart from the channel: the specular lobe's models and roughness (p), the diffuse
 * model (-1: none) and its parameter (F0, sigma or r, diffuse.h). */
typedef struct BrdfMaterial {
  int ndf, gaf;
  BrdfParams p;
  int fresnel; /* FRESNEL_*, parameters per channel */
  int diffuse; /* DIFFUSE_* or -1 */
  real dparam;
} BrdfMaterial;

/* The specular lobe's parameters from perceptual roughness r (MODELS.md "Roughness axes"): alpha =
 * r^2 and Schlick's k; inv_kp = 1/k_p of the raw shape, which only the gaussian's D needs (it has
 * no closed form: integrate/hemisphere.h brdf_params computes it, the 3D tables take it from the
 * host). The weight fields name no split (F = 1). */
BRDF_FN BrdfParams brdf_params_kp(int gaf, real r, real inv_kp) {
  BrdfParams p;
  p.r = r;
  p.alpha = r * r;
  p.k = gaf_schlick_k(gaf, r, p.alpha);
  p.inv_kp = inv_kp;
  p.moments = HEMI_SPLIT;
  p.fresnel = FRESNEL_ONE;
  p.fr_x = RC(0.0);
  p.fr_y = RC(0.0);
  p.fr_z = RC(0.0);
  p.has_view = 0;
  p.view_cl = RC(0.0);
  p.smith_col = 0;
  return p;
}

/* f(i, o) of one colour channel: Fresnel parameters (fx, fy) as fresnel_F takes them and the
 * diffuse albedo rho. */
BRDF_FN real brdf_f(BrdfMaterial m, BrdfGeometry g, real fx, real fy, real rho) {
  if (g.ni < -BRDF_HORIZON || g.no < -BRDF_HORIZON) return RC(0.0);
  /* rounding can put a cosine an ulp past 1 (and 1 - cos^2 below 0): clamp both */
  real ni = fmin(fmax(g.ni, BRDF_MIN_COS), RC(1.0)), no = fmin(fmax(g.no, BRDF_MIN_COS), RC(1.0));
  real s2i = fmax(fmin(g.s2i, (RC(1.0) - ni) * (RC(1.0) + ni)), RC(0.0));
  real s2o = fmax(fmin(g.s2o, (RC(1.0) - no) * (RC(1.0) + no)), RC(0.0));
  /* f_s = F D (G/(n.o)) / (4 n.i): G/(n.o) as gaf.h computes it, finite at n.o -> 0 */
  real spec = RC(0.0);
  if (g.oh > RC(0.0)) {
    real d = ndf_D(m.ndf, m.p, g.nh, g.s2h);
    real gon = gaf_G_over_no(m.gaf, m.ndf, m.p, ni, no, g.nh, g.oh, s2i, s2o);
    spec = fresnel_F(m.fresnel, fx, fy, g.oh) * d * (gon / (RC(4.0) * ni));
  }
  real diff = RC(0.0);
  if (m.diffuse >= 0) {
    real si = sqrt(s2i), so = sqrt(s2o);
    diff = rho * diffuse_f(m.diffuse, m.dparam, ni, si, no, so, g.cphi);
  }
  return spec + diff;
}
#endif /* !BRDF_LANE_PASS */
#endif /* BRDF_BRDF_H */
