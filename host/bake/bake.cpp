#include "bake/bake.h"

#include <chrono>
#include <map>

#include "formats/output_set.h"
#include "tables/registry.h"

namespace brdfbake {

void preflight(BakeContext& ctx, const Plan& plan, const std::string& outDir) {
  std::map<const TableFamily*, std::vector<const Job*>> byFamily;
  for (const Job& j : plan.jobs) byFamily[j.family].push_back(&j);
  for (const TableFamily* f : families())
    if (byFamily.count(f)) f->preflight(ctx, outDir, byFamily[f]);
}

bool usesDevice(const Plan& plan) {
  for (const Job& j : plan.jobs)
    if (j.family->usesDevice(j)) return true;
  return false;
}

void buildKernels(BakeContext& ctx, const Plan& plan) {
  std::vector<KernelNeed> needs;
  for (const Job& j : plan.jobs)
    for (const KernelNeed& k : j.family->kernels(j)) needs.push_back(k);
  if (!needs.empty()) ctx.runner().prepareAll(needs);  // on parallel contexts (cl/runner.h)
}

std::vector<TableReport> runPlan(const Plan& plan) {
  // Nothing is created before every table is computed and checked: a bad -o, a missing device
  // or an interrupt leaves the file system as it was.
  checkOutputDir(plan.outDir);
  BakeContext ctx(plan.device);
  preflight(ctx, plan, plan.outDir);
  const bool device = usesDevice(plan);
  if (device) ctx.runner();  // a missing device is reported before the interrupt guard
  guardInterrupts("abandoned " + std::to_string(plan.jobs.size()) + " table(s) for " + plan.outDir + "/");
  const auto built0 = std::chrono::steady_clock::now();
  if (device) buildKernels(ctx, plan);
  const double buildSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - built0).count();
  FileSet set;
  set.extraStrings = plan.extraStrings;
  for (const Job& j : plan.jobs) j.family->addFiles(ctx, j, set);
  commitOutputs(plan.outDir, set.files, !plan.noWait);
  for (auto& after : set.afterCommit) after();
  for (TableReport& r : set.reports) r.buildSeconds = device ? buildSeconds : 0;
  return set.reports;
}

}  // namespace brdfbake
