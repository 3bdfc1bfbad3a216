/* azimuth.h: the inner (azimuth) rules of the hemisphere estimators (hemisphere.h holds the
 * derivation): int_0^phimax H dphi at fixed theta_h, by the trapezoid rule on whole circles or
 * GK15 panels on arcs, split at the GAF's and Fresnel's kinks and graded towards the horizon.
 * Needs integrand.h and quadrature.h; hemisphere.h, which calls hemi_phi, comes after it, and
 * azimuth_lanes.h holds the same rules transposed for the device. The rules here and in
 * hemisphere.h take the texel's fixed view as arguments (ndf, gaf, p, mu, s), not as one struct:
 * a struct of them, passed by value and read into locals, measured slower on PoCL
 * (docs/performance.md, "Kernel choices"). */
/* Once per pass (compat.h "Passes"). */
#if defined(BRDF_SECOND_PASS) ? !defined(BRDF_AZIMUTH_H_2) : !defined(BRDF_AZIMUTH_H)
#ifdef BRDF_SECOND_PASS
#define BRDF_AZIMUTH_H_2
#else
#define BRDF_AZIMUTH_H
#endif
#include "integrate/lanes.h"
#include "integrate/quadrature.h"
/* The azimuth's budgets (the brdf.method text is generated from these: host/bake/bake.cpp). */
#define HEMI_TRAP_N 16             /* trapezoid intervals on the whole circle; refined: twice as many */
#define HEMI_PHI_GROW RC(4.0)      /* grading of the arc panels towards phimax; refined: halved */
#define HEMI_PHI_GROW_OWN RC(16.0) /* the same from the Smith/Schlick layer n.i ~ alpha (hemi_phi) */

/* Whether the GAF's shadowing of i changes on the scale n.i ~ alpha rather than n.i ~ mu: the Smith
 * Lambdas (Lambda_i ~ alpha tan(theta_i), so G1(i) goes from ~1 to ~n.i/alpha within n.i ~ alpha)
 * and Schlick's G1 = n.i/(n.i (1 - k) + k) with k ~ alpha (schlick-ggx-direct's k >= 1/8 is not). */
BRDF_FN int hemi_gaf_alpha_layer(int gaf) {
  return gaf == GAF_SMITH || gaf == GAF_SMITH_CORRELATED || gaf == GAF_SMITH_EXACT ||
         gaf == GAF_SMITH_CORRELATED_EXACT || gaf == GAF_SCHLICK_GGX || gaf == GAF_SCHLICK_BECKMANN;
}

/* cos(x) on the azimuth's range, x in [0, pi] (valid to pi/2 + 1.65 either side of pi/2): in float,
 * -sin(x - pi/2) with pi/2 in two parts (Cody and Waite) and an odd polynomial of degree 11
 * fitted to sin by least squares on Chebyshev nodes (relative error 4.4e-11 in exact arithmetic;
 * tools/fit_polynomials.py cos); within 1.4e-7 of cos(x) in float (1.6e-7 without fused
 * multiply-adds: tests/float_forms_test.cpp), the size of the node's own
 * rounding (phi near pi is within 1.2e-7). In double (the host's brdf64) libm's cos. Measured: the
 * library cos took 28% of ggx + cook-torrance's split-sum kernel, 20% of ggx + smith-correlated's
 * (perf). */
BRDF_FN lane_t cos_arc(lane_t x) {
  if (sizeof(lane_t) == 8) return cos(x);
  lane_t u = (x - RC(1.57079637050628662109375)) - RC(-4.37113882867379e-08);
  lane_t w = u * u;
  lane_t q = RC(-2.3768219438410352e-08);
  q = q * w + RC(2.7518271965282657e-06);
  q = q * w + RC(-0.00019840723020309498);
  q = q * w + RC(0.008333329914426554);
  q = q * w + RC(-0.16666666592166149);
  q = q * w + RC(0.99999999998301103);
  return -(q * u);
}

/* One GK15 panel's node values over phi in [lo, hi] (the nodes GK15_XL from k), the substitution's
 * Jacobian applied (sq_lo, sq_hi: hemi_phi_gk). */
