// brdfbake convergence: error against run time for each integration method the baker offers, on
// one table (the albedo of an NDF/GAF pair, with its Fresnel), against the independent reference:
//  - its quadrature on the OpenCL device (float) at budget levels 0 (the bake's default), 1 (the
//    bake's refined budget) and finer (--levels, default 0,1,2,3), every texel at the same level;
//  - the same quadrature in double on the host (what the rule converges to without float);
//  - the common-practice Monte Carlo estimator: NDF importance sampling with Hammersley points
//    (float, 2 threads), 16 to 65536 samples per texel (--samples).
// For each rung: wall time, the estimated error (the quadrature's bound; 3 standard errors for MC)
// and the true error; per method the observed convergence order and the time to reach 1e-3, 1e-5
// and 1e-7. A terminal table, CSV, and an error-against-time plot on log-log axes.
#pragma once
#include <string>
#include <vector>

#include "brdfbake/request.h"

namespace brdfbake {

struct Rung {
  std::string method;  // "quadrature (device, float)", ...
  std::string budget;  // "level 0", "1024 samples"
  double seconds = 0, estimate = 0, error = 0;
};

struct ConvergenceResult {
  std::string table;  // what was measured
  std::vector<Rung> rungs;
  std::string summary;  // orders and times to tolerance
};

ConvergenceResult runConvergence(const BakeRequest& req, std::string* pageLine);
std::string formatConvergence(const ConvergenceResult& r);

}  // namespace brdfbake
