// What the LTC family's test files share: a sphere quadrature in double and the default pair's
// 64 x 64 fit, made once per test binary.
#pragma once
#include <algorithm>
#include <boost/math/quadrature/gauss.hpp>
#include <cmath>

#include "tables/ltc/ltc_fit.h"

namespace brdfbake::testing_ltc {

// int over the sphere of g(x, y, z): Gauss-Legendre in z = cos(theta) on [-1, 1] (panels) times
// the trapezoid in phi (periodic: exact for trigonometric polynomials, fast for smooth ones).
template <class G>
double sphereIntegral(G g, int zPanels, int phis) {
  boost::math::quadrature::gauss<double, 20> gl;
  double sum = 0;
  for (int p = 0; p < zPanels; ++p) {
    const double a = -1 + 2.0 * p / zPanels, b = -1 + 2.0 * (p + 1) / zPanels;
    sum += gl.integrate(
        [&](double z) {
          const double s = std::sqrt(std::max(0.0, 1 - z * z));
          double row = 0;
          for (int k = 0; k < phis; ++k) {
            const double ph = 2 * M_PI * (k + 0.5) / phis;
            row += g(s * std::cos(ph), s * std::sin(ph), z);
          }
          return row * 2 * M_PI / phis;
        },
        a, b);
  }
  return sum;
}

}  // namespace brdfbake::testing_ltc

namespace brdfbake {
// The default pair's 64 x 64 fit (ltc_test.cpp), once for the tests that read it.
const LtcFit& defaultLtcFit();
}  // namespace brdfbake
