// E_avg of a tabulated isotropic BRDF, integrated over the table's own coordinates.
//
// Rusinkiewicz's change of variables: d is i in h's frame (for fixed h a rotation, dw_i = dw_d),
// and for fixed i, o = 2 (h.i) h - i gives dw_o = 4 (h.i) dw_h; so dw_i dw_o = 4 cos(theta_d)
// dw_h dw_d (Rusinkiewicz 1998). With n in h's frame at (-sin theta_h, 0, cos theta_h):
//   cos theta_i = cos theta_h cos theta_d - sin theta_h sin theta_d cos phi_d,
//   cos theta_o = cos theta_h cos theta_d + sin theta_h sin theta_d cos phi_d,
// neither depends on phi_h (isotropy: phi_h integrates to 2 pi), and their product
//   W = cos^2 theta_h cos^2 theta_d - sin^2 theta_h sin^2 theta_d cos^2 phi_d
// is even in cos phi_d, so [0, pi) twice covers phi_d (the table's period). Then
//   E_avg = 2 int E(mu) mu dmu = (1/pi) int int f cos theta_i cos theta_o dw_i dw_o
//         = 16 int_0^{pi/2} int_0^{pi/2} int_0^{pi} f W sin theta_h sin theta_d cos theta_d
//           dphi_d dtheta_d dtheta_h   over W > 0 (|cos phi_d| < cot theta_h cot theta_d).
// Here the table's kinks are coordinate planes (theta_h by u = sqrt(theta_h/(pi/2)) 90, theta_d,
// phi_d), and the only other surface is the horizon W = 0. So, Gauss-Legendre with n nodes:
//   theta_h: per u bin;
//   theta_d: per piece between the theta_d bin edges, theta_d = pi/2 - theta_h (where the horizon
//            starts to cut phi_d's range: a square root) and the theta_d where the horizon's
//            phi_d crosses a phi_d bin edge (cot theta_d = tan theta_h cos(j pi/180));
//   phi_d:   per piece between the phi_d bin edges and the horizon's bounds (W vanishes there).
// h-space albedos and their mu average (merl_albedo.cpp) meet thousands of crossings of the edges'
// curves per mu, and E(mu) kinks wherever one meets a bin edge; here only the horizon is oblique.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "materials/merl_albedo.h"
#include "materials/merl_quadrature.h"

namespace brdfbake {

namespace {

constexpr double kPi = 3.14159265358979323846;

// One rule: n nodes per theta_h bin, theta_d piece and phi_d piece; per channel, and the weight
// where f had no value (*lost, of a total pi).
std::array<double, 3> directRule(const RusinkiewiczFn& f, int n, int threads, const ProgressFn& progress,
                                 double* lost) {
  const merl_detail::Gauss& g = merl_detail::gaussCached(n);
  const int jobs = kMerlThetaH * n;
  std::vector<std::array<double, 4>> part(jobs);  // R, G, B, lost
  merl_detail::parallelFor(jobs, threads, progress, [&](int job) {
    const int bin = job / n, q = job % n;
    const double u = bin + g.x[q], t = u / kMerlThetaH, th = t * t * kPi / 2;
    const double wh = kPi * t / kMerlThetaH * g.w[q];  // d theta_h / du times the node's weight
    const double sh = std::sin(th), ch = std::cos(th), tanH = sh / ch;
    std::vector<double> bd, bp;
    for (int k = 0; k <= kMerlThetaD; ++k) bd.push_back(k * kPi / 2 / kMerlThetaD);
    auto cutD = [&](double td) {
      if (td > 0 && td < kPi / 2) bd.push_back(td);
    };
    cutD(kPi / 2 - th);
    for (int j = 0; 2 * j < kMerlPhiD; ++j) cutD(std::atan2(1.0, tanH * std::cos(j * kPi / kMerlPhiD)));
    std::sort(bd.begin(), bd.end());
    std::array<double, 4> acc{0, 0, 0, 0};
    for (size_t a = 0; a + 1 < bd.size(); ++a) {
      const double d0 = bd[a], dl = bd[a + 1] - bd[a];
      if (dl <= 1e-15) continue;
      for (int r = 0; r < n; ++r) {
        const double td = d0 + dl * g.x[r], sd = std::sin(td), cd = std::cos(td);
        // both above the horizon where |cos phi_d| < c
        const double c = ch * cd / std::max(sh * sd, 1e-300);
        double lo = 0, hi = kPi;
        if (c < 1) lo = std::acos(c), hi = kPi - lo;
        bp.assign(1, lo);  // in order: the bin edges inside (lo, hi) lie between its ends
        for (int j = 1; j < kMerlPhiD; ++j) {
          const double p = j * kPi / kMerlPhiD;
          if (p > lo && p < hi) bp.push_back(p);
        }
        bp.push_back(hi);
        const double wd = dl * g.w[r] * 16 * wh * sh * sd * cd;
        for (size_t b = 0; b + 1 < bp.size(); ++b) {
          const double p0 = bp[b], pl = bp[b + 1] - bp[b];
          if (pl <= 1e-15) continue;
          for (int s = 0; s < n; ++s) {
            const double pd = p0 + pl * g.x[s], cp = std::cos(pd);
            const double wW = ch * ch * cd * cd - sh * sh * sd * sd * cp * cp;
            if (wW <= 0) continue;
            double v[3];
            const double w = wd * pl * g.w[s] * wW;
            if (!f(th, td, pd, v)) acc[3] += w;
            for (int ch3 = 0; ch3 < 3; ++ch3) acc[ch3] += w * v[ch3];
          }
        }
      }
    }
    part[job] = acc;
  });
  std::array<double, 3> e{0, 0, 0};
  double l = 0;
  for (const auto& p : part) {
    for (int c = 0; c < 3; ++c) e[c] += p[c];
    l += p[3];
  }
  if (lost) *lost = l / kPi;
  return e;
}

}  // namespace

std::array<double, 3> directAlbedoAvgRule(const RusinkiewiczFn& f, int n, int threads) {
  return directRule(f, n, threads, {}, nullptr);
}

// The rules converge fast here (on four test materials the n = 4 rule is within 1.6e-9 of n = 8;
// docs/merl.md, "E_avg over the table's coordinates"), but not geometrically everywhere (the horizon still crosses
// edges), so the estimate is the ladder's, as for the texels: max(|Q_n - Q_n-1|, |Q_n - Q_n-2|) from n = 4, climbing
// while any channel's is above merlAvgTarget.
AlbedoEstimate directAlbedoAvg(const RusinkiewiczFn& f, int threads, const ProgressFn& progress) {
  return merl_detail::climbLadder(kMerlAvgLadder, merlAvgTarget,
                                  [&](int n, double* lost) { return directRule(f, n, threads, progress, lost); });
}

}  // namespace brdfbake