BRDF_FN void hemi_phi_gk_values(int ndf, int gaf, BrdfParams p, real mu, real s, BrdfAngle h, real sn, real lo, real hi,
                                int sq_lo, int sq_hi, int k, lane_t* fa, lane_t* fb) {
  real hw = RC(0.5) * (hi - lo), mid = RC(0.5) * (hi + lo), len = hi - lo;
  lane_t x = lane_load(GK15_XL, k);
  if (sq_lo || sq_hi) {
    lane_t y = RC(0.5) * (x + RC(1.0)), phi, jac;
    if (sq_lo && sq_hi) {
      phi = lo + len * y * y * (RC(3.0) - RC(2.0) * y);
      jac = RC(3.0) * y * (RC(1.0) - y); /* (dphi/dy)/(2 hw) */
    } else if (sq_lo) {
      phi = lo + len * y * y;
      jac = y;
    } else {
      phi = hi - len * (RC(1.0) - y) * (RC(1.0) - y);
      jac = RC(1.0) - y;
    }
    hemi_node(ndf, gaf, p, mu, s, h, sn, cos_arc(phi), fa, fb);
    *fa *= RC(2.0) * jac;
    *fb *= RC(2.0) * jac;
  } else {
    hemi_node(ndf, gaf, p, mu, s, h, sn, cos_arc(mid + hw * x), fa, fb);
  }
}

/* GK15 over phi in [lo, hi]: adds the Kronrod values to ka, kb and their error estimates
 * (gk_error) to ea, eb. All 15 nodes in one lane vector on the device (HEMI_GK_N = 16, the last of
 * weight 0); the nodes' values are kept for resasc (a second pass over them).
 * The estimates here and on hemisphere.h's outer panels are sharpened (gk_error, sharp = 1) for
 * every pair: the integrand is analytic on and near each panel, because the panels end where it is
 * not. The min/max kinks of cook-torrance and neumann and charlie-smith's branch switch sit on
 * panel ends in phi (gaf_kinks) and in theta_h (gaf_theta_breaks), with substitutions where the
 * phi integral has a root or 3/2-power end (gaf_root_at_normal, the theta breaks) and where G
 * itself is singular at i's horizon (gaf_root_at_horizon); the horizon layers of `none` and
 * kelemen are graded (gaf_horizon_layer). Without those panel ends, the rescaled estimates miss by
 * up to 1.3e-6 of the value (none, cook-torrance, kelemen, neumann) and fall 4 times below the
 * error (the charlie NDF), where |K15 - G7| runs 6 to 52 times the error.
 * sq_lo / sq_hi: an end with a square-root singularity in the integrand (Fresnel's critical
 * angle) or a power of n.i (charlie-smith at phimax), eased by phi = lo + L y^2 (hi - L (1 - y)^2;
 * the smoothstep for both). */
BRDF_FN void hemi_phi_gk(int ndf, int gaf, BrdfParams p, real mu, real s, BrdfAngle h, real sn, real lo, real hi,
                         int sq_lo, int sq_hi, real* ka, real* kb, real* ea, real* eb) {
  real hw = RC(0.5) * (hi - lo);
  real sa = RC(0.0), sb = RC(0.0), da = RC(0.0), db = RC(0.0);
  real ra = RC(0.0), rb = RC(0.0); /* resasc: the Kronrod weights sum to 2, so the mean is sa/2 */
#if BRDF_LANES < HEMI_GK_N
  real va[16], vb[16]; /* the host: one node per pass, kept for resasc's second pass */
#endif
  int k = 0;
  for (; k + BRDF_LANES <= HEMI_GK_N; k += BRDF_LANES) {
    lane_t fa, fb;
    hemi_phi_gk_values(ndf, gaf, p, mu, s, h, sn, lo, hi, sq_lo, sq_hi, k, &fa, &fb);
    lane_t wk = lane_load(GK15_WKL, k), wd = lane_load(GK15_WDL, k);
#if BRDF_LANES < HEMI_GK_N
    sa += lane_sum(wk * fa);
    sb += lane_sum(wk * fb);
    da += lane_sum(wd * fa);
    db += lane_sum(wd * fb);
    lane_store(fa, va, k);
    lane_store(fb, vb, k);
  }
  for (k = 0; k < HEMI_GK_N; ++k) {
    ra += GK15_WKL[k] * fabs(va[k] - RC(0.5) * sa);
    rb += GK15_WKL[k] * fabs(vb[k] - RC(0.5) * sb);
  }
  real ga = gk_error(fabs(da), ra, 1), gb = gk_error(fabs(db), rb, 1);
#else
    /* the device: every node is in this one pass, so the mean is known already */
    float4 s4 = lane_sum4(wk * fa, wk * fb, wd * fa, wd * fb);
    sa = s4.x;
    sb = s4.y;
    da = s4.z;
    db = s4.w;
    float2 r2 = lane_sum2(wk * fabs(fa - RC(0.5) * sa), wk * fabs(fb - RC(0.5) * sb));
    ra = r2.x;
    rb = r2.y;
  }
  /* both moments' gk_error at once: lane by lane gk_error's operations, so its bits */
  float2 g2 = gk_error4((float4)(fabs(da), fabs(db), RC(0.0), RC(0.0)), (float4)(ra, rb, RC(0.0), RC(0.0))).xy;
  real ga = g2.x, gb = g2.y;
