// What a bilinear lookup in a (mu, r) table misses between its texels, measured: the kernel
// evaluated at probe points against the lookup there. The estimate from the table itself
// (interp_estimate.h) sees only what the texels hold; towards the corner (mu, r) = (0, 0) the
// albedo of a microfacet model dips where mu ~ alpha = r^2 (to 0.89 for ggx + smith-correlated)
// between texels that hold ~1, in a wedge narrower than a texel at every resolution. The probes:
// quarter-texel steps over the first two texels of mu (kProbeMuTexels), and mu = alpha 2^k and
// r 2^k (k = -3..3, the grazing layer's scales), on every half-texel row up to r = 0.3.
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

// brdf.interp-error: the larger of the estimate from the texels (interp_estimate.h) and the
// probes' largest lookup error with this margin (the probes sample the wedge near the corner, not
// its every point).
constexpr double kProbeMargin = 1.5;

// How many texels of mu from the edge the quarter-texel steps cover. Two find the corner's largest
// lookup error, at a layer point or a quarter step inside the first texel, as six do; where a
// larger error lies further out, in the smooth part, the estimate from the texels exceeds it.
// `brdfbake-bench --probe-span` checks that brdf.interp-error is the same with two as with six
// (every pair's split sum on both mu axes and 32^2 albedo) and times the probes: at 128^2, the same
// in all 168 tables and the same largest error in each, in 0.58 of the time.
constexpr int kProbeMuTexels = 2;

// The largest lookup error over the probes, relative to max(1, |value|), every probed plane;
// muTexels: the texels of mu that the quarter steps cover.
double probeInterpolation(KernelRunner& runner, const TableJob& job, const TableImage& img,
                          const std::vector<ProbePlane>& planes, int muTexels = kProbeMuTexels);

}  // namespace brdfbake
