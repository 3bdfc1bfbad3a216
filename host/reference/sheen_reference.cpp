#include "reference/sheen_reference.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "common/brdf_host.h"  // the GAF_* ids only
#include "reference/adaptive.h"

namespace brdfbake::reference {
namespace {

constexpr double kPi = 3.14159265358979323846;

using detail::adapt;
using detail::norm;
using detail::Pair;

template <class F>
auto integrate(F f, double a, double b, std::vector<double> br, double tol, double rel) -> decltype(f(a)) {
  return detail::adaptPieces(f, a, b, std::move(br), tol, 24, rel);
}

// Breaks geometric towards 0 and at the lobe's scale sqrt(alpha) and the view's mu.
std::vector<double> scaleBreaks(double alpha, double mu, double hi) {
  std::vector<double> b;
  for (double x = hi / 4; x > 1e-12; x /= 4) b.push_back(x);
  for (double m : {0.25, 0.5, 1.0, 2.0, 4.0, 8.0}) {
    if (m * std::sqrt(alpha) < hi) b.push_back(m * std::sqrt(alpha));
    if (m * mu < hi && mu > 0) b.push_back(m * mu);
  }
  return b;
}

// The visibility G/(4 (n.i)(n.o)) times (n.i): V(ni, no) ni.
double visTimesNi(int gaf, double r, double ni, double no) {
  switch (gaf) {
    case GAF_NEUBELT:
      return ni / (4 * (ni + no - ni * no));  // Neubelt and Pettineo 2013
    case GAF_IMPLICIT:
      return ni / 4;  // G = (n.i)(n.o)
    case GAF_NONE:
      return 1 / (4 * no);  // G = 1
    default:                // Estevez and Kulla 2017: G = 1/(1 + Lambda(i) + Lambda(o))
      return 1 / ((1 + charlieLambda(r, ni) + charlieLambda(r, no)) * 4 * no);
  }
}

// E and B (Schlick's weight (1 - o.h)^5) at (mu, r), mu > 0 or tiny, r > 0, over the incident
// direction: E = int_0^1 dx int_0^pi 2 dphi f(i, o) x, f = D G/(4 x mu), x = n.i.
Pair albedoInside(int gaf, double r, double mu) {
  double alpha = r * r, s = std::sqrt((1 - mu) * (1 + mu));
  auto outer = [&](double x) {
    double sx = std::sqrt((1 - x) * (1 + x));
    double vis = visTimesNi(gaf, r, x, mu);
    auto inner = [&](double phi) {
      // h ~ i + o, o = (s, 0, mu), i = (sx cos phi, sx sin phi, x); sin^2 theta_h without cancellation
      double hx = sx * std::cos(phi) + s, hy = sx * std::sin(phi), hz = x + mu;
      double hxy2 = hx * hx + hy * hy, h2 = hxy2 + hz * hz;
      double oh = (s * hx + mu * hz) / std::sqrt(h2);
      double f = charlieD(r, hxy2 / h2) * vis;
      double w = std::pow(std::max(0.0, 1 - oh), 5);
      return Pair{f, f * w};
    };
    // the mirror direction (phi = pi, x = mu) is h = n, where D has a cone point: the phi rule grades to pi
    std::vector<double> br;
    for (double d : {1e-1, 3e-2, 1e-2, 3e-3, 1e-3, 1e-4}) br.push_back(kPi - d * std::max(1.0, std::fabs(x - mu) * 10));
    for (double m : {0.25, 0.5, 1.0, 2.0}) br.push_back(m * std::sqrt(alpha));
    return 2 * integrate(inner, 0, kPi, br, 1e-15, 1e-12);
  };
  std::vector<double> br = scaleBreaks(alpha, mu, 1);
  br.push_back(mu);
  return integrate(outer, 0, 1, br, 1e-13, 1e-11);
}

Pair albedoAt(int gaf, double r, double mu) {
  if (r <= 0 && mu <= 0) return albedoInside(gaf, 3e-5, 1e-9 * 9e-10);
  if (r <= 0) return {};
  return albedoInside(gaf, r, mu <= 0 ? 1e-9 : mu);
}

}  // namespace

double charlieD(double r, double s2) {
  double alpha = r * r;
  // Estevez and Kulla 2017: D = (2 + 1/alpha) sin^(1/alpha)(theta_h) / (2 pi)
  return (2 + 1 / alpha) * std::pow(s2, 0.5 / alpha) / (2 * kPi);
}

double charlieLambda(double r, double c) {
  double alpha = r * r;
  // Estevez and Kulla 2017, table 1: the fit's coefficients at alpha = 0 and 1, blended by (1 - alpha)^2
  const double p0[5] = {25.3245, 3.32435, 0.16801, -1.27393, -4.85967};
  const double p1[5] = {21.5473, 3.82987, 0.19823, -1.97760, -4.32054};
  double t = (1 - alpha) * (1 - alpha), q[5];
  for (int k = 0; k < 5; ++k) q[k] = t * p0[k] + (1 - t) * p1[k];
  auto L = [&](double x) { return q[0] / (1 + q[1] * std::pow(x, q[2])) + q[3] * x + q[4]; };
  return c < 0.5 ? std::exp(L(c)) : std::exp(2 * L(0.5) - L(1 - c));
}

double charlieNormalisation(double r) {
  auto f = [&](double th) {
    double s = std::sin(th), c = std::cos(th);
    return 2 * kPi * charlieD(r, s * s) * c * s;
  };
  std::vector<double> br;
  for (double d = 0.5; d > 1e-9; d /= 4) br.push_back(kPi / 2 - d);  // the lobe hugs the horizon
  return integrate(f, 0, kPi / 2, br, 1e-14, 1e-13);
}

double sheenAlbedo(int gaf, double r, double mu) { return albedoAt(gaf, r, mu).e; }

void sheenMoments(int gaf, double r, double mu, double* a, double* b) {
  Pair p = albedoAt(gaf, r, mu);
  *a = p.e - p.b;
  *b = p.b;
}

double sheenAlbedoAvg(int gaf, double r) {
  if (r <= 0) return 0;
  auto f = [&](double mu) { return 2 * mu * albedoInside(gaf, r, mu).e; };
  return integrate(f, 0, 1, scaleBreaks(r * r, 0, 1), 1e-11, 1e-10);
}

}  // namespace brdfbake::reference
