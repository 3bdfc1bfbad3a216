#include "tables/ladder.h"

#include <boost/math/quadrature/gauss.hpp>
#include <thread>

#include "common/errors.h"

namespace brdfbake::ladder {

void onTwoThreads(size_t count, const std::function<void(size_t)>& f) {
  std::thread other([&] {
    for (size_t k = 1; k < count; k += 2) f(k);
  });
  for (size_t k = 0; k < count; k += 2) f(k);
  other.join();
}

double gaussLegendre(const std::function<double(double)>& f, double a, double b, int panels) {
  using GL = boost::math::quadrature::gauss<double, 8>;
  double h = (b - a) / panels, sum = 0;
  for (int p = 0; p < panels; ++p) sum += GL::integrate(f, a + p * h, a + (p + 1) * h);
  return sum;
}

std::vector<Node> gaussLegendreNodes(double a, double b, int panels) {
  using GL = boost::math::quadrature::gauss<double, 8>;
  std::vector<Node> out;
  double h = (b - a) / panels;
  for (int p = 0; p < panels; ++p) {
    double mid = a + (p + 0.5) * h, half = h / 2;
    for (size_t k = 0; k < GL::abscissa().size(); ++k) {
      out.push_back({mid - half * GL::abscissa()[k], half * GL::weights()[k]});
      out.push_back({mid + half * GL::abscissa()[k], half * GL::weights()[k]});
    }
  }
  return out;
}

Rung rung(const std::string& method, const std::string& budget, double seconds, const std::vector<double>& value,
          const std::vector<double>& estimate, const std::vector<double>& reference) {
  Rung r{method, budget, seconds, 0, 0};
  for (size_t k = 0; k < value.size(); ++k) {
    r.error = std::max(r.error, rel(value[k], reference[k]));
    if (k < estimate.size()) r.estimate = std::max(r.estimate, estimate[k]);
  }
  return r;
}

std::vector<double> changeFrom(const std::vector<double>& prev, const std::vector<double>& v) {
  std::vector<double> e(v.size(), 0.0);
  if (prev.size() == v.size())
    for (size_t k = 0; k < v.size(); ++k) e[k] = rel(v[k], prev[k]);
  return e;
}

int pointsPerAxis(const BakeRequest& req, int dflt, int lo, int hi, const std::string& what) {
  int n = req.size ? *req.size : dflt;
  if (n < lo || n > hi)
    throw Error(kExitUsage, "--size for convergence of " + what + " must be in " + std::to_string(lo) + ".." +
                                std::to_string(hi) + " (points per axis), got " + std::to_string(n));
  return n;
}

}  // namespace brdfbake::ladder
