// The shared BRDF code (kernels/brdf, kernels/integrate) compiled for the host, twice:
// brdf64 in double (model tests, the reference's integrand) and brdf32 in float (the device's
// arithmetic, one lane: same formulas and rules, but lane sums in a different order, so results
// agree with the device's to float rounding, not bit for bit). The second namespace is the
// headers' second pass (kernels/brdf/compat.h "Passes"); each header brings what it uses.
#pragma once
#include "brdf/compat.h"
#define BRDF_HOST_NAMESPACE 1

namespace brdf64 {
typedef double real;
#include "common/brdf_host_models.h"
}  // namespace brdf64

#define BRDF_SECOND_PASS 1
namespace brdf32 {
typedef float real;
#include "common/brdf_host_models.h"
}  // namespace brdf32
#undef BRDF_SECOND_PASS
