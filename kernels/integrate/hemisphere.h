/* hemisphere.h: directional albedo E(mu) and split-sum moments (A, B), E = A + B, at (mu, alpha);
 * average albedo E_avg and the NDF normalisation k_p. Shared by the device and the host tests.
 *
 * Derivation. E(mu) = int f (n.i) dw_i with f = D G F / (4 (n.i)(n.o)). Since dw_i = 4 (o.h) dw_h,
 *   E = int D (G/(n.o)) F (o.h) dw_h  over the h whose mirror direction i has n.i > 0 (then o.h > 0).
 * Map theta_h by the NDF's CDF u and then v = -log(1-u) (ndf.h): D sin dtheta dphi = e^-v dv dphi/(2 pi c),
 *   E = (1/pi) int_0^inf dv e^-v w(v) int_0^phimax(v) dphi H,   H = (G/no) F (o.h)/(n.h),
 * folding phi -> -phi (w = 1, or D_gauss/D_ggx on the gaussian's GGX grid).
 * Visible domain: o = (s, 0, mu), h = (sn cos phi, ., c); n.i = 2 (o.h) c - mu > 0 <=> cos phi > c0 with
 *   c0 = -mu (1 - t^2)/(2 s t), t = tan theta_h.  c0 <= -1 (whole hw circle) for t <= t1 = mu/(1+s),
 *   c0 >= 1 (nothing) for t >= t2 = (1+s)/mu: theta_h = (pi/2 -+ theta_o)/2 by the hw-angle identities.
 * So v1 = v(t1^2), v2 = v(t2^2) split the outer axis. Factored, 1 + c0 = (t - t1)(mu t + 1 + s)/(2 s t) and
 *   1 - c0 = (1 + s - mu t)(t + t1)/(2 s t); with t^2 - t1^2 taken from v - v1 (ndf_tan2_diff), phimax
 *   stays accurate where it is close to pi.
 * Quadrature: outer v in panels at fixed breakpoints (the integrand decays like e^-v) and at v1 and v2;
 * GK15 per panel, with a v = a + L y^2 (resp. b - L (1-y)^2) substitution at v1 (v2), where the
 * inner integral has a square-root end (phimax ~ pi - sqrt(v - v1), ~ sqrt(v2 - v)). Inner phi: on
 * the whole hw circle the integrand is smooth, even and 2 pi-periodic, so the trapezoid rule on
 * 16 intervals converges geometrically (error from its 8-interval subset, cosines from a table); on a
 * partial arc, and around the kinks of min/max GAFs (gaf_kinks), GK15 on each smooth piece.
 * The returned error is the outer rule's estimate (gk_error: |K15 - G7| rescaled where the
 * integrand is analytic) plus the weighted inner estimates, plus a floor (hemisphere_moments).
 * Cost: libm calls are counted per lane vector, not per node (compat.h): one float16 pass prepares
 * an outer panel's 15 nodes (expm1, sqrt, atan2, exp), one evaluates a GK15 azimuth panel (cos and
 * the integrand), one the 16-interval trapezoid but its last node (cosines from a table), and one
 * the last nodes, phi = pi, of all of the panel's trapezoids together. At the default budget the
 * device runs most panels transposed instead, one pass per azimuth node over all 15 outer nodes:
 * a whole-circle panel without kinks in 17 (hemi_trap_lanes), a partial one in 16 per panel of
 * its nodes' arcs (hemi_arcs_lanes).
 */
/* Once per pass (compat.h "Passes"). */
#if defined(BRDF_SECOND_PASS) ? !defined(BRDF_HEMISPHERE_H_2) : !defined(BRDF_HEMISPHERE_H)
#ifdef BRDF_SECOND_PASS
#define BRDF_HEMISPHERE_H_2
#else
#define BRDF_HEMISPHERE_H
#endif
#include "integrate/azimuth.h"
#include "integrate/azimuth_lanes.h"
#include "brdf/brdf.h"
#include "integrate/quadrature.h"
#define HEMI_VCAP RC(40.0)
/* The budgets (the brdf.method text is generated from these: host/bake/bake.cpp); the azimuth's,
 * HEMI_TRAP_N and HEMI_PHI_GROW, are in azimuth.h. */