#endif
  *ka += sa * hw;
  *kb += sb * hw;
  *ea += ga * hw;
  *eb += gb * hw;
}

#if BRDF_LANES >= HEMI_GK_N
/* hemi_phi_gk on [lo1, hi1], then on [lo2, hi2] (p12), two panels of one azimuth integral (the
 * refined budget and the whole-circle arcs of kinked GAFs; partial panels at the default budget
 * run transposed, hemi_arcs_lanes); sq12: each
 * one's sq_lo + 2 sq_hi. The same bits as the two calls: each lane vector goes through the same
 * reduction tree as alone (compat.h lane_sum4), and gk_error4 works lane by lane. What it saves is
 * the wait: a panel's resasc waits on its mean and its estimate on its resasc, and the other
 * panel's reductions run beside them. It measured faster than one panel at a time; pairing the
 * panels of neighbouring outer nodes as well, or two nodes' trapezoids, gained nothing more
 * (docs/performance.md, "Kernel choices"). */
BRDF_FN void hemi_phi_gk_pair(int ndf, int gaf, BrdfParams p, real mu, real s, BrdfAngle h, real sn, float4 p12,
                              int2 sq12, real* ka, real* kb, real* ea, real* eb) {
  lane_t fa1, fb1, fa2, fb2;
  hemi_phi_gk_values(ndf, gaf, p, mu, s, h, sn, p12.x, p12.y, sq12.x & 1, sq12.x >> 1, 0, &fa1, &fb1);
  hemi_phi_gk_values(ndf, gaf, p, mu, s, h, sn, p12.z, p12.w, sq12.y & 1, sq12.y >> 1, 0, &fa2, &fb2);
  lane_t wk = lane_load(GK15_WKL, 0), wd = lane_load(GK15_WDL, 0);
  float4 s1 = lane_sum4(wk * fa1, wk * fb1, wd * fa1, wd * fb1);
  float4 s2 = lane_sum4(wk * fa2, wk * fb2, wd * fa2, wd * fb2);
  float4 r4 = lane_sum4(wk * fabs(fa1 - RC(0.5) * s1.x), wk * fabs(fb1 - RC(0.5) * s1.y),
                        wk * fabs(fa2 - RC(0.5) * s2.x), wk * fabs(fb2 - RC(0.5) * s2.y));
  float4 g4 = gk_error4((float4)(fabs(s1.z), fabs(s1.w), fabs(s2.z), fabs(s2.w)), r4);
  real hw1 = RC(0.5) * (p12.y - p12.x), hw2 = RC(0.5) * (p12.w - p12.z);
  *ka += s1.x * hw1;
  *kb += s1.y * hw1;
  *ea += g4.x * hw1;
  *eb += g4.y * hw1;
  *ka += s2.x * hw2;
  *kb += s2.y * hw2;
  *ea += g4.z * hw2;
  *eb += g4.w * hw2;
}
#endif

