// LTC fits of a lobe over the engines' (roughness, view) grid, on the OpenCL device
// (kernels/ltc.cl, kernels/integrate/ltc_fit.h), with the magnitudes from the integrators.
#pragma once
#include <string>
#include <vector>

#include "cl/runner.h"

namespace brdfbake {

// The lobe a table fits: an NDF/GAF pair's specular lobe (diffuse = -1), or a diffuse model.
struct LtcLobeSpec {
  int ndf = -1, gaf = -1;
  int diffuse = -1;
  bool isDiffuse() const { return diffuse >= 0; }
  std::string name() const;  // "ggx_smith-correlated", "burley"
};

// The grid: texel (x, y) of an n x n table holds roughness r = x/(n - 1) (alpha = r^2, floored at
// kLtcMinAlpha) and the view at sqrt(1 - mu) = y/(n - 1), theta_v capped at kLtcMaxTheta: the 2016
// fit's and the engines' parameterisation (three.js's LTC_Uv, Blender's ltc_mat_ggx).
constexpr double kLtcMinAlpha = 1e-5;
constexpr double kLtcMaxTheta = 1.57;
// Texels whose magnitude E is below this carry no light worth an LTC (kernels/ltc.cl
// LTC_NEGLIGIBLE_E): their distance is stated as 1, which every LTC meets.
constexpr double kLtcNegligibleE = 1e-6;
// Texels whose lobe float cannot resolve: a direction's rounding u = 2^-24 moves the half vector by
// about u/mu against a lobe alpha wide, so the device's float estimate of the distance drifts where
// rho = u/(alpha mu) is large. Against the reference (tables/ltc/ltc_reference.h) on the default
// 64^2 GGX fit: at r = 0 (rho >= 6e-3) distances off by up to 0.40 (mu = cos 1.57); at r = 2/63
// (rho = 6e-5) by 1.5e-6, 58 standard errors. Their distances are measured by the same estimator in
// double on the host (r <= 3/63 at 64^2: 256 texels, 0.3 s).
constexpr double kLtcFloatRho = 2e-5;
bool ltcMeasuredInDouble(const LtcLobeSpec& lobe, int x, int y, int n);
double ltcRoughness(int x, int n);
double ltcMu(int y, int n);
// A diffuse model's parameter at roughness r: its axis (common/material.h diffuseAxis) over [0, 1].
double ltcDiffuseParam(int diffuse, double r);

// The fit's budgets (objective points per strategy, Nelder-Mead evaluations, the polish's at 4x
// the points, the distance's points per strategy and shifts). fitPoints is at most 96: the polish's
// fixed points fill kernels/integrate/ltc_fit.h's LTC_MAX_FIXED (768). Measured on the default
// 64^2 table against the 2016 fit (Ltc.DefaultFitIsNoFartherThanThePublished2016Table,
// brdfbake-bench --ltc): these take 11.0 s for a mean distance of 0.0362 and no texel farther than
// the 2016 fit's; a polish of 30 evaluations takes 9.0 s and leaves one texel farther (by 1%).
struct LtcBudget {
  int fitPoints = 96;
  int evals = 200;
  int polishEvals = 60;
  int finalPoints = 256;
  int shifts = 16;
};

// An n x n fit, every plane [y * n + x].
struct LtcFit {
  int n = 0;
  std::vector<float> store[4];   // M^-1 / M^-1_11 entries: (inv00, inv20, inv02, inv22)
  std::vector<float> e, b;       // magnitude E (F = 1) and Fresnel moment B = int f (1 - o.h)^5 cos
  std::vector<double> eBound;    // E's and B's claim (absolute), the integrators' or the diffuse rule's
  std::vector<float> tv, tvErr;  // total-variation distance of the fit and its error estimate (the
                                 // lattices' spread and E's claim relative to E)
  std::vector<float> below;      // the LTC's mass below the horizon
  std::vector<float> evals;      // objective evaluations spent
  int byReference = 0;           // texels whose distance the reference quadrature gave (estimates above 1)
  double seconds = 0;            // fitting (device) time
  double magnitudeSeconds = 0;   // E and B
};

// E's share of a texel's distance claim: p is normalised by the stored E, not the lobe's true
// integral, so the distance moves by at most half their relative difference, which E's claim
// bounds (0 where E is negligible: such texels state distance 1).
double ltcMagnitudeShare(float e, double eBound);

// Fits every texel, rows from the roughest down, each start from the row above (kernels/ltc.cl).
// Progress: runner.progress("rows", ...).
LtcFit fitLtc(KernelRunner& runner, const LtcLobeSpec& lobe, int n, const LtcBudget& budget = {});

// The distance (planes TV, error estimate, mass below) of other stored LTCs (four planes, [y * n + x],
// as LtcFit::store) to the same lobes, measured as fitLtc measures its own; e: the magnitudes.
std::vector<std::vector<float>> measureLtc(KernelRunner& runner, const LtcLobeSpec& lobe, int n,
                                           const std::vector<float> (&store)[4], const std::vector<float>& e,
                                           const LtcBudget& budget = {});

}  // namespace brdfbake
