// Baseline Karis-style Monte Carlo bake of the split-sum (A, B) table. See karis_mc.h.
//
// Per texel (mu, alpha), view o = (sqrt(1 - mu^2), 0, mu), normal n = +z. For sample k of N the
// Hammersley point (u1, u2) = (k/N, radicalInverse2(k)) gives a GGX-distributed half vector
//   cos^2(theta_h) = (1 - u1) / (1 + (alpha^2 - 1) u1),  phi = 2 pi u2,
// the light direction is the reflection i = 2 (o.h) h - o, and if n.i > 0 the sample adds
//   w = G (o.h) / ((n.h)(n.o)),  Fc = (1 - o.h)^5,  A += w (1 - Fc),  B += w Fc,
// where G = 1 / (1 + Lambda(i) + Lambda(o)) is the height-correlated Smith term. Finally A, B /= N.
#include "bench/karis_mc.h"

#include <cstddef>
#include <stdexcept>

#include "tables/mc_common.h"

namespace brdfbake {
namespace {

void bakeRows(int n, int samples, int jBegin, int jEnd, float* planeA, float* planeB) {
  const float invN = 1.0f / static_cast<float>(samples);
  for (int j = jBegin; j < jEnd; ++j) {
    const float r = (static_cast<float>(j) + 0.5f) / static_cast<float>(n);
    const float alpha = r * r;
    const float a2 = alpha * alpha;
    for (int i = 0; i < n; ++i) {
      const float mu = (static_cast<float>(i) + 0.5f) / static_cast<float>(n);
      float A = 0.0f;
      float B = 0.0f;
      mc::ggxReflectionSamples(mu, a2, samples, [&](float w, float oh) {
        const float t = 1.0f - oh;
        const float t2 = t * t;
        const float Fc = t2 * t2 * t;
        A += w * (1.0f - Fc);
        B += w * Fc;
      });
      planeA[static_cast<std::size_t>(j) * n + i] = A * invN;
      planeB[static_cast<std::size_t>(j) * n + i] = B * invN;
    }
  }
}

}  // namespace

std::vector<std::vector<float>> karisSplitSumMC(int n, int samples, int threads) {
  if (n < 1) throw std::invalid_argument("karisSplitSumMC: n must be >= 1");
  if (samples < 1) throw std::invalid_argument("karisSplitSumMC: samples must be >= 1");
  std::vector<std::vector<float>> planes(2, std::vector<float>(static_cast<std::size_t>(n) * n, 0.0f));
  float* planeA = planes[0].data();
  float* planeB = planes[1].data();
  mc::splitRows(n, threads, [=](int jBegin, int jEnd) { bakeRows(n, samples, jBegin, jEnd, planeA, planeB); });
  return planes;
}

}  // namespace brdfbake
