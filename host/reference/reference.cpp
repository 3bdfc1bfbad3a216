#include "reference/reference.h"

#include <algorithm>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <vector>

#include "common/brdf_host.h"

namespace brdfbake::reference {
namespace {

using boost::math::quadrature::gauss_kronrod;
constexpr double kPi = 3.14159265358979323846;
constexpr double kTol = 1e-11;  // absolute, per integral
constexpr unsigned kDepth = 18;

// Adaptive GK31 with an absolute tolerance: bisect until |K31 - G15| <= tol on each piece (a
// relative tolerance would chase rounding noise in pieces whose integral is tiny).
template <class F>
double adapt(F& f, double a, double b, double tol, unsigned depth) {
  double err = 0;
  double v = gauss_kronrod<double, 31>::integrate(f, a, b, 0, 0.0, &err);
  if (err <= tol || depth == 0) return v;
  double m = 0.5 * (a + b);
  return adapt(f, a, m, 0.5 * tol, depth - 1) + adapt(f, m, b, 0.5 * tol, depth - 1);
}

// Over [a, b], split first at the given interior points.
template <class F>
double integrate(F f, double a, double b, std::vector<double> breaks, unsigned depth = kDepth,
                 double tol = kTol) {
  breaks.push_back(a);
  breaks.push_back(b);
  std::sort(breaks.begin(), breaks.end());
  double sum = 0;
  for (size_t i = 0; i + 1 < breaks.size(); ++i) {
    double lo = std::max(a, breaks[i]), hi = std::min(b, breaks[i + 1]);
    if (hi <= lo) continue;
    sum += adapt(f, lo, hi, tol, depth);
  }
  return sum;
}

// Breakpoints at multiples of the lobe width, where an adaptive rule could otherwise step over it.
std::vector<double> lobeBreaks(double alpha, double hi) {
  std::vector<double> b;
  for (double m : {0.01, 0.03, 0.1, 0.3, 1.0, 3.0, 10.0, 30.0, 100.0, 300.0, 1000.0})
    if (alpha * m < hi) b.push_back(alpha * m);
  return b;
}

brdf64::BrdfParams params(int ndf, int gaf, double r) {
  brdf64::BrdfParams p{};
  p.r = r;
  p.alpha = r * r;
  p.k = brdf64::gaf_schlick_k(gaf, r, p.alpha);
  p.inv_kp = (ndf == NDF_GAUSSIAN && p.alpha > 0) ? 1.0 / kp(ndf, r) : 0.0;
  return p;
}

}  // namespace

double kp(int ndf, double r) {
  brdf64::BrdfParams p{};
  p.r = r;
  p.alpha = r * r;
  // k_p = 2 pi int_0^{pi/2} p(theta) cos sin dtheta
  auto f = [&](double th) {
    double s = std::sin(th), c = std::cos(th);
    return 2 * kPi * brdf64::ndf_p(ndf, p, c, s * s) * c * s;
  };
  return integrate(f, 0, kPi / 2, lobeBreaks(p.alpha, kPi / 2));
}

Moments albedo(int ndf, int gaf, double r, double mu) {
  brdf64::BrdfParams p = params(ndf, gaf, r);
  double s = std::sqrt((1 - mu) * (1 + mu));
  Moments m;
  if (p.alpha == 0) {
    brdf64::HemiResult h = brdf64::hemisphere_moments(ndf, gaf, p, mu);  // the delta limit
    m.a = h.a;
    m.b = h.b;
    return m;
  }
  // E = int sin(th) dth 2 int_0^phimax dphi D (G/no) F (o.h), the h-space form of the albedo.
  double th1 = std::atan(mu / (1 + s)), th2 = std::atan2(1 + s, mu);
  for (int which = 0; which < 2; ++which) {
    auto outer = [&](double th) {
      double sn = std::sin(th), c = std::cos(th);
      double D = brdf64::ndf_D(ndf, p, c, sn * sn);
      double phimax = kPi;
      if (th > th1) {
        double c0 = -mu * std::cos(2 * th) / (s * std::sin(2 * th));
        phimax = std::acos(std::clamp(c0, -1.0, 1.0));
      }
      auto inner = [&](double phi) {
        double oh = s * sn * std::cos(phi) + mu * c;
        double ni = 2 * oh * c - mu;
        double G = brdf64::gaf_G_over_no(gaf, ndf, p, ni, mu, c, oh, (1 - ni) * (1 + ni), s * s);
        double f5 = std::pow(1 - oh, 5);
        return G * oh * (which == 0 ? 1 : f5);
      };
      if (phimax <= 0) return 0.0;
      // depth 12: the integrand is smooth in phi; deeper only chases rounding where it is tiny
      return 2 * sn * D * integrate(inner, 0, phimax, {}, 12, 1e-12);
    };
    // [0, th1]: the whole half circle is visible; [th1, th2]: phimax falls from pi to 0 with
    // square-root ends, which the smoothstep th = th1 + (th2-th1) y^2 (3 - 2y) makes smooth.
    double full = integrate(outer, 0, th1, lobeBreaks(p.alpha, th1));
    double L = th2 - th1;
    auto partial = [&](double y) { return outer(th1 + L * y * y * (3 - 2 * y)) * 6 * L * y * (1 - y); };
    std::vector<double> ybr;
    for (double t : lobeBreaks(p.alpha, th2)) {
      if (t <= th1) continue;
      // invert the smoothstep by bisection to place the lobe breakpoints in y
      double lo = 0, hi = 1;
      for (int it = 0; it < 60; ++it) {
        double mid = 0.5 * (lo + hi);
        (th1 + L * mid * mid * (3 - 2 * mid) < t ? lo : hi) = mid;
      }
      ybr.push_back(lo);
    }
    double v = full + (L > 0 ? integrate(partial, 0, 1, ybr) : 0.0);
    (which == 0 ? m.a : m.b) = v;
  }
  m.a -= m.b;  // the first pass integrated E = A + B
  return m;
}

double albedoAvg(int ndf, int gaf, double r) {
  auto f = [&](double mu) { return 2 * mu * albedo(ndf, gaf, r, mu).e(); };
  return integrate(f, 0, 1, lobeBreaks(r * r, 1));
}

double weakFurnace(int ndf, double r, double mu) {
  brdf64::BrdfParams p = params(ndf, NDF_GGX, r);
  double s = std::sqrt((1 - mu) * (1 + mu));
  double g1 = brdf64::ndf_G1(ndf, p, mu, s * s);
  // int over h with o.h > 0: cos(phi) > -mu c/(s sn)
  auto outer = [&](double th) {
    double sn = std::sin(th), c = std::cos(th);
    double c0 = s > 0 && sn > 0 ? -mu * c / (s * sn) : -2.0;
    double phimax = std::acos(std::clamp(c0, -1.0, 1.0));
    auto inner = [&](double phi) { return std::max(0.0, s * sn * std::cos(phi) + mu * c); };
    return 2 * sn * brdf64::ndf_D(ndf, p, c, sn * sn) * integrate(inner, 0, phimax, {});
  };
  std::vector<double> br = lobeBreaks(p.alpha, kPi / 2);
  br.push_back(std::atan2(mu, s));  // theta_h = pi/2 - theta_o: o.h > 0 on the whole circle below it
  return g1 * integrate(outer, 0, kPi / 2, br);
}

}  // namespace brdfbake::reference
