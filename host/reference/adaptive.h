// The reference's adaptive rule, shared by the specular and the diffuse references: Gauss-Kronrod
// 31/15 from Boost.Math's node tables, bisected until |K31 - G15| on a piece is below an absolute
// tolerance (halved with each split) or below `rel` times the piece's L1 norm, or the depth runs
// out. (Boost's own integrate() floors its error estimate near 1e-11, which would stall an absolute
// tolerance, and nested it would take minutes.) For a vector value type V, norm(V) (found by
// argument-dependent lookup) is the max norm: every component must pass.
#pragma once
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <algorithm>
#include <cmath>
#include <vector>

namespace brdfbake::reference::detail {

inline double norm(double v) { return std::fabs(v); }

template <class F>
auto adapt(F& f, double a, double b, double tol, unsigned depth, double rel) -> decltype(f(a)) {
  // K31 value, |K31 - G15| error, L1 norm
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
  if (err <= tol || err <= rel * l1 || depth == 0) return v;
  double m = 0.5 * (a + b);
  return adapt(f, a, m, 0.5 * tol, depth - 1, rel) + adapt(f, m, b, 0.5 * tol, depth - 1, rel);
}

// Over [a, b], split first at the given interior points (outside ones are ignored), each piece by adapt.
template <class F>
auto adaptPieces(F f, double a, double b, std::vector<double> breaks, double tol, unsigned depth, double rel)
    -> decltype(f(a)) {
  breaks.push_back(a);
  breaks.push_back(b);
  std::sort(breaks.begin(), breaks.end());
  decltype(f(a)) sum{};
  for (size_t i = 0; i + 1 < breaks.size(); ++i) {
    double lo = std::max(a, breaks[i]), hi = std::min(b, breaks[i + 1]);
    if (hi > lo) sum = sum + adapt(f, lo, hi, tol, depth, rel);
  }
  return sum;
}

// Breakpoints at multiples of the lobe width, where an adaptive rule could otherwise step over it.
inline std::vector<double> lobeBreaks(double alpha, double hi) {
  std::vector<double> b;
  for (double m : {0.01, 0.03, 0.1, 0.3, 1.0, 3.0, 10.0, 30.0, 100.0, 300.0, 1000.0})
    if (alpha * m < hi) b.push_back(alpha * m);
  return b;
}

// Two quantities integrated together on the same nodes (E and a moment B): the vector value type.
struct Pair {
  double e = 0, b = 0;
};
inline Pair operator+(Pair x, Pair y) { return {x.e + y.e, x.b + y.b}; }
inline Pair operator-(Pair x, Pair y) { return {x.e - y.e, x.b - y.b}; }
inline Pair operator*(double s, Pair x) { return {s * x.e, s * x.b}; }
inline Pair operator*(Pair x, double s) { return s * x; }
inline double norm(Pair x) { return std::max(std::fabs(x.e), std::fabs(x.b)); }

}  // namespace brdfbake::reference::detail
