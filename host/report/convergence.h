// brdfbake convergence --table KIND: error against run time for each method that can compute one
// table kind, against its independent reference. Each table family supplies its ladder
// (tables/family.h convergence(): the microfacet tables' quadrature on the device and in double
// and Monte Carlo; rules of rising budget for the averages, k_p, F_avg, glass and measured
// materials; resolution for the 3D and Ashikhmin-Shirley tables). For each rung: wall time, the
// method's own error estimate and the true error; per method the observed order and the time to
// reach 1e-3, 1e-5 and 1e-7. A terminal table, CSV, and an error-against-time plot on log-log axes.
#pragma once
#include <string>
#include <vector>

#include "brdfbake/request.h"
#include "tables/family.h"

namespace brdfbake {

struct ConvergenceResult {
  std::string table;  // what was measured
  std::vector<Rung> rungs;
  std::string summary;  // orders and times to tolerance
};

ConvergenceResult runConvergence(const BakeRequest& req, const LadderBudgets& budgets, std::string* pageLine);
std::string formatConvergence(const ConvergenceResult& r);

}  // namespace brdfbake
