// Monte Carlo baselines for the dielectric and diffuse albedo tables. See material_mc.h.
//
// Dielectric: per texel, karis_mc.cpp's estimator (mc::ggxReflectionSamples) with the sample
// weight w multiplied by the exact dielectric F(o.h) (brdf32::fresnel_dielectric).
// Diffuse: view o = (so, 0, no), no = mu; for sample k of N the Hammersley point (u1, u2) =
// (k/N, radicalInverse2(k)) gives the cosine-distributed light direction
//   n.i = sqrt(1 - u1),  sin(theta_i) = sqrt(u1),  phi = 2 pi u2  (pdf (n.i)/pi),
// so f_d (n.i)/pdf = pi f_d(i, o) (brdf32::diffuse_f), averaged over the N samples.
#include "bench/material_mc.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "tables/mc_common.h"
#include "common/brdf_host.h"

namespace brdfbake {
namespace {

constexpr float kPi = 3.14159265358979323846f;

void check(int n, int samples, const char* what) {
  if (n < 1) throw std::invalid_argument(std::string(what) + ": n must be >= 1");
  if (samples < 1) throw std::invalid_argument(std::string(what) + ": samples must be >= 1");
}

float texelCentre(int i, int n) { return (static_cast<float>(i) + 0.5f) / static_cast<float>(n); }

}  // namespace

std::vector<float> dielectricAlbedoMC(int n, float eta, int samples, int threads) {
  check(n, samples, "dielectricAlbedoMC");
  std::vector<float> out(static_cast<std::size_t>(n) * n, 0.0f);
  float* e = out.data();
  mc::splitRows(n, threads, [=](int jBegin, int jEnd) {
    const float invN = 1.0f / static_cast<float>(samples);
    for (int j = jBegin; j < jEnd; ++j) {
      const float alpha = texelCentre(j, n) * texelCentre(j, n);
      for (int i = 0; i < n; ++i) {
        float sum = 0.0f;
        mc::ggxReflectionSamples(texelCentre(i, n), alpha * alpha, samples,
                                 [&](float w, float oh) { sum += w * brdf32::fresnel_dielectric(eta, oh); });
        e[static_cast<std::size_t>(j) * n + i] = sum * invN;
      }
    }
  });
  return out;
}

std::vector<float> diffuseAlbedoMC(int model, float pLo, float pHi, int n, int samples, int threads) {
  check(n, samples, "diffuseAlbedoMC");
  std::vector<float> out(static_cast<std::size_t>(n) * n, 0.0f);
  float* e = out.data();
  mc::splitRows(n, threads, [=](int jBegin, int jEnd) {
    const float invN = 1.0f / static_cast<float>(samples);
    for (int j = jBegin; j < jEnd; ++j) {
      const float p = pLo + (pHi - pLo) * texelCentre(j, n);
      for (int i = 0; i < n; ++i) {
        const float no = texelCentre(i, n);
        const float so = std::sqrt(std::max(0.0f, 1.0f - no * no));
        float sum = 0.0f;
        for (int k = 0; k < samples; ++k) {
          const float u1 = static_cast<float>(k) * invN;
          const float cphi = std::cos(mc::kTwoPi * mc::radicalInverse2(static_cast<std::uint32_t>(k)));
          sum += brdf32::diffuse_f(model, p, std::sqrt(1.0f - u1), std::sqrt(u1), no, so, cphi);
        }
        e[static_cast<std::size_t>(j) * n + i] = kPi * sum * invN;
      }
    }
  });
  return out;
}

}  // namespace brdfbake
