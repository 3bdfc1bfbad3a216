// What the tests that run kernels share: one KernelRunner on the first OpenCL device (with none,
// selectDevice throws and the test fails loudly), and errors relative to max(1, |want|).
#pragma once
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "cl/device.h"
#include "cl/runner.h"
#include "tables/error_model.h"

namespace brdfbake::testing_device {

inline KernelRunner& runner() {
  static std::unique_ptr<KernelRunner> r;
  if (!r) r = std::make_unique<KernelRunner>(selectDevice("").device);
  return *r;
}

inline double rel(double got, double want) { return std::fabs(got - want) / std::max(1.0, std::fabs(want)); }

// The largest float error seen, in u = 2^-24, its largest share of its model's bound, and where
// the largest in u is: what the float models (tables/error_model.h) are fitted to.
struct FloatWorst {
  double u = 0, share = 0;
  std::string at;
  void add(double err, double bound, const std::string& where) {
    if (err / kUnitRoundoff > u) at = where;
    u = std::max(u, err / kUnitRoundoff);
    share = std::max(share, err / bound);
  }
  void add(const FloatWorst& o) {
    if (o.u > u) at = o.at;
    u = std::max(u, o.u);
    share = std::max(share, o.share);
  }
};

}  // namespace brdfbake::testing_device
