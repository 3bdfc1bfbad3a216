// Albedo of a tabulated BRDF by h-space quadrature with the table's bin edges as panel edges.
// See merl_albedo.h; the geometry (o at azimuth 0, h at (theta_h, phi_h)):
//   o.h = a cos phi_h + b,  a = sin theta_o sin theta_h,  b = cos theta_o cos theta_h = cos theta_d
//   n.i = 2 (o.h) cos theta_h - cos theta_o
//   o in h's frame (Rusinkiewicz's d, up to phi_d + pi, which the table folds away):
//     d = (sin theta_o cos phi_h cos theta_h - cos theta_o sin theta_h, -sin theta_o sin phi_h, o.h)
#include "materials/merl_albedo.h"
#include "materials/merl_quadrature.h"

#include <Imath/half.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <thread>
#include <vector>

#include "common/errors.h"
#include "common/format.h"
#include "version.h"

namespace brdfbake {

using merl_detail::Gauss;
using merl_detail::gaussCached;
using merl_detail::parallelFor;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2 * kPi;

// Gauss-Legendre nodes and weights on [0, 1] (Newton on P_n from Chebyshev starting points).
Gauss gaussLegendre(int n) {
  Gauss g;
  for (int i = 0; i < n; ++i) {
    double z = std::cos(kPi * (i + 0.75) / (n + 0.5)), dp = 1;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = z;
      for (int k = 2; k <= n; ++k) {
        double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (z * p1 - p0) / (z * z - 1);
      double dz = p1 / dp;
      z -= dz;
      if (std::fabs(dz) < 1e-16) break;
    }
    g.x.push_back(0.5 * (1 - z));
    g.w.push_back(1.0 / ((1 - z * z) * dp * dp));  // 2/((1-z^2) P'^2), halved for [0, 1]
  }
  return g;
}

// Bin edges as the quadrature needs them, computed once.
struct Edges {
  double cosThetaD[kMerlThetaD];                  // cos of theta_d edges k = 1..89 (index k)
  double sinPhiD[kMerlPhiD], cosPhiD[kMerlPhiD];  // of phi_d edges k pi/180
  Edges() {
    for (int k = 0; k < kMerlThetaD; ++k) cosThetaD[k] = std::cos(k * kPi / 2 / kMerlThetaD);
    for (int k = 0; k < kMerlPhiD; ++k)
      sinPhiD[k] = std::sin(k * kPi / kMerlPhiD), cosPhiD[k] = std::cos(k * kPi / kMerlPhiD);
  }
};
const Edges& edges() {
  static const Edges e;
  return e;
}

double wrap(double t) {
  t = std::fmod(t, kTwoPi);
  return t < 0 ? t + kTwoPi : t;
}

}  // namespace

namespace merl_detail {
const Gauss& gaussCached(int n) {
  static std::mutex m;
  static std::vector<Gauss> cache(32);  // the ladders' rules and the checks' above them, n <= 31
  std::lock_guard<std::mutex> lock(m);
  if (cache[n].x.empty()) cache[n] = gaussLegendre(n);
  return cache[n];
}
}  // namespace merl_detail

RusinkiewiczFn merlFunction(const MerlData& d, bool nearestBin) {
  if (nearestBin)
    return [&d](double th, double td, double pd, double f[3]) {
      bool ok = true;
      for (int c = 0; c < 3; ++c) {
        f[c] = d.nearest(c, th, td, pd);
        if (f[c] < 0) f[c] = 0, ok = false;
      }
      return ok;
    };
  return [&d](double th, double td, double pd, double f[3]) { return d.lookup(th, td, pd, f); };
}

RusinkiewiczFn analyticFunction(const Brdf3dSpec& s) {
  return [s](double th, double td, double pd, double f[3]) {
    Directions dirs = fromRusinkiewicz(th, td, pd);
    for (int c = 0; c < 3; ++c) f[c] = hostBrdf(s, dirs, s.channels() == 3 ? c : 0);
    return true;
  };
}

