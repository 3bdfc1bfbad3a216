/* azimuth_lanes.h: the azimuth rules of azimuth.h transposed, for the device: an outer panel's 15
 * nodes in the lanes and the azimuth nodes in a loop, instead of one lane vector of azimuth nodes
 * per outer node with its own reduction trees. Each lane adds its nodes in the order of the tree
 * it replaces (compat.h lane_sum4, lane_sum2) and its panels in hemi_phi's order, so the values
 * and estimates are hemi_phi's bits. hemisphere.h calls them at the default budget; the refined
 * budget, the whole-circle panels with kinks and the host (one lane) keep azimuth.h's form.
 * Needs azimuth.h (hemi_phi_plan, cos_arc) and the integrand's lane pass (lanes.h). */
/* Once per pass (compat.h "Passes"). */
#if defined(BRDF_SECOND_PASS) ? !defined(BRDF_AZIMUTH_LANES_H_2) : !defined(BRDF_AZIMUTH_LANES_H)
#ifdef BRDF_SECOND_PASS
#define BRDF_AZIMUTH_LANES_H_2
#else
#define BRDF_AZIMUTH_LANES_H
#endif
#include "integrate/azimuth.h"
#if BRDF_LANES >= HEMI_GK_N
/* Whether every node of a whole-circle outer panel takes the plain 16-interval trapezoid in
 * hemi_phi (no GAF kink, no Fresnel kink or layer, the default budget): then hemi_trap_lanes
 * serves them. */
BRDF_FN int hemi_trap_plain(int gaf, BrdfParams p, int refine) {
  real x0;
  int both;
  return refine == 0 && gaf != GAF_NEUMANN && gaf != GAF_COOK_TORRANCE && gaf != GAF_CHARLIE_SMITH &&
         !(fresnel_kink(p.moments, p.fresnel, p.fr_x, p.fr_z) > RC(0.0)) &&
         !(fresnel_layer(p.moments, p.fresnel, p.fr_x, p.fr_y, p.fr_z, &x0, &both) > RC(0.0));
}

/* Six sums of the four azimuth nodes i, i + 1, i + 8, i + 9, as lane_sum4's tree pairs them:
 * (x_i + x_(i+8)) + (x_(i+1) + x_(i+9)), each x a weight times a node's value, formed apart from
 * the sums as lane_sum4's arguments are (no multiply-add contraction). */
BRDF_FN void hemi_trap_quad(int ndf, int gaf, BrdfParams p, real mu, real s, lane_t c, lane_t sn, int i, lane_t* t) {
  lane_t fa[4], fb[4];
  int js[4] = {i, i + 8, i + 1, i + 9};
  for (int q = 0; q < 4; ++q) hemi_node_c(ndf, gaf, p, mu, s, c, sn, COS_PI16[js[q]], &fa[q], &fb[q]);
  BRDF_TABLE real* wts[3] = {TRAP16_W, TRAP16_D, TRAP16_D2};
  for (int m = 0; m < 3; ++m) {
    BRDF_TABLE real* w = wts[m];
    lane_t a0 = w[js[0]] * fa[0], a1 = w[js[1]] * fa[1], a2 = w[js[2]] * fa[2], a3 = w[js[3]] * fa[3];
    lane_t b0 = w[js[0]] * fb[0], b1 = w[js[1]] * fb[1], b2 = w[js[2]] * fb[2], b3 = w[js[3]] * fb[3];
    t[2 * m] = (a0 + a1) + (a2 + a3);
    t[2 * m + 1] = (b0 + b1) + (b2 + b3);
  }
}

/* The 16-interval trapezoids (hemi_phi_trap, hemi_trap_finish) of an outer panel's 15 nodes at
 * once: theta_h per lane (c, sn), the azimuth nodes in a loop (hemi_node_c, which forms a node as
 * hemi_node does). Each lane's sums add the weighted nodes in the order of the reduction tree
 * hemi_phi_trap uses (compat.h lane_sum4, lane_sum2) and the phi = pi node last, so every node's
 * values and estimates are the bits hemi_phi gives; what goes is the horizontal reductions and
 * the scalar set-up per node, which measured faster (docs/performance.md, "Kernel choices"). */
