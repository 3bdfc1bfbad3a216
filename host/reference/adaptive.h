// The reference's adaptive rule, shared by the specular and the diffuse references: Gauss-Kronrod
// 31/15 from Boost.Math's node tables, bisected until |K31 - G15| on a piece is below an absolute
// tolerance (halved with each split) or below `rel` times the piece's L1 norm, or the depth runs
// out. (Boost's own integrate() floors its error estimate near 1e-11, which would stall an absolute
// tolerance, and nested it would take minutes.) For a vector value type V, norm(V) (found by
// argument-dependent lookup) is the max norm: every component must pass.
#pragma once
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>

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

}  // namespace brdfbake::reference::detail
