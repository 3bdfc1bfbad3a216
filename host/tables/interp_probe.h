// What a bilinear lookup in a (mu, r) table misses between its texels, measured: the kernel
// evaluated at probe points against the lookup there. The estimate from the table itself
// (interp_estimate.h) sees only what the texels hold; towards the corner (mu, r) = (0, 0) the
// albedo of a microfacet model dips where mu ~ alpha = r^2 (to 0.89 for ggx + smith-correlated)
// between texels that hold ~1, in a wedge narrower than a texel at every resolution. The probes:
// quarter-texel steps over the first six texels of mu, and mu = alpha 2^k and r 2^k (k = -3..3,
// the grazing layer's scales), on every half-texel row up to r = 0.3.
#pragma once
#include <vector>

#include "cl/runner.h"
#include "formats/table_image.h"
#include "tables/job.h"

namespace brdfbake {

// Where one plane of the table comes from: the hemisphere kernel with weight w, its A (0), B (1)
// or A + B (2); which < 0: not probed (a plane from another kernel).
struct ProbePlane {
  HemiWeight w;
  int which;
};

// The planes of a splitsum or albedo job as computeTable (bake.cpp) fills them; empty for other
// tables (and a diffuse model's albedo, from its own kernel).
std::vector<ProbePlane> probePlanes(const TableJob& job);

// The largest lookup error over the probes, relative to max(1, |value|), every probed plane.
double probeInterpolation(KernelRunner& runner, const TableJob& job, const TableImage& img,
                          const std::vector<ProbePlane>& planes);

}  // namespace brdfbake