/* Texels whose estimate (floor included) exceeds this are refined: the bake's tables claim their
 * largest estimate plus the float arithmetic (host/bake), so the target keeps the claim within a
 * small factor of the float rounding a table cannot avoid (~3e-7 at values near 1). */
#define HEMI_BAKE_TARGET 3e-7

typedef struct HemiResult {
  acc_t a, b;         /* A (F0 coefficient) and B (F90 bias), E = A + B */
  acc_t err_a, err_b; /* error bounds */
} HemiResult;

/* Where refinement cuts each outer panel (fractions of its length). */
BRDF_CONST real HEMI_REFINE_CUTS[4] = {RC(0.0625), RC(0.25), RC(0.75), RC(0.9375)};

/* The outer breakpoints after the ones at v1, v2: the e^-v decay wants panels of growing width. */
#define HEMI_NBREAKS 5
/* Room for every outer breakpoint: the fixed ones twice, the horizon layer, the GAF's theta
 * breaks, Fresnel's kink crossings and the Fresnel layer's (fresnel_layer). */
#define HEMI_MAX_BREAKS 96
BRDF_CONST real HEMI_BREAKS[HEMI_NBREAKS] = {RC(1.0), RC(3.0), RC(7.0), RC(15.0), RC(40.0)};

/* Where the curve o.h = x (0 < x < 1) meets the ends of the arc at the view o = (s, 0, mu): at
 * phi = 0, o.h = cos(theta_h - theta_o), so theta_h = |theta_o - theta_x| and theta_o + theta_x
 * (theta_x = acos x); at the horizon end, o.h = mu/(2 cos theta_h). Their tan^2 theta_h (those
 * with theta_h in (0, pi/2)) go to t2; returns how many. From sines and cosines of the sums
 * rather than the angles' difference: theta_o - theta_x in float loses the digits of two angles
 * near pi/2 (mu = 1/64, x = 0.01414 for eta = 0.9999: 0.0014 from 1.555 and 1.557, 1e-4 of it, a
 * break that far from F's square-root end); the sine form's break, in float, is at v = 0.37503681
 * against 0.37503688 in double (r = 3/64). */
BRDF_FN int hemi_cross_tan2(real mu, real s, real x, real* t2) {
  real sx = sqrt((RC(1.0) - x) * (RC(1.0) + x));
  int n = 0;
  real d = s * x - mu * sx, c = mu * x + s * sx; /* sin, cos of theta_o - theta_x */
  if (d != RC(0.0) && c > RC(0.0)) t2[n++] = (d * d) / (c * c);
  real su = s * x + mu * sx, cu = mu * x - s * sx; /* of theta_o + theta_x */
  if (cu > RC(0.0)) t2[n++] = (su * su) / (cu * cu);
  if (mu < RC(2.0) * x) {
    real q = mu / (RC(2.0) * x);
    if (q > RC(0.0)) t2[n++] = (RC(1.0) - q) * (RC(1.0) + q) / (q * q);
  }
  return n;
}

/* One GK15 panel [a, b] of the outer v axis, added to res (values; errors: the outer rule's
 * estimate, gk_error, plus the inner rules' estimates weighted as the values are).
 * partial: the panel lies in [v1, v2], where the phi arc ends at phimax(v) < pi.
 * sq_lo / sq_hi: the panel starts at v1 / ends at v2, where the inner integral has a square-root
 * end; v = a + L y^2, b - L (1-y)^2, or the smoothstep for both, make it smooth in y.
 * First the nodes' angles, arcs and weights, all nodes at once in lanes; then each node's azimuth
 * integral (itself in lanes). */
