// Common-practice Monte Carlo baselines for two more tables (the counterparts of karis_mc.h):
// the dielectric-Fresnel albedo of GGX + height-correlated Smith, and a diffuse model's albedo.
// Hammersley points, float arithmetic, plain C++ on a few std::threads, every texel independent
// with the same sample sequence (the result does not depend on `threads`; threads < 1 is 1).
#pragma once

#include <vector>

namespace brdfbake {

// E_F(mu, r) = int f_{GGX, smith-correlated} F_dielectric(eta, o.h) (n.i) dw_i by GGX importance
// sampling of h (as karisSplitSumMC: w = G (o.h)/((n.h)(n.o)), times F). n*n floats [j*n + i],
// texel centres mu = (i + 0.5)/n, r = (j + 0.5)/n, alpha = r^2. Throws std::invalid_argument if
// n < 1 or samples < 1.
std::vector<float> dielectricAlbedoMC(int n, float eta, int samples, int threads);

// E(mu, p) = int f_d (n.i) dw_i of diffuse model `model` (kernels/brdf/diffuse.h DIFFUSE_*) by
// cosine-weighted sampling of i: the mean of pi f_d(i, o). n*n floats [j*n + i], texel centres
// mu = (i + 0.5)/n, p = pLo + (pHi - pLo)(j + 0.5)/n. Throws std::invalid_argument if n < 1 or
// samples < 1.
std::vector<float> diffuseAlbedoMC(int model, float pLo, float pHi, int n, int samples, int threads);

}  // namespace brdfbake
