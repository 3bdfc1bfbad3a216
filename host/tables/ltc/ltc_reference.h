// The fit's distance by an independent quadrature in double: the reference that `brdfbake
// convergence --table ltc` and `brdfbake stress` hold the device's estimate (kernels/integrate/
// ltc_fit.h ltc_tv) against.
#pragma once
#include <vector>

#include "common/brdf_host.h"
#include "tables/ltc/ltc_fit.h"

namespace brdfbake {

// The total-variation distance 1/2 int |p - D| of a stored LTC (ltc_store's four entries) to the
// lobe of texel (x, y) of an n x n table, p normalised by the magnitude e; err: the quadrature's
// own error estimate (its change from half the nodes per axis).
// The lobe of texel (x, y) in double, view set (ltc_lobe_view), p normalised by e: the lobe the
// device fits, at its float view and roughness (a narrow lobe is that sensitive: at 64^2, r = 1/63,
// mu = 1 - (2/63)^2, rounding mu to float alone moves the distance by 3.3e-4).
brdf64::LtcLobe ltcTexelLobe(const LtcLobeSpec& lobe, int x, int y, int n, double e);

struct LtcDistance {
  double tv = 0, err = 0;
};
LtcDistance ltcDistanceReference(const LtcLobeSpec& lobe, int x, int y, int n, const float (&store)[4], double e);
// The same for texel t ([y * n + x]) of n x n planes as LtcFit holds them (store, e).
LtcDistance ltcDistanceReference(const LtcLobeSpec& lobe, int n, const std::vector<float> (&store)[4],
                                 const std::vector<float>& e, size_t t);

}  // namespace brdfbake
