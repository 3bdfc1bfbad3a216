#include "reference/reference.h"

#include <algorithm>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <vector>

#include "common/brdf_host.h"

namespace brdfbake::reference {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTol = 1e-11;  // absolute, per integral
constexpr unsigned kDepth = 18;

// The two split-sum moments (E, B) integrated together: the same nodes serve both.
struct Pair {
  double e = 0, b = 0;
};
Pair operator+(Pair x, Pair y) { return {x.e + y.e, x.b + y.b}; }
Pair operator-(Pair x, Pair y) { return {x.e - y.e, x.b - y.b}; }
Pair operator*(double s, Pair x) { return {s * x.e, s * x.b}; }
Pair operator*(Pair x, double s) { return s * x; }
double norm(double v) { return std::fabs(v); }
double norm(Pair x) { return std::max(std::fabs(x.e), std::fabs(x.b)); }

// Adaptive GK31: bisect until |K31 - G15| on a piece is below an absolute tolerance (halved with
// each split) or below `rel` times the piece's L1 norm, whichever comes first. For a Pair, both
// components must pass (max norm).
template <class F>
auto adapt(F& f, double a, double b, double tol, unsigned depth, double rel) -> decltype(f(a)) {
  // GK31 on [a, b] from Boost's node tables: K31 value, |K31 - G15| error, L1 norm. (Boost's own
  // integrate() floors its error estimate near 1e-11, which would stall an absolute tolerance.)
  using K = boost::math::quadrature::gauss_kronrod<double, 31>;
  using G = boost::math::quadrature::gauss<double, 15>;
  const auto& x = K::abscissa();
  const auto& wk = K::weights();
  const auto& wg = G::weights();
  double c = 0.5 * (a + b), h = 0.5 * (b - a);
  auto f0 = f(c);
  auto vk = wk[0] * f0, vg = wg[0] * f0;
  double l1 = wk[0] * norm(f0);
  for (size_t i = 1; i < x.size(); ++i) {
    auto fl = f(c - h * x[i]), fr = f(c + h * x[i]);
    vk = vk + wk[i] * (fl + fr);
    l1 += wk[i] * (norm(fl) + norm(fr));
    if (i % 2 == 0) vg = vg + wg[i / 2] * (fl + fr);
  }
  auto v = vk * h;
  double err = norm(vk - vg) * h;
  l1 *= h;
  // converged: absolutely, or relative to the piece's L1 norm (the pieces' L1 norms add up to
  // about the whole integral, so the sum is good to ~rel relative)
  if (err <= tol || err <= rel * l1 || depth == 0) return v;
  double m = 0.5 * (a + b);
  return adapt(f, a, m, 0.5 * tol, depth - 1, rel) + adapt(f, m, b, 0.5 * tol, depth - 1, rel);
}

// Over [a, b], split first at the given interior points.
template <class F>
auto integrate(F f, double a, double b, std::vector<double> breaks, unsigned depth = kDepth,
               double tol = kTol, double rel = 1e-10) -> decltype(f(a)) {
  breaks.push_back(a);
  breaks.push_back(b);
  std::sort(breaks.begin(), breaks.end());
  decltype(f(a)) sum{};
  for (size_t i = 0; i + 1 < breaks.size(); ++i) {
    double lo = std::max(a, breaks[i]), hi = std::min(b, breaks[i + 1]);
    if (hi <= lo) continue;
    sum = sum + adapt(f, lo, hi, tol, depth, rel);
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
    brdf64::HemiResult h = brdf64::hemisphere_moments(ndf, gaf, p, mu, 0);  // the delta limit
    m.a = h.a;
    m.b = h.b;
    return m;
  }
  // E = int sin(th) dth 2 int_0^phimax dphi D (G/no) F (o.h), the h-space form of the albedo.
  // E and B = the same with F = (1 - o.h)^5 are integrated together (Pair).
  double th1 = std::atan(mu / (1 + s)), th2 = std::atan2(1 + s, mu);
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
      return Pair{G * oh, G * oh * f5};
    };
    if (phimax <= 0) return Pair{};
    // Split at the kinks of min/max GAFs (their locations are checked on their own in
    // tests/models_test.cpp); elsewhere the integrand is smooth and the bisection converges.
    double kinks[3];
    int nk = brdf64::gaf_kinks(gaf, mu, s, c, sn, kinks);
    std::vector<double> br;
    for (int k = 0; k < nk; ++k)
      if (kinks[k] > -1 && kinks[k] < 1) br.push_back(std::acos(kinks[k]));
    // inner far tighter than outer: its rounding must not look like structure to the outer rule.
    // Its absolute tolerance applies to the weighted value w * inner (1e-14, or as before where
    // w > 1): where D is tiny, far from the lobe, resolving the n.i ~ alpha layer at the arc's end
    // to 1e-14 of the inner integral alone would take millions of nodes and buy nothing.
    double w = 2 * sn * D;
    if (!(w > 0)) return Pair{};
    return w * integrate(inner, 0, phimax, br, 30, std::max(1e-14, 1e-14 / w), 1e-13);
  };
  // [0, th1]: the whole half circle is visible; [th1, th2]: phimax falls from pi to 0 with
  // square-root ends. The partial range is cut geometrically (th1 2^k: the NDF's tail is a power
  // law there), at the lobe scale and at the GAF's kinks; th = a + L y^2 on the first panel and
  // th = b - L (1-y)^2 on the last one make the square-root ends smooth.
  std::vector<double> fullBreaks = lobeBreaks(p.alpha, th1);
  double gt2[4];
  int ng = brdf64::gaf_theta_breaks(gaf, mu, s, gt2);
  std::vector<double> kinkTheta;
  for (int k = 0; k < ng; ++k) kinkTheta.push_back(std::atan(std::sqrt(gt2[k])));
  fullBreaks.insert(fullBreaks.end(), kinkTheta.begin(), kinkTheta.end());
  Pair v = integrate(outer, 0, th1, fullBreaks);
  std::vector<double> pb = lobeBreaks(p.alpha, th2);
  pb.insert(pb.end(), kinkTheta.begin(), kinkTheta.end());
  // (at mu = 0, th1 = 0: start the doubling at the lobe scale instead)
  for (double t = th1 > 0 ? 2 * th1 : std::max(p.alpha, 1e-6); t < th2; t *= 2) pb.push_back(t);
  pb.push_back(th1);
  pb.push_back(th2);
  std::sort(pb.begin(), pb.end());
  pb.erase(std::remove_if(pb.begin(), pb.end(), [&](double t) { return t < th1 || t > th2; }), pb.end());
  for (size_t k = 0; k + 1 < pb.size(); ++k) {
    double a = pb[k], b = pb[k + 1], L = b - a;
    if (L <= 0) continue;
    bool first = k == 0, last = k + 2 == pb.size();
    auto panel = [&](double y) {
      if (first && last) return outer(a + L * y * y * (3 - 2 * y)) * 6 * L * y * (1 - y);
      if (first) return outer(a + L * y * y) * 2 * L * y;
      if (last) return outer(b - L * (1 - y) * (1 - y)) * 2 * L * (1 - y);
      return outer(a + L * y) * L;
    };
    v = v + integrate(panel, 0, 1, {});
  }
  m.a = v.e - v.b;
  m.b = v.b;
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