/* A trapezoid's running sums (values, n/2 and n/4 differences) before its last node, phi = pi,
 * which hemisphere.h evaluates for a whole outer panel's nodes in one lane vector. */
typedef struct TrapSums {
  real sa, sb, da, db, ca, cb;
  int n; /* intervals; 0: the arc's rule ran instead (hemi_phi's results are final) */
} TrapSums;

/* Adds the node phi = pi (fa, fb) to t and gives the trapezoid's values and error estimates. */
BRDF_FN void hemi_trap_finish(TrapSums t, real fa, real fb, real* ia, real* ib, real* ea, real* eb) {
  int n = t.n;
  BRDF_TABLE real* w = n == 32 ? TRAP32_W : TRAP16_W;
  BRDF_TABLE real* d = n == 32 ? TRAP32_D : TRAP16_D;
  BRDF_TABLE real* d2 = n == 32 ? TRAP32_D2 : TRAP16_D2;
  t.sa += w[n] * fa;
  t.sb += w[n] * fb;
  t.da += d[n] * fa;
  t.db += d[n] * fb;
  t.ca += d2[n] * fa;
  t.cb += d2[n] * fb;
  real step = BRDF_PI / (real)n;
  *ia = t.sa * step;
  *ib = t.sb * step;
  *ea = trap_error(fabs(t.da), fabs(t.ca)) * step;
  *eb = trap_error(fabs(t.db), fabs(t.cb)) * step;
}

/* Trapezoid on the whole half-circle with n = 16 or 32 intervals (nodes cos(k pi/n)), all but the
 * last node (phi = pi): its sums, which hemi_trap_finish completes into the values and the error
 * estimates from the n/2- and n/4-interval rules (trap_error). Lane vectors of nodes. The last
 * nodes of a panel's 15 outer nodes go in one lane vector (hemisphere.h), faster than one by one
 * in scalar code (docs/performance.md, "Kernel choices"). On the device a panel whose nodes all
 * take the 16 intervals plainly runs transposed instead (hemi_trap_lanes, the same bits); this form
 * serves the refined budget, the panels with kinks and the host. */
BRDF_FN TrapSums hemi_phi_trap(int ndf, int gaf, BrdfParams p, real mu, real s, BrdfAngle h, real sn, int n) {
  BRDF_TABLE real* cs = n == 32 ? COS_PI32 : COS_PI16;
  BRDF_TABLE real* w = n == 32 ? TRAP32_W : TRAP16_W;
  BRDF_TABLE real* d = n == 32 ? TRAP32_D : TRAP16_D;
  BRDF_TABLE real* d2 = n == 32 ? TRAP32_D2 : TRAP16_D2;
  TrapSums t;
  t.sa = RC(0.0), t.sb = RC(0.0), t.da = RC(0.0), t.db = RC(0.0), t.ca = RC(0.0), t.cb = RC(0.0);
  t.n = n;
  for (int k = 0; k + BRDF_LANES <= n; k += BRDF_LANES) { /* n is a multiple of the lanes */
    lane_t fa, fb;
    hemi_node(ndf, gaf, p, mu, s, h, sn, lane_load(cs, k), &fa, &fb);
    lane_t wk = lane_load(w, k), dk = lane_load(d, k), ek = lane_load(d2, k);
#if BRDF_LANES > 1
    float4 s4 = lane_sum4(wk * fa, wk * fb, dk * fa, dk * fb); /* compat.h */
    float2 c2 = lane_sum2(ek * fa, ek * fb);
    t.sa += s4.x;
    t.sb += s4.y;
    t.da += s4.z;
    t.db += s4.w;
    t.ca += c2.x;
    t.cb += c2.y;
#else
    t.sa += lane_sum(wk * fa);
    t.sb += lane_sum(wk * fb);
    t.da += lane_sum(dk * fa);
    t.db += lane_sum(dk * fb);
    t.ca += lane_sum(ek * fa);
    t.cb += lane_sum(ek * fb);
#endif
  }
  return t;
}

