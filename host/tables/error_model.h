// The float arithmetic's share of a baked table's error. The kernels compute in float; their
// per-texel estimates (kernels/integrate/hemisphere_texel.h hemi_rel_error, hemisphere.h ndf_kp) cover the
// quadrature only. What float adds is modelled per texel from the texel's own values:
//
//   float error <= (K1 min(1, |v|) + K0) u,   relative to max(1, |value|) like every bound,
//
// u = 2^-24 (float's unit roundoff), v the largest magnitude among the moments the kernel returned
// for the texel (A, B, A + B; E for E_avg, k_p). Every node's value carries a few rounding errors of
// relative size u (its libm calls, its position and weight, the lane sums); the moments are sums of
// non-negative terms, perfectly conditioned (Higham, Accuracy and Stability of Numerical
// Algorithms, 2nd ed., 2002, sec. 4.2), so those add up to a small multiple of u times the value:
// K1. K0 is the part that does not scale with the value: where the integrand vanishes at a horizon
// (n.i -> 0) it is formed from cosines that cancel (n.i = 2 (o.h) c - mu), whose absolute error u
// is not reduced by the small factor that makes the value small (at mu = 1, r = 7/8 the implicit
// GAF's E = 0.35 carries 2.95 u). A = H - H w is a difference too, but its absolute error stays
// within u H <= u E: hence the largest moment as the scale.
// K1 and K0 are measured, not derived: the device's value against the same rule evaluated in
// double on the host (brdf64), at every texel of tests/tables/microfacet/accuracy_test.cpp's sweeps for every NDF/GAF
// pair (9x9 node grids with mu = 0, 1 and r = 0, 1; 8x8 texel centres; every edge texel of a
// 128x128 table; the stiff blinn-phong texels), both budgets, per NDF (what differs between them
// is the float work of D and its sampling map; ~21,500 channel values each): on PoCL's CPU device
// at most 4.58 u for ggx, 4.94 u for beckmann, 5.55 u for blinn-phong, 6.21 u for the gaussian
// (a run of the whole of brdfbake-accuracy-tests prints each, and where). The models (3.5 s + 3) u,
// (2.5 s + 3) u, (3.5 s + 3) u and (6 s + 3) u hold the error at every one of those texels, at
// most 0.92 of the bound (beckmann + smith, mu = 1/256, r = 0.84). Fresnel-weighted moments (E_F, F82-tint's C) take
// (10 s + 4) u for every NDF (kFresnelFloat below: the stiff-corner sweep's largest, margin 1.19;
// tests/tables/fresnel_avg/fresnel_test.cpp checks ggx + smith-correlated's whole claims against
// the reference). The charlie NDF is measured the same way
// on the rescaled estimates' panels (charlie-smith's kink breaks and horizon substitution), every
// texel of a 32x32 and a 128x128 table against the same rule in double at the closer budget:
// charlie-smith 35.6 u (its G/(n.o) grows without bound towards grazing views), so (48 s + 4) u,
// at most 0.68 of it; none 7.9 u, (10 s + 4) u, at most 0.62 of it; neubelt 3.9 u and implicit
// 1.5 u, (4 s + 3) u, at most 0.58 and 0.34 of it (`ctest -L sweep -R SheenSweep` prints each).
// tests/tables/microfacet/accuracy_test.cpp and tests/tables/microfacet/sheen_test.cpp check the models at every such
// texel. Another OpenCL device with less accurate built-ins (OpenCL 1.2 allows up to 4 ulp for exp and cos) may exceed
// them: `brdfbake-bench --bounds --device NAME` measures the float part there.
#pragma once
#include <algorithm>
#include <cmath>

#include "common/brdf_host.h"

