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
  // --half and --precision float16 are one request, however a library caller spells it: the values'
  // claims then include float16's rounding, and the EXR stores HALF
  if (req.precision == Precision::Float16) req.half = true;
  if (req.half && !req.precision) req.precision = Precision::Float16;
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