BRDF_FN void hemi_trap_lanes(int ndf, int gaf, BrdfParams p, real mu, real s, lane_t c, lane_t sn, lane_t* ia,
                             lane_t* ib, lane_t* ea, lane_t* eb) {
  lane_t t0[6], t1[6], t2[6], t3[6], sum[6];
  hemi_trap_quad(ndf, gaf, p, mu, s, c, sn, 0, t0);
  hemi_trap_quad(ndf, gaf, p, mu, s, c, sn, 2, t1);
  hemi_trap_quad(ndf, gaf, p, mu, s, c, sn, 4, t2);
  hemi_trap_quad(ndf, gaf, p, mu, s, c, sn, 6, t3);
  for (int q = 0; q < 6; ++q) sum[q] = RC(0.0) + ((t0[q] + t1[q]) + (t2[q] + t3[q]));
  lane_t fa, fb; /* the last node, phi = pi, as hemi_trap_finish adds it (one statement each, so the
                  * same contraction into a fused multiply-add) */
  hemi_node_c(ndf, gaf, p, mu, s, c, sn, RC(-1.0), &fa, &fb);
  sum[0] += TRAP16_W[16] * fa;
  sum[1] += TRAP16_W[16] * fb;
  sum[2] += TRAP16_D[16] * fa;
  sum[3] += TRAP16_D[16] * fb;
  sum[4] += TRAP16_D2[16] * fa;
  sum[5] += TRAP16_D2[16] * fb;
  real step = BRDF_PI / (real)16;
  *ia = sum[0] * step;
  *ib = sum[1] * step;
  *ea = trap_error16(fabs(sum[2]), fabs(sum[4])) * step;
  *eb = trap_error16(fabs(sum[3]), fabs(sum[5])) * step;
}

/* One lane per outer node: the sum of sixteen weighted node values v[j] in the order of the tree
 * that lane_sum4 and lane_sum2 (compat.h) give a lane vector of them. */
BRDF_FN lane_t hemi_tree16(const lane_t* v) {
  lane_t t0 = (v[0] + v[8]) + (v[1] + v[9]), t1 = (v[2] + v[10]) + (v[3] + v[11]);
  lane_t t2 = (v[4] + v[12]) + (v[5] + v[13]), t3 = (v[6] + v[14]) + (v[7] + v[15]);
  return (t0 + t1) + (t2 + t3);
}

/* hemi_phi on the arcs of an outer panel's 15 nodes at once, at the default budget (partial
 * panels: no node takes the trapezoid). Each node's panels come from hemi_phi_plan as hemi_phi
 * makes them; then panel m of every node is one pass, theta_h, the panel's ends and its
 * substitutions per lane, its 16 GK15 nodes in a loop. A node with fewer panels sits the later
 * passes out. Each lane's sums follow the reduction trees of hemi_phi_gk (hemi_tree16) and its
 * estimate gk_error's operations, and the panels are added in hemi_phi's order, so every node's
 * values and estimates are hemi_phi's bits. c, sn, phimax: per outer node (16 lanes, the 16th
 * unused); the results go to ia, ib, ea, eb (16 each). Over the default split sum's partial
 * panels 0.86 of the lanes' passes do work, and the form measured faster than a vector of GK15
 * nodes per panel. Only the passes a node sits out get their ends written: setting all 17 x 16 of
 * them first measured slower (docs/performance.md, "Kernel choices"). */
