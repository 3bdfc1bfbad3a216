#include "tables/measures.h"

#include <algorithm>
#include <cmath>

namespace brdfbake {

StressPoint stressPoint(const std::string& sweep, const std::string& label, double value, double reference,
                        double bound, double slack) {
  StressPoint p;
  p.sweep = sweep;
  p.label = label;
  p.value = value;
  p.reference = reference;
  p.bound = bound;
  p.finite = std::isfinite(value) && std::isfinite(bound);
  p.error = std::fabs(value - reference) / std::max(1.0, std::fabs(reference));
  p.withinBound = p.finite && p.error <= bound + slack;
  return p;
}

}  // namespace brdfbake