BRDF_FN void hemi_outer_panel(int ndf, int gaf, BrdfParams p, real mu, real s, real t1, real v1, real a, real b,
                              int partial, int sq_lo, int sq_hi, int refine, HemiResult* res) {
  real len = b - a;
  real nc[16], ns2[16], nt2[16], nsn[16], nphi[16], nsin[16], nw[16];
  for (int k = 0; k + BRDF_LANES <= HEMI_GK_N; k += BRDF_LANES) {
    lane_t y = RC(0.5) * (lane_load(GK15_XL, k) + RC(1.0));
    lane_t off, jac; /* v - a and dv/dy */
    if (sq_lo && sq_hi) {
      off = len * y * y * (RC(3.0) - RC(2.0) * y);
      jac = RC(6.0) * len * y * (RC(1.0) - y);
    } else if (sq_lo) {
      off = len * y * y;
      jac = RC(2.0) * len * y;
    } else if (sq_hi) {
      off = len * (RC(1.0) - (RC(1.0) - y) * (RC(1.0) - y));
      jac = RC(2.0) * len * (RC(1.0) - y);
    } else {
      off = len * y;
      jac = len;
    }
    lane_t v = a + off, c, s2, t2;
    ndf_angle_v(ndf, p, v, &c, &s2, &t2);
    lane_t phimax = BRDF_PI, sinmax = RC(0.0);
    if (partial) {
      lane_t t = sqrt(t2);
      lane_t dt2 = ndf_tan2_diff(ndf, p, v1, v - v1); /* t^2 - t1^2 */
      if (ndf == NDF_CHARLIE) {
        /* charlie (sheen.h): v1 can be far above v (1e5 at grazing views of small alpha; inf at mu = 0),
         * where v - v1 loses v's digits; the plain difference has no cancellation there */
        lane_t direct = t2 - t1 * t1;
        dt2 = direct > RC(0.5) * t2 ? direct : dt2;
      }
      lane_t inv = RC(1.0) / (RC(2.0) * s * t);
      lane_t opc = fmax(dt2 / (t + t1) * (mu * t + RC(1.0) + s) * inv, RC(0.0)); /* 1 + c0 */
      lane_t omc = fmax((RC(1.0) + s - mu * t) * (t + t1) * inv, RC(0.0));       /* 1 - c0 */
      lane_t c0 = opc < RC(1.0) ? opc - RC(1.0) : RC(1.0) - omc;
      sinmax = sqrt(opc * omc);
      phimax = atan2(sinmax, c0);
    }
    lane_store(c, nc, k);
    lane_store(s2, ns2, k);
    lane_store(t2, nt2, k);
    lane_store(sqrt(s2), nsn, k);
    lane_store(phimax, nphi, k);
    lane_store(sinmax, nsin, k);
    lane_store(RC(0.5) * jac * exp(-v) * ndf_weight(ndf, p, c, s2), nw, k);
  }
  real va[16], vb[16], vea[16], veb[16]; /* each node's azimuth integrals and their bounds (15 used) */
#if BRDF_LANES >= HEMI_GK_N
  if (!partial && hemi_trap_plain(gaf, p, refine)) {
    lane_t ia, ib, ea, eb;
    hemi_trap_lanes(ndf, gaf, p, mu, s, lane_load(nc, 0), lane_load(nsn, 0), &ia, &ib, &ea, &eb);
    lane_store(ia, va, 0);
    lane_store(ib, vb, 0);
    lane_store(ea, vea, 0);
    lane_store(eb, veb, 0);
  } else if (partial && refine == 0) {
    hemi_arcs_lanes(ndf, gaf, p, mu, s, nc, ns2, nt2, nsn, nphi, nsin, va, vb, vea, veb);
  } else
#endif
  {
    TrapSums trap[15];
    int pending = 0;
    for (int k = 0; k < 15; ++k) {
      BrdfAngle h;
      h.c = nc[k];
      h.s2 = ns2[k];
      h.t2 = nt2[k];
      hemi_phi(ndf, gaf, p, mu, s, h, nsn[k], !partial, nphi[k], nsin[k], refine, &va[k], &vb[k], &vea[k], &veb[k],
               &trap[k]);
      pending |= trap[k].n > 0;
    }
    if (pending) {
      /* the trapezoids' last nodes, phi = pi, at every outer node at once (hemi_phi_trap) */
      real pa[16], pb[16];
      for (int k = 0; k + BRDF_LANES <= HEMI_GK_N; k += BRDF_LANES) {
        lane_t fa, fb;
        hemi_node_c(ndf, gaf, p, mu, s, lane_load(nc, k), lane_load(nsn, k), RC(-1.0), &fa, &fb);
        lane_store(fa, pa, k);
        lane_store(fb, pb, k);
      }
      for (int k = 0; k < 15; ++k)
        if (trap[k].n > 0) hemi_trap_finish(trap[k], pa[k], pb[k], &va[k], &vb[k], &vea[k], &veb[k]);
    }
  }
  real pka = RC(0.0), pkb = RC(0.0), pda = RC(0.0), pdb = RC(0.0), pea = RC(0.0), peb = RC(0.0);
  real ga[15], gb[15]; /* the nodes' values, for resasc */
  for (int k = 0; k < 15; ++k) {
    real ia = va[k], ib = vb[k], ea = vea[k], eb = veb[k];
    real wk = GK15_WKL[k] * nw[k], wd = GK15_WDL[k] * nw[k];
    ga[k] = nw[k] * ia;
    gb[k] = nw[k] * ib;
    pka += wk * ia;
    pkb += wk * ib;
    pda += wd * ia;
    pdb += wd * ib;
    pea += wk * ea;
    peb += wk * eb;
  }
  real ra = RC(0.0), rb = RC(0.0); /* resasc (the Kronrod weights sum to 2: the mean is pka/2) */
  for (int k = 0; k < 15; ++k) {
    ra += GK15_WKL[k] * fabs(ga[k] - RC(0.5) * pka);
    rb += GK15_WKL[k] * fabs(gb[k] - RC(0.5) * pkb);
  }
  res->a += pka;
  res->b += pkb;
  res->err_a += gk_error(fabs(pda), ra, 1) + pea;
  res->err_b += gk_error(fabs(pdb), rb, 1) + peb;
}

