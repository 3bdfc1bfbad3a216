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
 * Directions below the horizon (n.i <= 0 or n.o <= 0 before the floor) give f = 0.
 */
#ifndef BRDF_LANE_PASS
#define BRDF_MIN_COS RC(1e-6)

typedef struct BrdfGeometry {
  real ni, no;    /* n.i, n.o */
  real s2i, s2o;  /* sin^2 theta_i, sin^2 theta_o */
  real nh, s2h;   /* n.h, sin^2 theta_h */
  real oh;        /* o.h = i.h */
  real cphi;      /* cos(phi_i - phi_o) (1 where either direction is the normal) */
} BrdfGeometry;

/* The material apart from the channel: the specular lobe's models and roughness (p), the diffuse
 * model (-1: none) and its parameter (F0, sigma or r, diffuse.h). */
typedef struct BrdfMaterial {
  int ndf, gaf;
  BrdfParams p;
  int fresnel;     /* FRESNEL_*, parameters per channel */
  int diffuse;     /* DIFFUSE_* or -1 */
  real dparam;
} BrdfMaterial;

/* f(i, o) of one colour channel: Fresnel parameters (fx, fy) as fresnel_F takes them and the
 * diffuse albedo rho. */
BRDF_FN real brdf_f(BrdfMaterial m, BrdfGeometry g, real fx, real fy, real rho) {
  if (g.ni <= RC(0.0) || g.no <= RC(0.0)) return RC(0.0);
  real ni = fmax(g.ni, BRDF_MIN_COS), no = fmax(g.no, BRDF_MIN_COS);
  real s2i = fmin(g.s2i, (RC(1.0) - ni) * (RC(1.0) + ni));
  real s2o = fmin(g.s2o, (RC(1.0) - no) * (RC(1.0) + no));
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