std::array<double, 3> hSpaceIntegral(const RusinkiewiczFn& f, double mu, HSpaceRule rule, double* unsupported) {
  const Gauss& gu = gaussCached(rule.thetaNodes);
  const Gauss& gp = gaussCached(rule.phiNodes);
  const Edges& ed = edges();
  mu = std::clamp(mu, 0.0, 1.0);
  const double co = mu, so = std::sqrt((1 - mu) * (1 + mu));
  std::array<double, 3> e{0, 0, 0};
  double lost = 0;
  std::vector<double> br;
  br.reserve(2 * (kMerlThetaD + kMerlPhiD) + 8);
  // theta_h panels: the bins, cut where the inner integral's derivative is singular: where the
  // horizon's curve turns in theta_h (its ends at phi_h = 0 and pi: theta_h = pi/4 +- theta_o/2),
  // and where a theta_d edge's circle touches the arc o.h in [cos(theta_o + theta_h),
  // cos(theta_o - theta_h)] (theta_h = |theta_o - theta_d|, theta_o + theta_d): there its two phi_h
  // cuts appear, a square root. Without those cuts the rules do not settle at grazing views of a
  // MERL file (r 0.3, mu 1/32: (4,3) to (15,14) spread over 4.6e-7, (6,5) off by 4.4e-7 under an
  // estimate of 1.4e-7); with them and the phi_d cuts below they converge monotonically, (6,5) within
  // 8.1e-9 (MerlAlbedo.EstimateHoldsOnAFilesInterpolantAtGrazingViews).
  std::vector<double> ub;
  for (int k = 0; k <= kMerlThetaH; ++k) ub.push_back(k);
  const double thetaO = std::acos(mu);
  auto cut = [&](double t) {
    if (t > 0 && t < kPi / 2) ub.push_back(std::sqrt(t / (kPi / 2)) * kMerlThetaH);
  };
  cut(kPi / 4 + thetaO / 2);
  cut(kPi / 4 - thetaO / 2);
  for (int k = 1; k < kMerlThetaD; ++k) {
    const double td = k * kPi / 2 / kMerlThetaD;
    cut(std::fabs(thetaO - td));
    cut(thetaO + td);
  }
  // and where a phi_d edge's curve touches the circle: A sin phi_h + B cos phi_h = C below has
  // C^2 = A^2 + B^2 there, which is sin theta_h = sin theta_o / |sin phi_d|
  for (int j = 1; j < kMerlPhiD; ++j) {
    const double sp = std::fabs(ed.sinPhiD[j]);
    if (so < sp) cut(std::asin(so / sp));
  }
  std::sort(ub.begin(), ub.end());
  for (size_t k = 0; k + 1 < ub.size(); ++k) {
    const double u0 = ub[k], ulen = ub[k + 1] - ub[k];
    if (ulen <= 1e-12) continue;
    for (size_t q = 0; q < gu.x.size(); ++q) {
      const double u = u0 + ulen * gu.x[q], t = u / kMerlThetaH, th = t * t * kPi / 2;
      const double dth = kPi * t / kMerlThetaH * gu.w[q] * ulen;  // d theta_h / du times the node's weight
      const double sh = std::sin(th), ch = std::cos(th);
      const double a = so * sh, b = co * ch;
      if (2 * (a + b) * ch - co <= 0) continue;  // i below the horizon all round
      br.assign({0.0, kTwoPi});
      auto addCos = [&](double x) {  // cos phi_h = x
        if (a > 1e-300 && std::fabs(x) < 1) {
          double p = std::acos(x);
          br.push_back(p);
          br.push_back(kTwoPi - p);
        }
      };
      if (a > 1e-300) {
        addCos((co / (2 * ch) - b) / a);  // the horizon of i
        for (int j = 1; j < kMerlThetaD; ++j) addCos((ed.cosThetaD[j] - b) / a);
      }
      for (int j = 0; j < kMerlPhiD; ++j) {  // d.y cos c = d.x sin c: A sin phi + B cos phi = C
        double A = so * ed.cosPhiD[j], B = so * ed.sinPhiD[j] * ch, C = ed.sinPhiD[j] * co * sh;
        double R = std::hypot(A, B);
        if (R > 1e-300 && std::fabs(C) <= R) {
          double delta = std::atan2(A, B), p = std::acos(std::clamp(C / R, -1.0, 1.0));
          br.push_back(wrap(delta + p));
          br.push_back(wrap(delta - p));
        }
      }
      std::sort(br.begin(), br.end());
      for (size_t s = 0; s + 1 < br.size(); ++s) {
        const double p0 = br[s], len = br[s + 1] - br[s];
        if (len <= 1e-15) continue;
        for (size_t r = 0; r < gp.x.size(); ++r) {
          const double phi = p0 + len * gp.x[r], cp = std::cos(phi), sp = std::sin(phi);
          const double oh = a * cp + b, ni = 2 * oh * ch - co;
          if (oh <= 0 || ni <= 0) continue;
          const double dx = so * cp * ch - co * sh, dy = -so * sp;
          const double thetaD = std::acos(std::min(oh, 1.0)), phiD = std::atan2(dy, dx) + kPi;  // of i
          double v[3];
          const double w = dth * len * gp.w[r] * sh * 4 * oh * ni;
          if (!f(th, thetaD, phiD, v)) lost += w;
          for (int c = 0; c < 3; ++c) e[c] += w * v[c];
        }
      }
    }
  }
  if (unsupported) *unsupported = lost / kPi;
  return e;
}