/* One outer panel [cur, next] at budget `refine` (hemisphere_moments explains the levels). */
BRDF_FN void hemi_panel(int ndf, int gaf, BrdfParams p, real mu, real s, real t1, real v1, real cur, real next,
                        int partial, int sq_lo, int sq_hi, int refine, HemiResult* res) {
  if (!refine) {
    hemi_outer_panel(ndf, gaf, p, mu, s, t1, v1, cur, next, partial, sq_lo, sq_hi, refine, res);
    return;
  }
  /* five pieces graded towards both ends, at 1/16, 1/4, 3/4, 15/16 of the panel: an end may
   * carry a square-root (v1, v2) or a 3/2-power singularity (a GAF kink entering the azimuth
   * range at a theta break), which halving resolves only algebraically. The first piece keeps
   * the v1 substitution, the last the v2 one. */
  real len = next - cur, lo = cur;
  int sub = 1 << (refine - 1); /* levels above 1 (convergence ladders): each piece in 2^(refine-1) */
  for (int q = 0; q < 5; ++q) {
    real hi = q < 4 ? cur + len * HEMI_REFINE_CUTS[q] : next;
    real w = (hi - lo) / (real)sub;
    for (int u = 0; u < sub; ++u) {
      real a = lo + w * (real)u, b = u + 1 < sub ? lo + w * (real)(u + 1) : hi;
      hemi_outer_panel(ndf, gaf, p, mu, s, t1, v1, a, b, partial, q == 0 && u == 0 && sq_lo,
                       q == 4 && u + 1 == sub && sq_hi, refine, res);
    }
    lo = hi;
  }
}

