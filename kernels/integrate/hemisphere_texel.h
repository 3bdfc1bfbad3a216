/* hemisphere_texel.h: what a table's texel claims, on top of the rules of hemisphere.h: the
 * estimators' floors, the tabulated Lambda's share, the choice between the default and the refined
 * budget against a target, and the texel at (mu, r) with its edges (mu = 0, r = 0 and the corner).
 * Shared by the device and the host tests. */
/* Once per pass (compat.h "Passes"). */
#if defined(BRDF_SECOND_PASS) ? !defined(BRDF_HEMISPHERE_TEXEL_H_2) : !defined(BRDF_HEMISPHERE_TEXEL_H)
#ifdef BRDF_SECOND_PASS
#define BRDF_HEMISPHERE_TEXEL_H_2
#else
#define BRDF_HEMISPHERE_TEXEL_H
#endif
#include "integrate/hemisphere.h"
#include "integrate/sheen.h"
/* The estimators' floor. The rules' estimates are estimates, not bounds: where they are tiny the
 * true error can exceed them. Measured in double against the converged rule (refine = 3), as the
 * texel's claim is made (the largest error over A, B, E against the largest estimate), over every
 * pair's 128x128 edge texels, every 32nd texel inside and 9x9 node grids (mu = 0, 1 and r = 0, 1),
 * both budgets: the sharpened estimates (gk_error) miss by at most 5.5e-8 of the value
 * (blinn-phong + smith-exact at mu = 0.47, r = 255/256; 4.4e-8 for ggx + smith at mu = 255/256,
 * r = 0.11, where G1(i) changes within n.i ~ alpha of i's horizon next to v1, inside one outer
 * panel), |K15 - G7| by at most 1.6e-7 of it (beckmann + none, mu = 1/256, r = 255/256; every
 * pair, none and charlie included, has the sharpened estimate's floors below). The
 * floor, relative to the value so that it scales with what the rule integrates (and averages into
 * E_avg's node bounds where the average keeps them; the plain average of the rescaled pairs has a
 * floor of its own, albedo_avg.h AVG_ERR_FLOOR), covers both;
 * tests/tables/microfacet/accuracy_test.cpp checks every such texel against the
 * reference. Re-measured there with the arcs graded from n.i = 2 alpha (azimuth.h), against the
 * reference, over every non-exact-Smith pair's 9x9 node and 8x8 centre grids and 128x128 edge
 * texels, both budgets: the sharpened estimates miss by at most 4.4e-8 of the value (7.5e-9 away
 * from the edges); `./tests/brdfbake-accuracy-tests` prints it. The refined budget's estimates miss
 * by far less, at most 4.5e-10 of the value over the same texels (gaussian + smith-correlated at
 * the 128x128 edges). Measured
 * on the unweighted moments of the pairs without a tabulated Lambda (whose 6.6e-7 dwarfs it), at
 * levels 0 and 1; the Fresnel-weighted moments and the convergence ladders' levels 2 and up use it
 * unmeasured. None, cook-torrance, kelemen and neumann, sharpened as well (azimuth.h), miss over
 * the same texels by at most 2.5e-8 of the value at the default budget and 6.2e-10 at the refined
 * one (gaussian + neumann at the 128x128 edges, mu = 1/256), so the refined floor is 1.5e-9
 * (margin 2.4). The charlie NDF's estimates, sharpened the same way (charlie-smith's kinks and
 * horizon singularity, gaf.h), miss the sheen reference (host/reference/sheen_reference.cpp,
 * independent of these rules) over 17 r x 27 mu per sheen pair (charlie-smith, neubelt, none,
 * implicit) by at most 4.4e-9 of the value at the
 * default budget and 1.1e-10 at the refined one (charlie-smith, r = 1, mu = 3/8 and 0.49), inside
 * both floors. */
