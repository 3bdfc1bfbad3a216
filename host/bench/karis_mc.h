// Baseline split-sum (DFG) LUT baker: "the common practice" (Karis 2013, "Real Shading in
// Unreal Engine 4"): Hammersley points, GGX importance sampling of the half vector,
// height-correlated Smith masking-shadowing, plain C++ on a few std::threads.
#pragma once

#include <vector>

namespace brdfbake {

// Split-sum (A, B) for GGX + height-correlated Smith, Karis-style importance sampling.
// Returns planes {A, B}, each n*n floats indexed [j*n + i] (i over mu, j over r), texel centres:
//   mu = (i + 0.5)/n (cosine of the view angle), r = (j + 0.5)/n (perceptual roughness), alpha = r*r.
// Runs on `threads` std::threads splitting the rows j; `samples` per texel. Float arithmetic inside
// the sample loop (as a shader/engine tool would), accumulation in float.
// Every texel is computed independently with the same sample sequence, so the result does not
// depend on `threads`. threads < 1 is treated as 1; more threads than rows are not started.
// Throws std::invalid_argument if n < 1 or samples < 1.
std::vector<std::vector<float>> karisSplitSumMC(int n, int samples, int threads);

}  // namespace brdfbake