// The rules' errors fall algebraically here, not geometrically: where two bin edges' curves cross
// inside a theta_h panel, and where the horizon cuts cells whose corners are partly unmeasured, the
// inner integral is only a few times differentiable, so (n, n-1) errs about as n^-4 to n^-6 and
// not always with one sign. So one difference, |R_6 - R_4|, is the coarse rule's error, 5 to 9
// times the fine one's, and at times (3 of 48 texel centres) below it. The ladder
// below takes three rules: R_k's estimate is max(|R_k - R_k-1|, |R_k - R_k-2|), which covers
// every value measured against the (30, 29) rule (4 materials x 16 texel centres and 3 x 11 nodes:
// 1.0 to 8.6 times the error, the 1.0 where the reference itself wobbles by 1e-10; docs/merl.md,
// "Tight claims"), and climbs while any channel's estimate is above merlTexelTarget.
AlbedoEstimate hSpaceAlbedo(const RusinkiewiczFn& f, double mu) {
  return merl_detail::climbLadder(kMerlLadder, merlTexelTarget, [&](int n, double* unsupported) {
    return hSpaceIntegral(f, mu, HSpaceRule{n, n - 1}, unsupported);
  });
}

TableImage merlTable(const MerlData& d, const std::string& name, const MerlTableSpec& spec, int width, bool nodeGrid,
                     bool half, const ProgressFn& progress) {
  RusinkiewiczFn f = merlFunction(d);
  TableImage img;
  img.channels = {"R", "G", "B"};
  std::vector<AlbedoEstimate> est;
  if (spec.average) {
    img.width = img.height = 1;
    est = {directAlbedoAvg(f, 0, progress)};
  } else {
    img.width = width;
    img.height = 1;
    est.resize(width);
    parallelFor(width, 0, progress, [&](int i) {
      double mu = nodeGrid ? (width > 1 ? i / (width - 1.0) : 0.0) : (i + 0.5) / width;
      est[i] = hSpaceAlbedo(f, mu);
    });
  }
  img.planes.assign(3, std::vector<float>(est.size()));
  // Each value's claim is its estimate plus its own storage rounding, known exactly (float, or
  // half with --half), relative above |E| = 1 as brdf.error is; the table claims the largest, plus
  // kMerlArithmetic for the double sums (about 1e5 terms of at most E each: 1e5 x 2^-53 < 1e-11).
  double claim = 0, lost = 0;
  for (size_t i = 0; i < est.size(); ++i) {
    lost = std::max(lost, est[i].unsupported);
    for (int c = 0; c < 3; ++c) {
      float v = static_cast<float>(est[i].e[c]);
      img.planes[c][i] = v;
      if (!std::isfinite(v))
        throw Error(kExitDataErr, "MERL file " + d.path + ": the " + spec.table + " texel " + std::to_string(i) +
                                      " is not finite (the data's values are too large); nothing was written");
      double stored = half ? static_cast<double>(static_cast<float>(Imath::half(v))) : static_cast<double>(v);
      claim =
          std::max(claim, (est[i].err[c] + std::fabs(stored - est[i].e[c])) / std::max(1.0, std::fabs(est[i].e[c])));
    }
  }
  claim += kMerlArithmetic;
  img.strings["brdf.schema"] = "brdfbake/1";
  img.strings["brdf.table"] = spec.table;
  img.strings["brdf.material"] = "merl:" + name;
  // the share of the lit bins the file measures, per channel (formats/merl.h kMerlMinMeasured)
  img.strings["brdf.merl.measured"] =
      "R " + fmtG(d.measuredShare[0], 4) + ", G " + fmtG(d.measuredShare[1], 4) + ", B " + fmtG(d.measuredShare[2], 4);
  img.strings["brdf.generator"] = std::string("brdfbake ") + BRDFBAKE_VERSION + " (git " + BRDFBAKE_GIT_REV + ")";
  auto listOf = [](const auto& ladder) {
    std::string text;
    for (int n : ladder) text += (text.empty() ? "" : ", ") + std::to_string(n);
    return text;
  };
  const std::string largest =
      std::to_string(std::max_element(est.begin(), est.end(), [](const AlbedoEstimate& a, const AlbedoEstimate& b) {
                       return a.nodes < b.nodes;
                     })->nodes);
  const std::string interpolant =
      "the MERL table's trilinear interpolant (sqrt theta_h bins, phi_d period pi, unmeasured and below-horizon bins "
      "left out of the weights)";
  const std::string claimText =
      std::string(" is within ") + (spec.average ? "max(1e-10, 2^-28 |E|)" : "max(1e-9, 2^-25 |E|)") +
      " in every channel (the largest n used: " + largest +
      "); error: that estimate + the value's storage rounding, the largest over the table, + 1e-11";
  if (spec.average) {
    img.strings["brdf.axes"] = "none";
    img.strings["brdf.channels"] = "R,G,B=E_avg (2 int E(mu) mu dmu of the measured material, per colour channel)";
    img.strings["brdf.method"] =
        "E_avg = 16 int f W sin(theta_h) sin(theta_d) cos(theta_d) over (theta_h, theta_d, phi_d) (Rusinkiewicz's "
        "change "
        "of variables, phi_h integrated out; W = cos(theta_i) cos(theta_o) > 0) of " +
        interpolant +
        ": Gauss-Legendre n per theta_h bin, per theta_d piece (bin edges, pi/2 - theta_h, and where the horizon's "
        "phi_d crosses a phi_d edge) and per phi_d piece (bin edges and the horizon); n climbs " +
        listOf(kMerlAvgLadder) + " until the estimate max(|Q_n - Q_prev|, |Q_n - Q_prev2|)" + claimText;
  } else {
    img.strings["brdf.axes"] = "mu";
    img.strings["brdf.grid"] = nodeGrid ? "node" : "texel-center";
    img.v2f["brdf.mu.range"] = {0.0f, 1.0f};
    img.strings["brdf.channels"] = spec.channels;
    img.strings["brdf.method"] =
        "h-space quadrature of " + interpolant +
        ": theta_h by Gauss-Legendre n per bin (bins cut where the horizon "
        "turns and where a theta_d or phi_d edge touches the arc), phi_h by Gauss-Legendre n - 1 per piece between the "
        "theta_d and phi_d bin edges and the horizon; n climbs " +
        listOf(kMerlLadder) + " until the estimate max(|R_n - R_prev|, |R_n - R_prev2|)" + claimText;
  }
  img.floats["brdf.merl.unsupported"] = static_cast<float>(lost);
  float stored = static_cast<float>(claim);
  if (static_cast<double>(stored) < claim) stored = std::nextafter(stored, 1.0f);  // never below the claim
  img.floats["brdf.error"] = stored;
  return img;
}

}  // namespace brdfbake
