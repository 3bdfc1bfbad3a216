// The LTC family's measurements against the reference distance (tables/ltc/ltc_reference.h):
// its convergence ladder (brdfbake convergence --table ltc) and its stress points (brdfbake stress).
#pragma once
#include <vector>

#include "tables/family.h"

namespace brdfbake {

Ladder ltcLadder(BakeContext& ctx, const BakeRequest& req);
void ltcStress(BakeContext& ctx, std::vector<StressPoint>& out);

}  // namespace brdfbake
