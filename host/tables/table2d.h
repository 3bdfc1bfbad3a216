// What every 2D (and 1D) table shares once its family has filled its values: the per-texel claims
// with their float arithmetic, the finite check, the storage rounding, the common metadata and the
// interpolation estimate. The families (microfacet, fresnel-avg) fill the rest.
#pragma once
#include <string>
#include <vector>

#include "cl/runner.h"
#include "formats/table_image.h"
#include "tables/job.h"

namespace brdfbake {

// How a kernel run's float arithmetic is accounted for in its texels' claims.
enum class Arith {
  Hemisphere,          // the hemisphere estimators: floatArithmeticError of the texel's largest moment
  HemiWeighted,        // the same with a Fresnel weight (E_F, F82-tint's C)
  HemiWeightedCancel,  // the same with a weight whose float value cancels (tables/error_model.h weightCancels)
  HemiAvg,             // E_avg: its float error (measured on the averages), plus its double sum rounded to float
  HemiAvgFresnel,      // E_F,avg: the nodes' float error bounds averaged, plus the rounding
  Kp,                  // k_p's rule
  HostDouble,          // computed in double on the host: the rounding to float
  Diffuse,             // the diffuse kernel: floatArithmeticError of E with its model's diffuseFloatModel
};

// Each texel's claim from one kernel run: its quadrature estimate plus its float arithmetic,
// merged (the largest) into `claim`.
void addClaims(std::vector<double>& claim, const KernelTable& t, Arith a, int ndf, int gaf, int diffuse = -1);

// A family's part of a 2D table: planes (one value: repeated in R, G, B), channels (empty: R, G,
// B), its own attributes (brdf.fresnel, brdf.channels, brdf.method, ranges) and each texel's claim.
struct Table2d {
  TableImage img;
  std::vector<double> claim;
  std::string axes = "r";  // brdf.axes: "mu,r", "mu,F0", "r", "eta"
};

// The shared rest: checks every value and claim is finite (Error(kExitSoftware) naming the texel:
// nothing is written), adds the storage rounding to each claim (texelBounds, when given, receives
// them), the common attributes, brdf.error and the interpolation estimate (runner: the probes of
// splitsum and albedo; may be null for host tables).
TableImage finishTable2d(KernelRunner* runner, const TableJob& job, Table2d t, std::vector<double>* texelBounds);

// "ggx+smith-correlated", or the diffuse model's name.
std::string modelsOf(const TableJob& job);

}  // namespace brdfbake
