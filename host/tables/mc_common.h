// What the common-practice Monte Carlo baselines (karis_mc.cpp, material_mc.cpp) share: the
// Hammersley point set, GGX importance sampling of the half vector with its reflected light
// direction and height-correlated Smith weight, and the split of a table's rows over std::threads.
// Float arithmetic throughout, as a shader or engine tool would do it.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <thread>
#include <vector>

namespace brdfbake::mc {

constexpr float kTwoPi = 6.28318530717958647692f;

// Van der Corput radical inverse in base 2 of k, in [0, 1).
inline float radicalInverse2(std::uint32_t k) {
  k = (k << 16) | (k >> 16);
  k = ((k & 0x00ff00ffu) << 8) | ((k & 0xff00ff00u) >> 8);
  k = ((k & 0x0f0f0f0fu) << 4) | ((k & 0xf0f0f0f0u) >> 4);
  k = ((k & 0x33333333u) << 2) | ((k & 0xccccccccu) >> 2);
  k = ((k & 0x55555555u) << 1) | ((k & 0xaaaaaaaau) >> 1);
  // Top 24 bits only, so the float conversion is exact and the result stays < 1
  // (for k < 2^24 the dropped low 8 bits are zero anyway, i.e. this is the exact value).
  return static_cast<float>(k >> 8) * (1.0f / 16777216.0f);
}

// Height-correlated Smith G for GGX, for cosines ci = n.i > 0 and co = n.o > 0.
// With Lambda(v) = (sqrt(c^2 + a2 (1 - c^2)) - c) / (2c), c = n.v, one has
//   1 + Lambda(i) + Lambda(o) = (si/ci + so/co) / 2,  s = sqrt(c^2 + a2 (1 - c^2)),
// so G = 2 ci co / (co si + ci so): no tan^2 overflow, no cancellation, no division by a
// tiny cosine alone (the denominator is > 0 whenever ci, co > 0).
inline float smithG2(float ci, float co, float a2) {
  const float si = std::sqrt(ci * ci + a2 * (1.0f - ci * ci));
  const float so = std::sqrt(co * co + a2 * (1.0f - co * co));
  return 2.0f * ci * co / (co * si + ci * so);
}

// Karis 2013 GGX importance sampling for the view o = (sqrt(1 - mu^2), 0, mu), alpha^2 = a2: for
// the Hammersley point (k/N, radicalInverse2(k)) of each sample k < N,
//   cos^2(theta_h) = (1 - u1) / (1 + (alpha^2 - 1) u1),  phi = 2 pi u2,  i = 2 (o.h) h - o,
// and, where n.i > 0, calls add(w, o.h) with w = G (o.h) / ((n.h)(n.o)) (the estimate of
// int f_{F=1} (n.i) dw_i is the sum of the w over N).
template <class Add>
inline void ggxReflectionSamples(float mu, float a2, int samples, Add&& add) {
  const float invN = 1.0f / static_cast<float>(samples);
  const float ox = std::sqrt(std::max(0.0f, 1.0f - mu * mu));
  for (int k = 0; k < samples; ++k) {
    const float u1 = static_cast<float>(k) * invN;
    const float u2 = radicalInverse2(static_cast<std::uint32_t>(k));
    // GGX half vector. cos^2 and sin^2 from a common denominator (no 1 - cos^2 cancellation).
    const float den = (1.0f - u1) + a2 * u1;
    const float cosH = std::sqrt((1.0f - u1) / den);
    const float sinH = std::sqrt(a2 * u1 / den);
    const float phi = kTwoPi * u2;
    const float hx = sinH * std::cos(phi);
    // (h.y does not enter: o.y = 0 and only n.i, o.h are needed.)
    const float oh = ox * hx + mu * cosH;    // o.h
    const float ni = 2.0f * oh * cosH - mu;  // n.i, i = 2 (o.h) h - o
    if (ni > 0.0f) add(smithG2(ni, mu, a2) * oh / (cosH * mu), oh);
  }
}

// rows(jBegin, jEnd) over [0, n) in contiguous blocks on `threads` std::threads (every texel
// costs about the same, so this balances well); threads < 1 is 1, never more threads than rows.
template <class Rows>
inline void splitRows(int n, int threads, Rows rows) {
  const int nThreads = std::max(1, std::min(threads, n));
  if (nThreads == 1) {
    rows(0, n);
    return;
  }
  std::vector<std::thread> pool;
  pool.reserve(static_cast<std::size_t>(nThreads));
  for (int t = 0; t < nThreads; ++t) {
    const int jBegin = static_cast<int>(static_cast<long long>(n) * t / nThreads);
    const int jEnd = static_cast<int>(static_cast<long long>(n) * (t + 1) / nThreads);
    pool.emplace_back(rows, jBegin, jEnd);
  }
  for (std::thread& th : pool) th.join();
}

}  // namespace brdfbake::mc
