#include "bake/bake.h"

#include <chrono>
#include <map>

#include "common/brdf_host.h"
#include "common/errors.h"
#include "common/format.h"
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

std::string preparePrograms(const std::string& dir, const std::string& device) {
  if (dir.empty()) throw Error(kExitUsage, "--prepare: empty directory name");
  BakeRequest defaults = defaultRequest();
  defaults.device = device;
  BakeRequest pairs = defaults;  // four pairs: the shared program
  pairs.ndfs = {NDF_GGX, NDF_BECKMANN};
  pairs.gafs = {GAF_SMITH, GAF_SMITH_CORRELATED};
  std::string out;
  for (const BakeRequest* req : {&defaults, &pairs}) {
    Plan plan = makePlan(*req);
    BakeContext ctx(plan.device);
    ctx.runner().setProgramCache(KernelRunner::ProgramCacheUse::Refresh, dir);
    buildKernels(ctx, plan);
    for (const KernelRunner::ProgramEvent& e : ctx.runner().programEvents())
      out += e.program + ": " + fmtG(e.seconds, 3) + " s, " + e.how + "\n";
  }
  return out;
}

namespace {
double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The report's words for how the programs were made ready: "1 loaded from its binary", ...
std::string buildHow(const std::vector<KernelRunner::ProgramEvent>& events) {
  int loaded = 0, stored = 0, lost = 0;
  for (const auto& e : events) (e.loaded ? loaded : e.stored ? stored : lost)++;
  auto programs = [](int n) { return n == 1 ? std::string("1 program") : std::to_string(n) + " programs"; };
  std::string s;
  if (loaded)
    s += loaded == 1 ? "1 program loaded from its kept binary"
                     : std::to_string(loaded) + " programs loaded from their kept binaries";
  if (stored)
    s += (s.empty() ? "" : ", ") + programs(stored) + " compiled (" +
         (stored == 1 ? "its binary is" : "their binaries are") + " kept: the next bake loads " +
         (stored == 1 ? "it" : "them") + ")";
  if (lost)
    s += (s.empty() ? "" : ", ") + programs(lost) + " compiled (" +
         (lost == 1 ? "its binary was" : "their binaries were") +
         " not kept: --timings says why; the next bake compiles again)";
  return s;
}
}  // namespace

std::vector<TableReport> runPlan(const Plan& plan) {
  // Nothing is created before every table is computed and checked: a bad -o, a missing device
  // or an interrupt leaves the file system as it was. A set lands whole, so it has at most
  // kMaxFilesPerSet files: each table writes one or more, refused before any is computed.
  if (plan.jobs.size() > static_cast<size_t>(kMaxFilesPerSet))
    throw Error(kExitUsage, "too many files for one set: " + std::to_string(plan.jobs.size()) +
                                " tables write at least as many files, and at most " + std::to_string(kMaxFilesPerSet) +
                                " land together; " +
                                (plan.shardHint.empty() ? "ask for fewer tables per run" : plan.shardHint));
  checkOutputDir(plan.outDir);
  BakeContext ctx(plan.device, plan.observer);
  ctx.reuseLaunches();
  BakeObserver* obs = plan.observer.get();
  preflight(ctx, plan, plan.outDir);
  const bool device = usesDevice(plan);
  if (device) ctx.runner();  // a missing device is reported before the interrupt guard
  guardInterrupts("abandoned " + std::to_string(plan.jobs.size()) + " table(s) for " + plan.outDir + "/");
  const auto built0 = std::chrono::steady_clock::now();
  if (device) buildKernels(ctx, plan);
  const double buildSeconds = since(built0);
  std::vector<KernelRunner::ProgramEvent> events;
  if (device) events = ctx.runner().programEvents();
  if (obs)
    for (const auto& e : events) obs->stage("program", e.program + ": " + e.how, e.seconds);
  FileSet set;
  set.extraStrings = plan.extraStrings;
  for (const Job& j : plan.jobs) {
    const auto t0 = std::chrono::steady_clock::now();
    ctx.working(j.path);
    j.family->addFiles(ctx, j, set);
    if (obs) obs->stage("table", j.path, since(t0));
  }
  const auto w0 = std::chrono::steady_clock::now();
  commitOutputs(plan.outDir, set.files, !plan.noWait);
  if (obs) obs->stage("write", std::to_string(set.files.size()) + " file(s) into " + plan.outDir + "/", since(w0));
  for (auto& after : set.afterCommit) after();
  const std::string how = buildHow(events);
  for (TableReport& r : set.reports) {
    r.buildSeconds = device ? buildSeconds : 0;
    r.buildHow = device ? how : "";
  }
  return set.reports;
}

}  // namespace brdfbake