/* The rule of the NDFs whose lobe peaks at h = n (all but charlie, whose rule is sheen.h's): its
 * values and error estimates (no floor: hemisphere_moments adds it).
 * refine = 0: the default budget; 1: every outer panel cut in five graded pieces, 32 trapezoid
 * intervals, phi grading x2 instead of x4 and every phi panel halved. Levels L >= 2 (the
 * convergence report's ladder, not the bake): each of the five pieces cut in 2^(L-1), every phi
 * panel in 2^L, and GK15 panels on whole circles too. Callers refine the few texels whose bound is above
 * their target (hemisphere_moments_to). */
BRDF_FN HemiResult hemi_rule_peaked(int ndf, int gaf, BrdfParams p, real mu, int refine) {
  HemiResult res;
  res.a = 0;
  res.b = 0;
  res.err_a = 0;
  res.err_b = 0;
  real s = sqrt((RC(1.0) - mu) * (RC(1.0) + mu));
  float col[SMITH_NZ];
  p = hemi_view(ndf, gaf, p, mu, s, col);
  if (p.alpha <= RC(0.0)) {
    /* alpha = 0: the NDF is a delta at h = n, so E = (G/no) F (o.h)/(n.h) at the mirror direction. */
    BrdfAngle h;
    h.c = RC(1.0);
    h.s2 = RC(0.0);
    h.t2 = RC(0.0);
    real fa, fb;
    hemi_node(ndf, gaf, p, mu, s, h, RC(0.0), RC(1.0), &fa, &fb);
    res.a = fa;
    res.b = fb;
    return res;
  }
  real t1 = mu / (RC(1.0) + s);
  real t2 = (RC(1.0) + s) / mu; /* +inf at mu = 0 */
  real v1 = ndf_v_of_tan2(ndf, p, t1 * t1);
  real v2 = ndf_v_of_tan2(ndf, p, t2 * t2);
  real vend = fmin(v2, HEMI_VCAP);
  /* Outer breakpoints. Full region [0, v1]: the fixed HEMI_BREAKS; partial region [v1, v2]: the
   * same widths counted from v1 (the integrand decays like e^-(v - v1) there too). A break that
   * would leave a panel ending within half its width of v1 or v2 is dropped: such a panel would see
   * the square-root end just outside itself, unsubstituted. Plus the GAF's kink crossings. */
  real bp[HEMI_MAX_BREAKS];
  int nbp = 0;
  real prev = RC(0.0);
  for (int k = 0; k < HEMI_NBREAKS; ++k) {
    real b = HEMI_BREAKS[k];
    if (b < v1 && v1 - b >= RC(0.5) * (b - prev) && b < vend) {
      bp[nbp++] = b;
      prev = b;
    }
  }
  if (v1 < vend) bp[nbp++] = v1;
  /* The horizon layer of gaf_horizon_layer: a break at tan theta_h = 2 tan theta_1, where the arc
   * is down to about two thirds of the circle; the 4-fold grading below then carries the panels
   * out to v1 + 1.
   * Measured (double, against the reference, 143 texels of each 128^2 table): ggx + kelemen at
   * mu = 1/256 missed by 8e-7 of the value without it, by 1e-10 with it. */
  if (gaf_horizon_layer(gaf) && v1 < vend) {
    real d = ndf_v_of_tan2(ndf, p, RC(4.0) * t1 * t1) - v1;
    if (d > RC(0.0) && d < RC(0.25) && v1 + d < vend) bp[nbp++] = v1 + d;
  }
  prev = v1;
  for (int k = 0; k < HEMI_NBREAKS; ++k) {
    real b = v1 + HEMI_BREAKS[k];
    if (b < vend && vend - b >= RC(0.5) * (b - prev)) {
      bp[nbp++] = b;
      prev = b;
    }
  }
  real gt2[GAF_MAX_THETA_BREAKS], gv[GAF_MAX_THETA_BREAKS];
  int ng = gaf_theta_breaks(gaf, mu, s, gt2);
  for (int k = 0; k < ng; ++k) {
    gv[k] = ndf_v_of_tan2(ndf, p, gt2[k]);
    bp[nbp++] = gv[k];
  }
  /* Fresnel's kink curve o.h = oc = cos(tk) meets the arc's ends where the phi integral changes
   * form: at phi = 0 (o.h = cos(theta_h - theta_o)): theta_h = theta_o -+ tk; at phi = pi
   * (o.h = cos(theta_h + theta_o)): theta_h = tk - theta_o; at the horizon end (n.i = 0, so
   * o.h = mu/(2 c)): c = mu/(2 oc). */
  real oc = fresnel_kink(p.moments, p.fresnel, p.fr_x, p.fr_z);
  real fv[4]; /* there the phi integral has a square-root end in theta: panels beside them substitute */
  int nfv = 0;
  if (oc > RC(0.0)) {
    real ct2[3];
    int nc = hemi_cross_tan2(mu, s, oc, ct2);
    for (int k = 0; k < nc; ++k) {
      fv[nfv] = ndf_v_of_tan2(ndf, p, ct2[k]);
      bp[nbp++] = fv[nfv++];
    }
  }
  /* The Fresnel layer's graded o.h levels X (fresnel_layer_levels) enter or leave the arc's o.h
   * range where the kink's crossings are for X = oc: the phi integral changes form there, and
   * without these breaks one outer panel spans the whole layer (azimuth.h hemi_phi_plan grades phi). */
  real lv[FRESNEL_MAX_LEVELS];
  int nlv = fresnel_layer_levels(p.moments, p.fresnel, p.fr_x, p.fr_y, p.fr_z, lv);
  for (int j = 0; j < nlv; ++j) {
    real ct2[3];
    int nc = hemi_cross_tan2(mu, s, lv[j], ct2);
    for (int k = 0; k < nc && nbp < HEMI_MAX_BREAKS; ++k) {
      real vb = ndf_v_of_tan2(ndf, p, ct2[k]);
      if (vb > RC(0.0) && vb < vend) bp[nbp++] = vb;
    }
  }
  sort_ascending(bp, nbp);
  real cur = RC(0.0);
  int ib = 0;
  while (cur < vend) {
    while (ib < nbp && bp[ib] <= cur) ++ib;
    real next = ib < nbp ? fmin(bp[ib], vend) : vend;
    int partial = cur >= v1;
    /* A square-root end just outside a panel (v1 before it, v2 after it) spoils GK15 as surely as
     * one inside. Panels that do not start at v1 (end at v2) are kept within 3 times their distance
     * from it, as HEMI_BREAKS are by construction: a GAF break close to v1 (cook-torrance at
     * grazing views puts one at ~4 v1) would otherwise leave a long panel right beside it. */
    if (partial && cur > v1) next = fmin(next, v1 + RC(4.0) * (cur - v1));
    if (partial && next < v2 && v2 <= HEMI_VCAP && next - cur > RC(3.0) * (v2 - next)) {
      real d = v2 - next;
      while (v2 - RC(4.0) * d > cur) d *= RC(4.0);
      next = v2 - d;
    }
    int sq_lo = (partial && cur == v1) || (cur == RC(0.0) && gaf_root_at_normal(gaf));
    int sq_hi = next == v2;
    for (int k = 0; k < nfv; ++k) {
      sq_lo |= cur == fv[k];
      sq_hi |= next == fv[k];
    }
    /* beside the GAF's theta breaks the phi integral goes as a 3/2 power (gaf_theta_breaks): the
     * square substitution makes that y^3 */
    for (int k = 0; k < ng; ++k) {
      sq_lo |= cur == gv[k];
      sq_hi |= next == gv[k];
    }
    hemi_panel(ndf, gaf, p, mu, s, t1, v1, cur, next, partial, sq_lo, sq_hi, refine, &res);
    cur = next;
  }
  res.a *= BRDF_INV_PI;
  res.b *= BRDF_INV_PI;
  res.err_a *= BRDF_INV_PI;
  res.err_b *= BRDF_INV_PI;
  return res;
}

