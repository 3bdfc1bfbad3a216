// The reference's Fresnel: reflectance from the complex amplitudes, the albedo weights, F_avg.
#include <algorithm>
#include <cmath>
#include <complex>

#include "common/brdf_host.h"
#include "reference/adaptive.h"
#include "reference/reference.h"

namespace brdfbake::reference {

// Fresnel from the complex amplitudes (Born and Wolf 1999, sec. 1.5 and 14.2): with the relative
// index n = eta + i k and cos_t = sqrt(1 - (1 - c^2)/n^2) (principal root: the transmitted wave
// decays), r_s = (c - n cos_t)/(c + n cos_t), r_p = (n c - cos_t)/(n c + cos_t),
// F = (|r_s|^2 + |r_p|^2)/2. Total internal reflection (real eta < 1) comes out as |r| = 1.
namespace {
using C = std::complex<double>;
double amplitudes(C n, double c, C ct) {
  C rs = (c - n * ct) / (c + n * ct), rp = (n * c - ct) / (n * c + ct);
  return 0.5 * (std::norm(rs) + std::norm(rp));
}
double schlick(double f0, double x) { return f0 + (1 - f0) * std::pow(1 - x, 5); }  // Schlick 1994

// F of a real index eta from ct2 = cos_t^2 = 1 - (1 - c^2)/eta^2 (negative under total internal
// reflection), however the caller computed it: the dielectric from its amplitudes; schlick-tir as
// Burley 2015, Schlick on the transmitted cosine where eta < 1 and on c above.
double realIndexFresnel(int model, double eta, double c, double ct2) {
  if (model == FRESNEL_SCHLICK_TIR) {
    const double f0 = std::pow((eta - 1) / (eta + 1), 2);
    if (eta >= 1) return schlick(f0, c);
    return ct2 < 0 ? 1.0 : schlick(f0, std::sqrt(ct2));
  }
  return amplitudes(C(eta, 0), c, std::sqrt(C(ct2)));
}

// cos_t^2 of a real index as (c^2 + (eta - 1)(eta + 1))/eta^2: written as 1 - (1 - c^2)/eta^2,
// next to eta = 1 at a grazing c it cancels to c^2 + eta^2 - 1 ~ 1e-6 and keeps 1e-16 of
// rounding, noise that F's steep layer there magnifies (the reference took 9.4 s a texel at
// eta = 1 + 1e-6, mu = r = 1/512 that way; 0.02 s this way).
double transmittedCos2(double eta, double c) { return (c * c + (eta - 1) * (eta + 1)) / (eta * eta); }
}  // namespace

double complexFresnel(double eta, double k, double c) {
  C n(eta, k);
  return amplitudes(n, c, std::sqrt(C(1.0) - C((1 - c) * (1 + c)) / (n * n)));
}

double fresnel(const FresnelSpec& f, double c) {
  c = std::min(std::fabs(c), 1.0);
  switch (f.model) {
    case FRESNEL_SCHLICK:
      return schlick(f.x, c);
    case FRESNEL_DIELECTRIC:
    case FRESNEL_SCHLICK_TIR:
      return realIndexFresnel(f.model, f.x, c, transmittedCos2(f.x, c));
    case FRESNEL_CONDUCTOR:
      return complexFresnel(f.x, f.y, c);
    case FRESNEL_F82_TINT: {  // Hoffman 2019 / OpenPBR: F(1/7) = tint * Schlick(1/7)
      const double mb = 1.0 / 7;
      double b = schlick(f.x, mb) * (1 - f.y) / (mb * std::pow(1 - mb, 6));
      return schlick(f.x, c) - b * c * std::pow(1 - c, 6);
    }
    default:
      return 1.0;
  }
}

double weightAt(const Weight& w, double c) {
  switch (w.kind) {
    case Weight::Fresnel:
      return fresnel(w.f, c);
    case Weight::F82C:
      return c * std::pow(1 - c, 6);
    default:
      return std::pow(1 - c, 5);
  }
}

// Next to the critical cosine oc = sqrt(1 - eta^2), 1 - (1 - c^2)/eta^2 = (c - oc)(c + oc)/eta^2.
// Computed as written on the left it loses all of c - oc's digits, and F's square-root end turns
// that rounding (1e-16) into noise of 1e-16/sqrt(c - oc) in F: at eta = 0.999, mu = 1/64 an
// adaptive rule asking 1e-13 of the inner integral bisected to its depth limit over a whole
// neighbourhood of the kink (over 5 minutes a texel). From delta = c - oc, given to full relative
// precision by the caller, F is a smooth function of sqrt(delta).
double weightNearKink(const Weight& w, double c, double delta) {
  double oc = weightKink(w);
  if (oc <= 0) return weightAt(w, c);
  const double eta = w.f.x;
  return realIndexFresnel(w.f.model, eta, c, delta * (c + oc) / (eta * eta));
}

double fresnelAvg(const FresnelSpec& f) {
  Weight w{Weight::Fresnel, f};
  double oc = weightKink(w);
  auto g = [&](double mu) { return 2 * mu * fresnel(f, mu); };
  if (oc <= 0) return detail::adapt(g, 0.0, 1.0, 1e-15, 40, 1e-14);
  // Split at the critical cosine, where F has a square-root end: [0, oc] is total reflection
  // (F = 1, so oc^2 exactly); above it, mu = oc + L y^2 with F from the distance t = L y^2
  // (weightNearKink), smooth in y. With F taken from mu alone, the rounding of mu - oc made the
  // rule bisect to its depth limit next to oc (245 s at eta = 0.9999; milliseconds this way).
  const double L = 1 - oc;
  auto graded = [&](double y) {
    double t = L * y * y, mu = oc + t;
    return 2 * mu * weightNearKink(w, mu, t) * 2 * L * y;
  };
  return oc * oc + detail::adapt(graded, 0.0, 1.0, 1e-15, 40, 1e-14);
}

}  // namespace brdfbake::reference