namespace brdfbake {

constexpr double kUnitRoundoff = 0x1p-24;

struct FloatModel {
  double k1, k0;  // error <= (k1 min(1, |v|) + k0) u
};
// The hemisphere estimators: the gaussian's.
constexpr FloatModel kHemiFloat{6, 3};
// Every NDF's Fresnel-weighted moments (E_F, F82-tint's C). The stiff-corner sweep (ctest -L sweep:
// every pair, 128^2, the first and last four texels on each axis, the device against the same rule
// in double) found f82-tint at tint 0, mu = 1/256, r = 0.996 off by 7.25e-7 with its estimate
// 2.9e-7: 7.2 u at s = 0.46, past the gaussian's (6 s + 3) u; (10 s + 4) u holds it with a margin
// of 1.19.
constexpr FloatModel kFresnelFloat{10, 4};
// The split-sum moments and the albedo of ggx, beckmann and blinn-phong.
constexpr FloatModel kHemiFloatGgx{3.5, 3};
constexpr FloatModel kHemiFloatBeckmann{2.5, 3};
constexpr FloatModel kHemiFloatBlinnPhong{3.5, 3};
// The same for the charlie (sheen) NDF: with charlie-smith, and with its other visibilities.
constexpr FloatModel kCharlieSmithFloat{48, 4};
constexpr FloatModel kSheenFloatNone{10, 4};
constexpr FloatModel kSheenFloatBounded{4, 3};  // neubelt and implicit (sheenGBounded)
// The sheen visibilities whose G/(n.o) stays bounded towards grazing views, and whose tables carry
// a fraction of the others' float error (below, per texel and on the averages).
inline bool sheenGBounded(int gaf) { return gaf == GAF_NEUBELT || gaf == GAF_IMPLICIT; }
// k_p: one GK15 sum of e^-v times a constant (the gaussian: a smooth ratio) per panel; measured at
// most 2.3 u min(1, |v|) on the 9-node and 32-texel grids of the four NDFs.
constexpr FloatModel kKpFloat{4, 0};
// The diffuse albedo kernel (kernels/integrate/diffuse_albedo.h; its |K15 - G7| bounds cover the
// quadrature, not rounding); a flat allowance of 1e-6 would be 5 times its largest error. Measured
// as the others: the device against the same rule in double, every texel of 32x32 and
// 128x128 centre grids and 33x33 and 64x64 node grids, over each model's parameter axis and [0, 1]:
// at most 3.0 u (lambert), 4.1 (shirley), 3.1 (ashikhmin-shirley, 3.1 u at E = 0.81), 4.2
// (oren-nayar), 5.5 (burley, mu = 0.96, r = 0.80) and 4.6 (oren-nayar-as-printed) u; (6 s + 4) u
// holds each with a margin of at least 1.64. shirley-as-printed, the deliberately broken model
// whose E is infinite at its edge, reaches 13.4 u at E = 2.1 (mu = 0.012) on the device and 14.9 u
// of a value under 1 in the host's float build at mu = 1e-6, f0 = 0.9 (tests/diffuse_test.cpp):
// (16 s + 24) u, margin 1.6.
constexpr FloatModel kDiffuseFloat{6, 4};
constexpr FloatModel kDiffuseFloatAsPrinted{16, 24};
inline FloatModel diffuseFloatModel(int model) {
  return model == DIFFUSE_SHIRLEY_AS_PRINTED ? kDiffuseFloatAsPrinted : kDiffuseFloat;
}
// A value computed in double on the host and stored as float: half an ulp, at most u |v|.
constexpr FloatModel kRoundToFloat{1, 0};

// weighted: a Fresnel-weighted moment (HEMI_FRESNEL, HEMI_F82C).
inline FloatModel hemiFloatModel(int ndf, int gaf, bool weighted = false) {
  if (ndf == NDF_CHARLIE)
    return sheenGBounded(gaf) ? kSheenFloatBounded : gaf == GAF_CHARLIE_SMITH ? kCharlieSmithFloat : kSheenFloatNone;
  if (weighted) return kFresnelFloat;
  switch (ndf) {
    case NDF_GGX:
      return kHemiFloatGgx;
    case NDF_BECKMANN:
      return kHemiFloatBeckmann;
    case NDF_BLINN_PHONG:
      return kHemiFloatBlinnPhong;
    default:
      return kHemiFloat;
  }
}

// The float arithmetic's bound for a texel whose largest moment is `scale`, relative to
// max(1, |value|).
inline double floatArithmeticError(double scale, FloatModel m = kHemiFloat) {
  return (m.k1 * std::min(1.0, std::fabs(scale)) + m.k0) * kUnitRoundoff;
}

// A Fresnel-weighted moment B = int H w next to E = int H, the F = 1 albedo. Where w's float value
// cancels (F82-tint: Schlick's term minus the tint term, most at tint 0) each node's w carries an
// absolute error of a fraction of u, so B carries u times a fraction of int H = E, not of B. With
// G = 1 (gaf none) E grows as 1/mu towards grazing views (E = 154 at mu = 1/512, r = 0.99), and
// the stiff-corner sweep at 256^2 (ctest -L sweep) found f82-tint at tint 0 there 27 u off on
// gaussian + none, 1.72 times the weighted model's (10 s + 4) u. Over every texel of the sweep's
// corners of the four none pairs with tint 0, the error is at most 0.21 u E/max(1, |B|) where E > 10
// (BRDFBAKE_SWEEP_TEXELS=1 BRDFBAKE_SWEEP_PAIRS=ggx+none,... ctest -L sweep -V): the claim takes the larger of the
// model and 0.3 u E/max(1, |B|), margin 1.43. Where E <= 46 the model is the larger, so every pair but none keeps its
// claims. Weights computed to a relative precision (dielectric, conductor, the Schlick forms) keep the model alone:
// scaled with E, dielectric eta = 1 - 1e-6 on ggx + none (B ~ 1e-6, E ~ 10) would claim 40 to 330 times its error.
inline bool weightCancels(int fresnelModel) { return fresnelModel == FRESNEL_F82_TINT; }
inline double weightedFloatError(double b, double e, double scale, int ndf, int gaf, bool cancels) {
  const double plain = floatArithmeticError(scale, hemiFloatModel(ndf, gaf, true));
  return cancels ? std::max(plain, 0.3 * kUnitRoundoff * std::fabs(e) / std::max(1.0, std::fabs(b))) : plain;
}

// E_avg = sum_k w_k E_k with weights w_k = 2 mu_k (Kronrod weight) >= 0 that sum to 1. Node k's
// absolute error is within (k1 E_k + k0 max(1, E_k)) u, so the sum's within
// (k1 E_avg + k0 (1 + E_avg)) u, relative to max(1, E_avg) within (k1 min(1, E_avg) + 2 k0) u.
// The host forms the sum in double and rounds it to float once: that rounding is known exactly
// and is in the entry's own claim (host/cl/runner_avg.cpp), not here. That bound adds
// every node's worst case, 13 u at E_avg ~ 1; the nodes' errors have both signs and mostly cancel.
// For the plain average albedo of the four microfacet NDFs the average's own float error is
// measured instead (tests/tables/microfacet/avg_float_test.cpp: every pair, the r of 32- and 64-entry tables and a
// 33-node grid, the bake's rule with the device's nodes against the same rule in double), per NDF:
// at most 1.70 u (ggx + none), 1.59 u (beckmann + none), 1.77 u (blinn-phong + none), 4.26 u
// (gaussian + none; integrated on GGX's grid with the weight D_gauss/D_ggx, more float operations
// per node); the pairs other than none at most 1.54, 1.51, 1.66 and 3.97 u. The models
// hold the largest with a margin of 1.35, so one model per NDF covers every GAF.
// Fresnel-weighted averages take the summed bound. Charlie's is measured (the summed bound would be
// 22 u for charlie-smith at E_avg ~ 0.3): the bake's table against its rule in double at the same
// nodes, every entry of 32-, 128- and 1024-entry tables on both grids (`ctest -L sweep -R
// SheenSweep`): at most 3.00 u (none, E_avg ~ 1 at r = 0.024, 1024 entries; the stored value's
// rounding included) and 2.85 u (charlie-smith, r = 0.93, 1024 entries): 4 u, the microfacet
// models' margin (3 u would hold 3.00 u with none, and the rule without its sheen lobe break
// reached 3.02 u at r = 1/256); 0.73 u (neubelt) and 0.58 u (implicit): 1 u; each at most 0.75 of
// its model.
constexpr FloatModel kAvgFloatMicrofacet[4] = {{0, 2.3}, {0, 2.15}, {0, 2.4}, {0, 5.76}};  // NDF_GGX .. NDF_GAUSSIAN
constexpr FloatModel kAvgFloatSheen{0, 4};
constexpr FloatModel kAvgFloatSheenBounded{0, 1};  // neubelt and implicit (sheenGBounded)
inline double avgFloatArithmeticError(double value, int ndf, int gaf, bool weighted = false) {
  if (ndf == NDF_CHARLIE)
    return floatArithmeticError(value, sheenGBounded(gaf) ? kAvgFloatSheenBounded : kAvgFloatSheen);
  if (weighted) {
    FloatModel m = hemiFloatModel(ndf, gaf, weighted);
    return floatArithmeticError(value, FloatModel{m.k1, 2 * m.k0});
  }
  // (the four microfacet NDFs are ids 0 to 3, NDF_GGX .. NDF_GAUSSIAN; charlie returned above)
  return floatArithmeticError(value, kAvgFloatMicrofacet[ndf - NDF_GGX]);
}

}  // namespace brdfbake
