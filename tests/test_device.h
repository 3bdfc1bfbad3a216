// What the tests that run kernels share: one KernelRunner on the first OpenCL device (with none,
// selectDevice throws and the test fails loudly), and errors relative to max(1, |want|).
#pragma once
#include <algorithm>
#include <cmath>
#include <memory>

#include "cl/device.h"
#include "cl/runner.h"

namespace brdfbake::testing_device {

inline KernelRunner& runner() {
  static std::unique_ptr<KernelRunner> r;
  if (!r) r = std::make_unique<KernelRunner>(selectDevice("").device);
  return *r;
}

inline double rel(double got, double want) { return std::fabs(got - want) / std::max(1.0, std::fabs(want)); }

}  // namespace brdfbake::testing_device