#define HEMI_ERR_FLOOR_SHARP RC(1e-7)
#define HEMI_ERR_FLOOR_REFINED RC(1.5e-9)
/* The exact Smith Lambda of blinn-phong and the gaussian is tabulated (smith_tables.h): its G1 is
 * within 3.3e-7 of the exact one (docs/MODELS.md "Exact Smith Lambda", the generator's largest at
 * the table's cell centres), so G = G1(o) G1(i) or 1/(1 + Lambda_o + Lambda_i) within twice that:
 * the integrand, and the moments, within 6.6e-7 of their values. */
#define HEMI_SMITH_TABLE_ERR RC(6.6e-7)

/* The model's own approximation: the tabulated exact Lambda's share (0 where it is exact). */
BRDF_FN real hemi_model_error(int ndf, int gaf) {
  return gaf_lambda_tabulated(ndf, gaf) ? HEMI_SMITH_TABLE_ERR : RC(0.0);
}
/* Adds f times the moments' magnitudes to their error estimates. */
BRDF_FN void hemi_add_relative(real f, HemiResult* h) {
  h->err_a += f * fabs(h->a);
  h->err_b += f * fabs(h->b);
}
BRDF_FN real hemi_floor(int refine) { return refine > 0 ? HEMI_ERR_FLOOR_REFINED : HEMI_ERR_FLOOR_SHARP; }

/* The NDF's rule at budget `refine` (hemisphere.h explains the levels): charlie's own (sheen.h),
 * else the one for lobes peaked at h = n. */
BRDF_FN HemiResult hemi_rule(int ndf, int gaf, BrdfParams p, real mu, int refine) {
  return ndf == NDF_CHARLIE ? sheen_moments(gaf, p, mu, refine) : hemi_rule_peaked(ndf, gaf, p, mu, refine);
}

/* The moments at (mu, alpha) and their error estimates (absolute): the rule's, the floor, and the
 * model's own approximation (the tabulated exact Lambda). */
BRDF_FN HemiResult hemisphere_moments(int ndf, int gaf, BrdfParams p, real mu, int refine) {
  HemiResult h = hemi_rule(ndf, gaf, p, mu, refine);
  hemi_add_relative(hemi_floor(refine) + hemi_model_error(ndf, gaf), &h);
  return h;
}

/* The texel's error estimate: the largest of those of A, B and E = A + B, each relative to
 * max(1, |value|). The quadrature's alone: the float arithmetic's share of a table's error is
 * host/bake's (bake/error_model.h). */
BRDF_FN real hemi_rel_error(HemiResult h) {
  real a = (real)h.a, b = (real)h.b, e = (real)(h.a + h.b);
  real ea = (real)h.err_a / fmax(RC(1.0), fabs(a));
  real eb = (real)h.err_b / fmax(RC(1.0), fabs(b));
  real ee = (real)(h.err_a + h.err_b) / fmax(RC(1.0), fabs(e));
  return fmax(ee, fmax(ea, eb));
}

/* The default budget, and the refined one where its estimate exceeds `target` (the refined result
 * is kept if its estimate is smaller); level >= 0 instead: that budget alone (=
 * hemisphere_moments).
 * The tabulated Lambda's error is added after the choice: no budget reduces it. bare: the chosen
 * budget's rule estimate alone, without the floor and the tabulated Lambda's error (the choice is
 * the same): the average albedo (host/cl/runner_avg.cpp) adds floors measured on the averages
 * themselves instead. Written as a loop around a single call of the rule so that a kernel compiles
 * one copy of the estimator, not one per budget (PoCL inlines every call site). */
