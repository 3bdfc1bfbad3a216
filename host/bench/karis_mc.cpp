// Baseline Karis-style Monte Carlo bake of the split-sum (A, B) table. See karis_mc.h.
//
// Per texel (mu, alpha), view o = (sqrt(1 - mu^2), 0, mu), normal n = +z. For sample k of N the
// Hammersley point (u1, u2) = (k/N, radicalInverse2(k)) gives a GGX-distributed half vector
//   cos^2(theta_h) = (1 - u1) / (1 + (alpha^2 - 1) u1),  phi = 2 pi u2,
// the light direction is the reflection i = 2 (o.h) h - o, and if n.i > 0 the sample adds
//   w = G (o.h) / ((n.h)(n.o)),  Fc = (1 - o.h)^5,  A += w (1 - Fc),  B += w Fc,
// where G = 1 / (1 + Lambda(i) + Lambda(o)) is the height-correlated Smith term. Finally A, B /= N.
#include "bench/karis_mc.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <thread>

namespace brdfbake {
namespace {

constexpr float kTwoPi = 6.28318530717958647692f;

// Van der Corput radical inverse in base 2 of k, in [0, 1).
float radicalInverse2(std::uint32_t k) {
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
float smithG2(float ci, float co, float a2) {
    const float si = std::sqrt(ci * ci + a2 * (1.0f - ci * ci));
    const float so = std::sqrt(co * co + a2 * (1.0f - co * co));
    return 2.0f * ci * co / (co * si + ci * so);
}

void bakeRows(int n, int samples, int jBegin, int jEnd, float* planeA, float* planeB) {
    const float invN = 1.0f / static_cast<float>(samples);
    for (int j = jBegin; j < jEnd; ++j) {
        const float r = (static_cast<float>(j) + 0.5f) / static_cast<float>(n);
        const float alpha = r * r;
        const float a2 = alpha * alpha;
        for (int i = 0; i < n; ++i) {
            const float mu = (static_cast<float>(i) + 0.5f) / static_cast<float>(n);
            const float ox = std::sqrt(std::max(0.0f, 1.0f - mu * mu));  // o = (ox, 0, mu)
            float A = 0.0f;
            float B = 0.0f;
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
                const float oh = ox * hx + mu * cosH;      // o.h
                const float ni = 2.0f * oh * cosH - mu;    // n.i, i = 2 (o.h) h - o
                if (ni > 0.0f) {
                    const float G = smithG2(ni, mu, a2);
                    const float w = G * oh / (cosH * mu);
                    const float t = 1.0f - oh;
                    const float t2 = t * t;
                    const float Fc = t2 * t2 * t;
                    A += w * (1.0f - Fc);
                    B += w * Fc;
                }
            }
            planeA[static_cast<std::size_t>(j) * n + i] = A * invN;
            planeB[static_cast<std::size_t>(j) * n + i] = B * invN;
        }
    }
}

}  // namespace

std::vector<std::vector<float>> karisSplitSumMC(int n, int samples, int threads) {
    if (n < 1) throw std::invalid_argument("karisSplitSumMC: n must be >= 1");
    if (samples < 1) throw std::invalid_argument("karisSplitSumMC: samples must be >= 1");
    const int nThreads = std::max(1, std::min(threads, n));

    std::vector<std::vector<float>> planes(2, std::vector<float>(static_cast<std::size_t>(n) * n, 0.0f));
    float* planeA = planes[0].data();
    float* planeB = planes[1].data();

    if (nThreads == 1) {
        bakeRows(n, samples, 0, n, planeA, planeB);
        return planes;
    }
    // Contiguous blocks of rows; every texel costs the same, so this balances well.
    std::vector<std::thread> pool;
    pool.reserve(static_cast<std::size_t>(nThreads));
    for (int t = 0; t < nThreads; ++t) {
        const int jBegin = static_cast<int>(static_cast<long long>(n) * t / nThreads);
        const int jEnd = static_cast<int>(static_cast<long long>(n) * (t + 1) / nThreads);
        pool.emplace_back(bakeRows, n, samples, jBegin, jEnd, planeA, planeB);
    }
    for (std::thread& th : pool) th.join();
    return planes;
}

}  // namespace brdfbake