BRDF_FN void hemi_arcs_lanes(int ndf, int gaf, BrdfParams p, real mu, real s, const real* nc, const real* ns2,
                             const real* nt2, const real* nsn, const real* nphi, const real* nsin, real* ia, real* ib,
                             real* ea, real* eb) {
  real plo[HEMI_ARC_PANELS][16], phi_[HEMI_ARC_PANELS][16];
  int psq[HEMI_ARC_PANELS][16], np[16];
  int most = 0;
  for (int k = 0; k < 16; ++k) {
    np[k] = 0;
    if (k >= 15) continue;
    BrdfAngle h;
    h.c = nc[k];
    h.s2 = ns2[k];
    h.t2 = nt2[k];
    /* hemi_phi's panels, each at one piece (a = lo + 0 w, b = hi), panel m of node k at [m][k] */
    hemi_phi_plan(gaf, p, mu, s, h, nsn[k], 0, nphi[k], nsin[k], 0, &plo[0][k], &phi_[0][k], &psq[0][k], 16, &np[k]);
    most = np[k] > most ? np[k] : most;
  }
  for (int k = 0; k < 16; ++k) /* the passes a node sits out: defined ends, their sums unused */
    for (int m = np[k]; m < most; ++m) {
      plo[m][k] = RC(0.0);
      phi_[m][k] = RC(1.0);
      psq[m][k] = 0;
    }
  lane_t c = lane_load(nc, 0), sn = lane_load(nsn, 0);
  lane_t ka = RC(0.0), kb = RC(0.0), ga = RC(0.0), gb = RC(0.0);
  int16 count = vload16(0, np);
  for (int m = 0; m < most; ++m) {
    lane_t lo = lane_load(plo[m], 0), hi = lane_load(phi_[m], 0);
    int16 sq = vload16(0, psq[m]);
    lane_t hw = RC(0.5) * (hi - lo), mid = RC(0.5) * (hi + lo), len = hi - lo;
    int sub = any(sq != 0);
    lane_t fa[16], fb[16];
    for (int j = 0; j < 16; ++j) { /* hemi_phi_gk_values, lane by lane */
      real x = GK15_XL[j];
      lane_t phi = mid + hw * x;
      lane_t jac = RC(0.0);
      if (sub) {
        real y = RC(0.5) * (x + RC(1.0));
        lane_t both = lo + len * y * y * (RC(3.0) - RC(2.0) * y);
        lane_t atlo = lo + len * y * y;
        lane_t athi = hi - len * (RC(1.0) - y) * (RC(1.0) - y);
        phi = select(phi, athi, sq == 2);
        phi = select(phi, atlo, sq == 1);
        phi = select(phi, both, sq == 3);
        jac = select(jac, (lane_t)(RC(1.0) - y), sq == 2);
        jac = select(jac, (lane_t)(y), sq == 1);
        jac = select(jac, (lane_t)(RC(3.0) * y * (RC(1.0) - y)), sq == 3);
      }
      hemi_node_c(ndf, gaf, p, mu, s, c, sn, cos_arc(phi), &fa[j], &fb[j]);
      if (sub) {
        lane_t fa2 = fa[j], fb2 = fb[j];
        fa2 *= RC(2.0) * jac;
        fb2 *= RC(2.0) * jac;
        fa[j] = select(fa[j], fa2, sq != 0);
        fb[j] = select(fb[j], fb2, sq != 0);
      }
    }
    lane_t v[16];
    for (int j = 0; j < 16; ++j) v[j] = GK15_WKL[j] * fa[j];
    lane_t sa = hemi_tree16(v);
    for (int j = 0; j < 16; ++j) v[j] = GK15_WKL[j] * fb[j];
    lane_t sb = hemi_tree16(v);
    for (int j = 0; j < 16; ++j) v[j] = GK15_WDL[j] * fa[j];
    lane_t da = hemi_tree16(v);
    for (int j = 0; j < 16; ++j) v[j] = GK15_WDL[j] * fb[j];
    lane_t db = hemi_tree16(v);
    for (int j = 0; j < 16; ++j) v[j] = GK15_WKL[j] * fabs(fa[j] - RC(0.5) * sa);
    lane_t ra = hemi_tree16(v);
    for (int j = 0; j < 16; ++j) v[j] = GK15_WKL[j] * fabs(fb[j] - RC(0.5) * sb);
    lane_t rb = hemi_tree16(v);
    lane_t ea_ = gk_error16(fabs(da), ra), eb_ = gk_error16(fabs(db), rb);
    int16 on = (int16)(m) < count;
    lane_t nka = ka, nkb = kb, nga = ga, ngb = gb;
    nka += sa * hw;
    nkb += sb * hw;
    nga += ea_ * hw;
    ngb += eb_ * hw;
    ka = select(ka, nka, on);
    kb = select(kb, nkb, on);
    ga = select(ga, nga, on);
    gb = select(gb, ngb, on);
  }
  lane_store(ka, ia, 0);
  lane_store(kb, ib, 0);
  lane_store(ga, ea, 0);
  lane_store(gb, eb, 0);
}
#endif
#endif /* BRDF_AZIMUTH_LANES_H */