/* The most breakpoints inside one arc, and the most panels it takes (its breakpoints and phimax):
 * room for the GAF's and Fresnel's kinks, the horizon grading and the Fresnel layer's grades. */
#define HEMI_PHI_MAXB 32
#define HEMI_ARC_PANELS (HEMI_PHI_MAXB + 1)

/* hemi_phi's set-up at fixed theta_h: 1 when the node takes the whole-circle trapezoid, else 0
 * with its arc's panels, in order: panel m spans [lo[m st], hi[m st]] and sq[m st] is its
 * sq_lo + 2 sq_hi (hemi_phi_gk: the ends at Fresnel's kink, and the horizon end where G is
 * singular there); *np panels, at most HEMI_ARC_PANELS. st: the stride, 1 for hemi_phi's own
 * arrays, 16 where hemi_arcs_lanes keeps a panel of every outer node side by side (written in
 * place there: a copy through one node's arrays measured slower (docs/performance.md, "Kernel choices")). */
BRDF_FN int hemi_phi_plan(int gaf, BrdfParams p, real mu, real s, BrdfAngle h, real sn, int full, real phimax,
                          real sinmax, int refine, real* lo_, real* hi_, int* sq_, int st, int* np) {
  /* zeroed: only the first nk are read, which GCC's host build cannot see (-Wmaybe-uninitialized) */
  real kinks[4] = {RC(0.0), RC(0.0), RC(0.0), RC(0.0)};
  int nk = gaf_kinks(gaf, mu, s, h.c, sn, kinks);
  /* Fresnel's kink at o.h = oc (total internal reflection): cos phi = (oc - mu c)/(s sn), formed
   * as the integrand forms o.h - oc (integrand.h hemi_kink_offset); F has a square-root end there
   * (panels beside it substitute) */
  real oc_lo, oc = fresnel_kink_split(p.moments, p.fresnel, p.fr_x, p.fr_z, &oc_lo);
  real fk = RC(-1.0);
  /* Where the kink nearly touches phi = pi, F's square root sits close to the real axis without
   * being on a panel end: sqrt(x - oc) with x - oc ~ d + (s sn/2)(pi - phi)^2 near pi, singular at
   * pi -+ i a, a = acosh(-ck) ~ sqrt(2 d/(s sn)) (the whole circle above oc: ck < -1), or, with the
   * kink on the arc at fk close to pi, at fk and at its mirror 2 pi - fk, a = 2 (pi - fk) beyond
   * the panel's end. The 16-interval trapezoid converges like e^-(32 a), too slowly below a ~ 1,
   * and there its estimate d1 (d1/d2)^2 is not yet asymptotic: it fell 3 to 4 times below the
   * error (eta = 1/1.5, ggx + smith-correlated, mu = 0.92, r = 0.86: error 3.9e-7 of E_F, estimate
   * 1.3e-7). GK15 panels graded 4-fold from that distance towards fg resolve it instead
   * (sqrt_near_pi, quadrature.h). */
  real fg = RC(-1.0), fw = RC(0.0); /* the graded point and the first panel's width (fw = 0: none) */
  if (oc > RC(0.0) && s * sn > RC(0.0)) {
    real ck = -hemi_kink_offset(mu, h.c, h.s2, oc, oc_lo) / (s * sn);
    if (ck < RC(1.0) && ck > RC(-1.0)) {
      fk = acos(ck);
      kinks[nk++] = ck;
    }
    fw = sqrt_near_pi(ck, &fg);
  }
  /* The Fresnel layer's graded o.h levels (fresnel_layer_levels) where the arc crosses them: their
   * own breakpoints, so that each panel sees F change by a bounded factor. */
  real br[HEMI_PHI_MAXB];
  int nb = 0;
  real lv[FRESNEL_MAX_LEVELS];
  int nlv = s * sn > RC(0.0) ? fresnel_layer_levels(p.moments, p.fresnel, p.fr_x, p.fr_y, p.fr_z, lv) : 0;
  for (int k = 0; k < nlv; ++k) {
    real cp = (lv[k] - mu * h.c) / (s * sn);
    if (cp > RC(-1.0) && cp < RC(1.0) && acos(cp) < phimax) br[nb++] = acos(cp);
  }
  if (full && nk == 0 && nb == 0 && fw <= RC(0.0) && refine <= 1) return 1;
  /* Breakpoints inside (0, phimax): the GAF's kinks, and on a partial arc a geometric grading
   * towards phimax. There n.i -> 0, and many GAFs (kelemen's 1/(o.h)^2, Smith's n.i/(n.o Lambda_i),
   * cook-torrance) change on the scale where n.i ~ mu, a layer of width
   * dphi ~ mu/(2 c s sn sin(phimax)) (n.i = 2 c s sn (cos phi - c0)); the Smith and Schlick GAFs
   * on the scale n.i ~ alpha where that is finer (hemi_gaf_alpha_layer: at alpha << mu the mu
   * layer left it inside one panel, which both under-resolved it and inflated |K15 - G7| there).
   * Panels of width dphi 4^k resolve it with a fixed number of nodes per panel, whatever mu. */
  for (int k = 0; k < nk; ++k) {
    if (kinks[k] < RC(1.0) && kinks[k] > RC(-1.0)) {
      real a = acos(kinks[k]);
      if (a < phimax) br[nb++] = a;
    }
  }
  if (!full) {
    real den = s * sn * fmax(sinmax, RC(1e-30));
    /* The Smith and Schlick GAFs change on their own scale, n.i ~ alpha, whatever mu: graded from
     * n.i = 2 alpha with panels growing 16-fold (G1(i) ~ n.i/(n.i + alpha) has its pole a panel's
     * width or more outside each panel, so GK15 converges there like rho^-30 with rho >= 2).
     * Measured on the default 128^2 ggx + smith-correlated split sum against grading from
     * min(mu, alpha) 4-fold: 0.72 of the kernel time, 57 instead of 53 texels refined; from alpha
     * 16-fold: 108 refined (the first panel sits inside the G1 transition), from 4 alpha: 274. */
    int own = hemi_gaf_alpha_layer(gaf) && p.alpha > RC(0.0);
    real layer = (own ? RC(2.0) * p.alpha : mu) / (RC(2.0) * h.c * den);
    /* Fresnel of eta slightly above 1 changes on the scale o.h ~ sqrt(eta^2 - 1), which the arc
     * reaches near its horizon end (o.h = mu/(2c) there, 0 at mu = 0): grade from that scale too. */
    real fs = fresnel_soft_scale(p.moments, p.fresnel, p.fr_x, p.fr_z);
    if (fs > RC(0.0)) {
      layer = layer > RC(0.0) ? fmin(layer, fs / den) : fs / den;
      own = 0; /* Fresnel's layer is not G1's: the 4-fold grading */
    }
    real grow = (refine ? RC(0.5) : RC(1.0)) * (own ? HEMI_PHI_GROW_OWN : HEMI_PHI_GROW);
    /* a grading break within d/4 of Fresnel's kink would leave the panel beside the kink ending
     * just short of its square root, unsubstituted: its |K15 - G7| then stood 240 times above the
     * error (eta = 1/1.5, mu = 0.73, r = 0.48, the refined budget); the kink's own break serves */
    /* Where H is a polynomial in cos(phi) between the kinks (gaf_polynomial_arc, with a Schlick or
     * F82 weight) there is no layer to resolve. Without the grading the default budget's largest
     * error against the refined budget at level 3 stays the same (cook-torrance 2.7e-9, none
     * 1.9e-8, neumann 1.9e-8, implicit 1.3e-9; double, ggx's 128^2 edge texels and every 9th
     * inside, a one-off harness, not kept) on 25% to 48% fewer nodes; what the repository keeps:
     * the pair tests' edge texels against the reference, and `brdfbake-bench --bounds --stride 8
     * --pair ggx+cook-torrance --pair beckmann+none --pair gaussian+neumann` (0 texels over). */
    int graded = !(gaf_polynomial_arc(gaf) && p.moments != HEMI_FRESNEL);
    for (real d = layer; graded && d < RC(0.5) * phimax && nb < HEMI_PHI_MAXB; d *= grow)
      if (!(fk >= RC(0.0) && fabs(phimax - d - fk) < RC(0.25) * d)) br[nb++] = phimax - d;
  }
  if (fw > RC(0.0)) {
    real grow = refine ? RC(0.5) * HEMI_PHI_GROW : HEMI_PHI_GROW;
    for (real d = fw; d < RC(0.5) * fg && nb < HEMI_PHI_MAXB; d *= grow)
      if (fg - d < phimax) br[nb++] = fg - d;
  }
  sort_ascending(br, nb);
  /* the panels between the breakpoints (an empty one, where two coincide, is left out) */
  int m = 0;
  real lo = RC(0.0);
  for (int k = 0; k <= nb; ++k) {
    real hi = k < nb ? br[k] : phimax;
    if (hi > lo) {
      int sl = lo == fk, sh = hi == fk;
      int hz = !full && hi == phimax && gaf_root_at_horizon(gaf); /* G singular at n.i = 0 (gaf.h) */
      lo_[m * st] = lo;
      hi_[m * st] = hi;
      sq_[m * st] = sl | ((sh || hz) << 1);
      m++;
    }
    lo = hi;
  }
  *np = m;
  return 0;
}