/* k_p = int p(h)(n.h) dw_h = int_0^inf e^-v (p/D_grid)(v) dv on the same v grid (ndf.h), GK15 panels.
 * Exact (pi alpha^2) for GGX, Beckmann and Blinn-Phong, where p/D_grid is constant; the gaussian's
 * p/D_ggx decays faster than e^-v grows, so the panels up to HEMI_VCAP hold all of it. err: bound. */
BRDF_FN real ndf_kp(int ndf, BrdfParams p, real* err) {
  acc_t sum = 0, e = 0;
  real cur = RC(0.0);
  for (int i = 0; i < HEMI_NBREAKS; ++i) {
    real len = HEMI_BREAKS[i] - cur;
    real sk = RC(0.0), sd = RC(0.0);
    for (int k = 0; k < 15; ++k) {
      real v = cur + RC(0.5) * len * (GK15_XL[k] + RC(1.0));
      BrdfAngle a = ndf_angle_of_v(ndf, p, v);
      real f = exp(-v) * ndf_p_over_D_grid(ndf, p, a.c, a.s2);
      sk += GK15_WKL[k] * f;
      sd += GK15_WDL[k] * f;
    }
    sum += RC(0.5) * len * sk;
    e += RC(0.5) * len * fabs(sd);
    cur = HEMI_BREAKS[i];
  }
  *err = (real)e;
  return (real)sum;
}

