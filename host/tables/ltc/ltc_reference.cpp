// Derivation. D and p both integrate to 1 over the sphere (D exactly, for every invertible M; p up to
// E's claim, which the device's error estimate carries), so
//   1/2 int |p - D| = 1 - int min(p, D).
// Substituting w = M w_o/|M w_o| (D(w) dw = D_o(w_o) dw_o, D_o = max(0, z_o)/pi):
//   int min(p, D) dw = int min(p(w)/D(w), 1) D_o(w_o) dw_o,
// and with Malley's map (w_o from a point of the unit disk at radius sqrt(s), angle phi;
// D_o dw_o = ds dphi/(2 pi)) it is the mean of g = min(p/D, 1) over s in [0, 1), phi in [0, 2 pi).
// g lies in [0, 1] and is broad wherever the LTC is near the lobe: where p is a spike D misses, g is
// 1 over a small area. Composite Gauss-Legendre in s times the trapezoid in phi (periodic), the lobe
// and the LTC symmetric in y (phi -> -phi): half the circle, doubled. It shares the kernels' p and D
// (kernels/integrate/ltc_fit.h, kernels/brdf/ltc.h, in double), not their sampling or estimator.
#include "tables/ltc/ltc_reference.h"

#include <algorithm>
#include <cmath>

#include "common/brdf_host.h"
#include "common/material.h"
#include "common/models.h"
#include "reference/adaptive.h"

namespace brdfbake {

namespace {

// The mean of g over the disk, s in [0, 1) and phi in [0, pi) (the y-symmetry's half), by nested
// adaptive Gauss-Kronrod (reference/adaptive.h) to absolute tolerance tol.
template <class G>
double diskMean(const G& g, double tol) {
  auto row = [&](double s) {
    auto inner = [&](double phi) { return g(s, phi); };
    return reference::detail::adapt(inner, 0.0, M_PI, tol * M_PI, 40, 0.0) / M_PI;
  };
  return reference::detail::adapt(row, 0.0, 1.0, tol, 40, 0.0);
}

}  // namespace

brdf64::LtcLobe ltcTexelLobe(const LtcLobeSpec& lobe, int x, int y, int n, double e) {
  const double rr = ltcRoughness(x, n), mu = static_cast<float>(ltcMu(y, n));
  const double r = static_cast<float>(lobe.isDiffuse() ? rr : std::max(rr, std::sqrt(kLtcMinAlpha)));
  const int kind = lobe.isDiffuse() ? 1 : 0;  // kernels/integrate/ltc_fit.h LTC_LOBE_DIFFUSE / _SPECULAR
  const int ndf = lobe.isDiffuse() ? NDF_GGX : lobe.ndf, gaf = lobe.isDiffuse() ? GAF_SMITH_CORRELATED : lobe.gaf;
  const double invKp = lobe.isDiffuse() ? 0.0 : static_cast<float>(brdf64::brdf_params(ndf, gaf, r).inv_kp);
  const double dparam = lobe.isDiffuse() ? static_cast<float>(ltcDiffuseParam(lobe.diffuse, rr)) : 0.0;
  brdf64::LtcLobe L = brdf64::ltc_lobe(kind, ndf, gaf, lobe.diffuse, mu, r, dparam, invKp, e);
  brdf64::ltc_lobe_view(&L);
  return L;
}

LtcDistance ltcDistanceReference(const LtcLobeSpec& lobe, int x, int y, int n, const float (&store)[4], double e) {
  const brdf64::LtcLobe L = ltcTexelLobe(lobe, x, y, n, e);
  const brdf64::Ltc l = brdf64::ltc_from_stored(store[0], store[1], store[2], store[3]);
  auto g = [&](double s, double phi) {
    const double rad = std::sqrt(s), oz = std::sqrt(std::max(0.0, 1 - s));
    const double ox = rad * std::cos(phi), oy = rad * std::sin(phi);
    double w[3] = {l.m[0] * ox + l.m[1] * oy + l.m[2] * oz, l.m[3] * ox + l.m[4] * oy + l.m[5] * oz,
                   l.m[6] * ox + l.m[7] * oy + l.m[8] * oz};
    const double len = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    for (double& c : w) c /= len;
    const double d = brdf64::ltc_D(l, w[0], w[1], w[2]);
    if (!(d > 0)) return 0.0;  // the disk's rim (z_o = 0): weight 0 in the mean
    return std::min(brdf64::ltc_lobe_p(&L, w[0], w[1], w[2]) / d, 1.0);
  };
  // to 1e-7 and to 1e-6: on a 16^2 GGX fit's texels at r 0, 1/15, 8/15 and 1 their difference was
  // within 3 times the change to 1e-8 (tests/tables/ltc/ltc_test.cpp)
  const double coarse = diskMean(g, 1e-6), fine = diskMean(g, 1e-7);
  LtcDistance out;
  out.tv = 1 - fine;
  out.err = std::fabs(fine - coarse);
  return out;
}

LtcDistance ltcDistanceReference(const LtcLobeSpec& lobe, int n, const std::vector<float> (&store)[4],
                                 const std::vector<float>& e, size_t t) {
  const float s[4] = {store[0][t], store[1][t], store[2][t], store[3][t]};
  return ltcDistanceReference(lobe, static_cast<int>(t % n), static_cast<int>(t / n), n, s, e[t]);
}

}  // namespace brdfbake
