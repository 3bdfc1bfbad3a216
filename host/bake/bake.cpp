#include "bake/bake.h"

#include <map>

#include "formats/output_set.h"
#include "tables/registry.h"

namespace brdfbake {

std::vector<TableReport> runPlan(const Plan& plan) {
  // Nothing is created before every table is computed and checked: a bad -o, a missing device
  // or an interrupt leaves the file system as it was.
  checkOutputDir(plan.outDir);
  BakeContext ctx(plan.device);
  // each family's checks over its jobs (free space, inputs read once), in registry order
  std::map<const TableFamily*, std::vector<const Job*>> byFamily;
  for (const Job& j : plan.jobs) byFamily[j.family].push_back(&j);
  for (const TableFamily* f : families())
    if (byFamily.count(f)) f->preflight(ctx, plan.outDir, byFamily[f]);
  // every kernel the plan needs, built at once on parallel contexts (on the device only when a
  // job runs there)
  std::vector<KernelNeed> needs;
  bool device = false;
  for (const Job& j : plan.jobs) {
    device = device || j.family->usesDevice(j);
    for (const KernelNeed& k : j.family->kernels(j)) needs.push_back(k);
  }
  if (device) ctx.runner();
  guardInterrupts("abandoned " + std::to_string(plan.jobs.size()) + " table(s) for " + plan.outDir + "/");
  if (device) ctx.runner().prepareAll(needs);
  FileSet set;
  set.extraStrings = plan.extraStrings;
  for (const Job& j : plan.jobs) j.family->addFiles(ctx, j, set);
  commitOutputs(plan.outDir, set.files);
  for (auto& after : set.afterCommit) after();
  return set.reports;
}

}  // namespace brdfbake
