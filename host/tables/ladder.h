// What the families' convergence ladders share (tables/family.h convergence()).
#pragma once
#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "tables/family.h"

namespace brdfbake::ladder {

inline double rel(double a, double b) { return std::fabs(a - b) / std::max(1.0, std::fabs(b)); }
inline double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// The best of three runs' wall time (a rung's time on a shared machine).
template <class F>
double best3(F f) {
  double b = 1e300;
  for (int k = 0; k < 3; ++k) {
    double t0 = now();
    f();
    b = std::min(b, now() - t0);
  }
  return b;
}

// Runs f(k) for k < count on two threads (the reference, host rules), the order of work fixed.
void onTwoThreads(size_t count, const std::function<void(size_t)>& f);

// The nodes and weights of composite 8-point Gauss-Legendre over `panels` equal panels of [a, b].
struct Node {
  double x, w;
};
std::vector<Node> gaussLegendreNodes(double a, double b, int panels);

// Composite 8-point Gauss-Legendre over `panels` equal panels of [a, b], in double.
double gaussLegendre(const std::function<double(double)>& f, double a, double b, int panels);

// A rung from values against the reference: true error and estimate, the largest of each.
Rung rung(const std::string& method, const std::string& budget, double seconds, const std::vector<double>& value,
          const std::vector<double>& estimate, const std::vector<double>& reference);

// The texel-centre coordinate of i < n on [0, 1], as a float (what the device sees).
inline double centre(int i, int n) { return static_cast<float>((i + 0.5) / n); }

// A fixed rule's own estimate: its change from the previous rung, relative to max(1, |v|), per
// value (0 on the first rung, which has none).
std::vector<double> changeFrom(const std::vector<double>& prev, const std::vector<double>& v);

// The points' count, --size or `dflt`, checked against [lo, hi] (Error(kExitUsage) naming --size).
int pointsPerAxis(const BakeRequest& req, int dflt, int lo, int hi, const std::string& what);

}  // namespace brdfbake::ladder
