/* anisotropic.h: the anisotropic Ashikhmin-Shirley specular BRDF and the three factorised textures
 * of seed 001 (docs/MODELS.md "Ashikhmin-Shirley: factorised textures"). Without the (n.i) cosine.
 * Directions in the shading frame: x = tangent (the n_u direction), y = bitangent (n_v), z = n.
 * Uses fresnel.h (fresnel_schlick, fresnel_schlick_weight). The host evaluates it (brdf64,
 * brdf32); it is written in the shared subset so that a kernel can include it.
 *
 * The specular factorises as (Ashikhmin and Shirley 2000, as Steigleder and McCool lay it out):
 *   rho_s = sqrt((n_u+1)(n_v+1))/(8 pi) Tex1(h.k, max(n.i, n.o)) Tex2(n.h, sqrt(n_u) h.x) Tex2(n.h, sqrt(n_v) h.y)
 * and the diffuse as rho_d = 28/(23 pi) R_d (1 - R_s) Tex0(n.i, n.o).
 */
/* Once per pass (compat.h "Passes"). */
#if defined(BRDF_SECOND_PASS) ? !defined(BRDF_ANISOTROPIC_H_2) : !defined(BRDF_ANISOTROPIC_H)
#ifdef BRDF_SECOND_PASS
#define BRDF_ANISOTROPIC_H_2
#else
#define BRDF_ANISOTROPIC_H
#endif
#include "brdf/fresnel.h"

/* Ashikhmin and Shirley 2000, eq. 5, the angular part: Tex0(u, v) = (1 - (1 - u/2)^5)(1 - (1 - v/2)^5) */
BRDF_FN real as_tex0(real u, real v) {
  return (RC(1.0) - fresnel_schlick_weight(RC(0.5) * u)) * (RC(1.0) - fresnel_schlick_weight(RC(0.5) * v));
}

/* Tex1 = F(u)/(u v) with Schlick's F(u) = Rs + (1 - Rs)(1 - u)^5 (MODELS.md erratum, seed 001), split
 * like the split sum so that it holds no parameter: F/(u v) = Rs as_tex1_rs(u, v) + as_tex1_one(u, v).
 * No epsilon: u, v > 0 on every texel centre, where the value is finite; u = 0 or v = 0 is infinite,
 * and is so here (the bake refuses grids that hold it). */
BRDF_FN real as_tex1_rs(real u, real v) { return (RC(1.0) - fresnel_schlick_weight(u)) / (u * v); }
BRDF_FN real as_tex1_one(real u, real v) { return fresnel_schlick_weight(u) / (u * v); }
/* Ashikhmin and Shirley 2000, eq. 4: F(k.h)/((h.k) max(n.k1, n.k2)), Schlick's F with reflectance rs */
BRDF_FN real as_tex1(real rs, real u, real v) { return fresnel_schlick(rs, u) / (u * v); }

/* Tex2(u, v) = u^(v^2/(1-u^2)) (seed 001), for u in [0, 1]. Evaluated as exp(v^2 log(u)/((1-u)(1+u)))
 * with log(u) = log1p(-d), d = 1 - u, where d is exact (u >= 1/2; below, where 1 - u rounds, log(u)
 * itself: the same function to an ulp, so no step):
 *   log1p(-d)/d = -(1 + d/2 + d^2/3 + ...) -> -1 as d -> 0, so the exponent -> -v^2/2 and
 *   Tex2(1, v) = exp(-v^2/2), the limit the seed switches to at u > 1 - 1/256.
 * log1p(-d)/d is accurate to a few ulps for every d > 0, so the formula is smooth up to u = 1; only
 * d = 0 itself (0/0) takes the limit -1. At u = 0 log1p(-1) = -inf: Tex2 = 0 for v != 0 and 0^0 = 1
 * (the limit along v = 0) for v = 0. */
BRDF_FN real as_tex2(real u, real v) {
  real d = RC(1.0) - u;
  real lg = u >= RC(0.5) ? log1p(-d) : log(u);
  real ratio = d > RC(0.0) ? lg / d : RC(-1.0); /* log(u)/(1-u) */
  real v2 = v * v;
  real e = v2 * ratio / (RC(1.0) + u);
  return v2 == RC(0.0) ? RC(1.0) : exp(e);
}

/* Ashikhmin and Shirley 2000, eq. 4: the anisotropic specular
 *   rho_s(i, o) = sqrt((n_u+1)(n_v+1))/(8 pi) (n.h)^(n_u cos^2 phi_h + n_v sin^2 phi_h) F(o.h)/((h.o) max(n.i, n.o)),
 * F Schlick's with reflectance rs. With cos^2 phi_h = h_x^2/(h_x^2 + h_y^2) (1 - (n.h)^2 written as
 * s2 = h_x^2 + h_y^2, no cancellation) the power is exp(log1p(-s2)/2 (n_u h_x^2 + n_v h_y^2)/s2),
 * which is 1 at h = n. i and o are unit vectors with iz, oz > 0. */
BRDF_FN real as_specular(real nu, real nv, real rs, real ix, real iy, real iz, real ox, real oy, real oz) {
  real hx = ix + ox, hy = iy + oy, hz = iz + oz;
  real len = sqrt(hx * hx + hy * hy + hz * hz);
  hx /= len;
  hy /= len;
  hz /= len;
  real hx2 = hx * hx, hy2 = hy * hy, s2 = fmin(hx2 + hy2, RC(1.0));
  real expo = s2 > RC(0.0) ? (nu * hx2 + nv * hy2) / s2 : RC(0.0);
  real lobe = exp(RC(0.5) * expo * log1p(-s2));
  real ho = hx * ox + hy * oy + hz * oz;
  real norm = sqrt((nu + RC(1.0)) * (nv + RC(1.0))) / (RC(8.0) * BRDF_PI);
  return norm * lobe * fresnel_schlick(rs, ho) / (ho * fmax(iz, oz));
}
#endif /* BRDF_ANISOTROPIC_H */