/* The same value with a panel's nodes in lanes, without the bound: brdf_params needs the gaussian's
 * k_p per texel, and the lanes evaluate it faster than the 75 nodes one by one
 * (docs/performance.md, "Kernel choices"). The kp table keeps ndf_kp: its |K15 - G7| is rounding
 * noise on the closed-form NDFs, and in the lanes' summation order the ggx table claimed 2.9e-7
 * against a true error of 6.1e-8, 4.7 times (sequential: 2.65e-7 against 1.13e-7;
 * brdfbake-bench --bounds --size 64 --stride 8). */
BRDF_FN real ndf_kp_lanes(int ndf, BrdfParams p) {
  acc_t sum = 0;
  real cur = RC(0.0);
  for (int i = 0; i < HEMI_NBREAKS; ++i) {
    real len = HEMI_BREAKS[i] - cur, sk = RC(0.0);
    for (int k = 0; k + BRDF_LANES <= HEMI_GK_N; k += BRDF_LANES) {
      lane_t v = cur + RC(0.5) * len * (lane_load(GK15_XL, k) + RC(1.0)), c, s2, t2;
      ndf_angle_v(ndf, p, v, &c, &s2, &t2);
      sk += lane_sum(lane_load(GK15_WKL, k) * exp(-v) * ndf_p_over_D_grid(ndf, p, c, s2));
    }
    sum += RC(0.5) * len * sk;
    cur = HEMI_BREAKS[i];
  }
  return (real)sum;
}

/* Per-texel parameters from perceptual roughness r: alpha = r^2, Schlick's k, and for the gaussian
 * 1/k_p (computed, no closed form; its error is folded into the estimate's by the caller). */
BRDF_FN BrdfParams brdf_params(int ndf, int gaf, real r) {
  BrdfParams p = brdf_params_kp(gaf, r, RC(0.0));
  if (ndf == NDF_GAUSSIAN && p.alpha > RC(0.0)) {
    p.inv_kp = RC(1.0) / ndf_kp_lanes(ndf, p);
  }
  return p;
}
#endif /* BRDF_HEMISPHERE_H */