BRDF_FN HemiResult hemisphere_moments_chosen(int ndf, int gaf, BrdfParams p, real mu, int level, real target,
                                             int bare) {
  HemiResult h;
  real e = RC(0.0);
  int first = 1;
  for (int l = level < 0 ? 0 : level;; l = 1) {
    HemiResult c = hemi_rule(ndf, gaf, p, mu, l), cf = c;
    hemi_add_relative(hemi_floor(l), &cf);
    real ec = hemi_rel_error(cf);
    if (first || ec < e) {
      h = bare ? c : cf;
      e = ec;
    }
    if (level >= 0 || !first || e <= target) break;
    first = 0;
  }
  if (!bare) hemi_add_relative(hemi_model_error(ndf, gaf), &h);
  return h;
}
BRDF_FN HemiResult hemisphere_moments_at(int ndf, int gaf, BrdfParams p, real mu, int level, real target) {
  return hemisphere_moments_chosen(ndf, gaf, p, mu, level, target, 0);
}
BRDF_FN HemiResult hemisphere_moments_to(int ndf, int gaf, BrdfParams p, real mu, real target) {
  return hemisphere_moments_at(ndf, gaf, p, mu, -1, target);
}

/* The value a table holds at (mu, r), its edges included.
 * r = 0 (alpha = 0) is the mirror limit (hemisphere_moments); mu = 0 is the limit mu -> 0 at fixed
 * alpha > 0, which the estimator computes directly (G/(n.o) is finite there). The corner
 * (mu = 0, r = 0), where the two limits can disagree (schlick-ggx: E -> 1 along the r = 0 row but
 * E(0, r) -> 0.84 as r -> 0), holds the limit along the mu = 0 edge, lim_{r->0} E(0, r): a view
 * more grazing than the surface is rough, which is what a grazing view of any real, very smooth
 * surface sees. The scale of that limit is alpha (theta_h ~ alpha, n.i ~ alpha), so r = 1e-5
 * (alpha = 1e-10) reaches it to O(1e-10), far inside float rounding; the mirror formula at h = n
 * would give 0 there (o.h = mu = 0, where chi+ zeroes G). */
#define HEMI_CORNER_R RC(1e-5)
/* How far that is from the limit: E(0, r) - E(0, 0+) is O(alpha) = 1e-10 of the value, and where the
 * limit is 0 (every GAF that vanishes at grazing) the value itself, measured at most 5e-11; the
 * corner's estimate adds 1e-9 (relative to max(1, |value|)). */
#define HEMI_CORNER_ERR RC(1e-9)
BRDF_FN BrdfParams hemisphere_texel_params(int ndf, int gaf, real mu, real r) {
  return brdf_params(ndf, gaf, (mu <= RC(0.0) && r <= RC(0.0)) ? HEMI_CORNER_R : r);
}
BRDF_FN void hemi_add_corner(real mu, real r, HemiResult* h) {
  if (mu <= RC(0.0) && r <= RC(0.0)) {
    h->err_a += HEMI_CORNER_ERR * fmax(RC(1.0), fabs((real)h->a));
    h->err_b += HEMI_CORNER_ERR * fmax(RC(1.0), fabs((real)h->b));
  }
}
BRDF_FN HemiResult hemisphere_texel(int ndf, int gaf, real mu, real r, real target) {
  HemiResult h = hemisphere_moments_to(ndf, gaf, hemisphere_texel_params(ndf, gaf, mu, r), mu, target);
  hemi_add_corner(mu, r, &h);
  return h;
}
/* The same with another weight (BrdfParams: moments, fresnel, fr_x, fr_y). */
BRDF_FN HemiResult hemisphere_texel_weighted(int ndf, int gaf, real mu, real r, real target, int moments, int fresnel,
                                             real fr_x, real fr_y) {
  BrdfParams p = hemisphere_texel_params(ndf, gaf, mu, r);
  p.moments = moments;
  p.fresnel = fresnel;
  p.fr_x = fr_x;
  p.fr_y = fr_y;
  HemiResult h = hemisphere_moments_to(ndf, gaf, p, mu, target);
  hemi_add_corner(mu, r, &h);
  return h;
}
#endif /* BRDF_HEMISPHERE_TEXEL_H */
