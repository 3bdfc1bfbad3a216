#include "plan/plan.h"

#include "formats/layout.h"
#include "tables/registry.h"

namespace brdfbake {

BakeRequest defaultRequest() {
  BakeRequest r;
  r.ndfs = {ndfId("ggx")};
  r.gafs = {gafId("smith-correlated")};
  r.tables = kindsWhere([](const KindInfo& k) { return k.inDefaultSet; });
  return r;
}

Plan makePlan(const BakeRequest& given) {
  // a layout preset's size, where the request gives none (its format and precision: parseArgs)
  BakeRequest req = given;
  if (req.preset.empty() && req.merl.empty() && req.layoutPreset && !req.size)
    req.size = layoutPreset(*req.layoutPreset).size;
  Plan plan;
  plan.outDir = req.outDir;
  plan.device = req.device;
  plan.noWait = req.noWait;
  plan.observer = req.observer;
  for (const TableFamily* f : families())
    for (Job& j : f->plan(req)) plan.jobs.push_back(std::move(j));
  return plan;
}

}  // namespace brdfbake
