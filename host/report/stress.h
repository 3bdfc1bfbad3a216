// brdfbake stress: every table kind swept through the stiff and extreme cases (alpha down to 1e-4
// and 0, Blinn-Phong exponents past 1e9, mu down to 1e-6 and 0, gaussian c to 1e3, eta near and
// below 1, conductors with large k, Oren-Nayar sigma to pi/2): for each point the kernel's value,
// whether it is finite, its error against the independent reference, the expected limit and
// whether it is met. Any NaN, Inf, missed limit or error above the claimed bound fails the run.
#pragma once
#include <string>
#include <vector>

#include "brdfbake/request.h"
#include "tables/family.h"

namespace brdfbake {

std::vector<StressPoint> runStress(const BakeRequest& req, std::string* pageLine);
std::string formatStress(const std::vector<StressPoint>& pts);

}  // namespace brdfbake