/* int_0^phimax H dphi at fixed theta_h (full: phimax = pi; sn = sin theta_h, sinmax = sin phimax).
 * Results in ia, ib; bounds in ea, eb; or, on a whole circle without kinks, the trapezoid's sums
 * without its last node in *trap (trap->n > 0), for hemi_trap_finish. */
BRDF_FN void hemi_phi(int ndf, int gaf, BrdfParams p, real mu, real s, BrdfAngle h, real sn, int full, real phimax,
                      real sinmax, int refine, real* ia, real* ib, real* ea, real* eb, TrapSums* trap) {
  trap->n = 0;
  *ia = RC(0.0);
  *ib = RC(0.0);
  *ea = RC(0.0);
  *eb = RC(0.0);
  real plo[HEMI_ARC_PANELS], phi_[HEMI_ARC_PANELS];
  int psq[HEMI_ARC_PANELS], np;
  if (hemi_phi_plan(gaf, p, mu, s, h, sn, full, phimax, sinmax, refine, plo, phi_, psq, 1, &np)) {
    *trap = hemi_phi_trap(ndf, gaf, p, mu, s, h, sn, refine ? 2 * HEMI_TRAP_N : HEMI_TRAP_N);
    return;
  }
#if BRDF_LANES >= HEMI_GK_N
  /* the panels two at a time (hemi_phi_gk_pair), in order; an odd one last, alone */
  real hlo = RC(0.0), hhi = RC(0.0);
  int hsq = 0, held = 0;
#endif
  for (int m = 0; m < np; ++m) {
    real lo = plo[m], hi = phi_[m];
    /* 2^refine equal pieces; the substitutions stay on the pieces that touch the kink */
    int pieces = 1 << refine;
    real w = (hi - lo) / (real)pieces;
    for (int q = 0; q < pieces; ++q) {
      real a = lo + w * (real)q, b = q + 1 < pieces ? lo + w * (real)(q + 1) : hi;
      int sq = (q == 0 ? psq[m] & 1 : 0) | (q + 1 == pieces ? psq[m] & 2 : 0);
#if BRDF_LANES >= HEMI_GK_N
      if (held) {
        hemi_phi_gk_pair(ndf, gaf, p, mu, s, h, sn, (float4)(hlo, hhi, a, b), (int2)(hsq, sq), ia, ib, ea, eb);
        held = 0;
      } else {
        hlo = a;
        hhi = b;
        hsq = sq;
        held = 1;
      }
#else
      hemi_phi_gk(ndf, gaf, p, mu, s, h, sn, a, b, sq & 1, sq >> 1, ia, ib, ea, eb);
#endif
    }
  }
#if BRDF_LANES >= HEMI_GK_N
  if (held) hemi_phi_gk(ndf, gaf, p, mu, s, h, sn, hlo, hhi, hsq & 1, hsq >> 1, ia, ib, ea, eb);
#endif
}
#endif /* BRDF_AZIMUTH_H */
