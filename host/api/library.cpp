// The library's entry points (brdfbake/brdfbake.h): a request -> the plan -> each job's family
// computes it in memory; write() hands the tables back to their families for their files.
#include <algorithm>
#include <typeinfo>

#include "brdfbake/brdfbake.h"

#include <chrono>

#include "bake/bake.h"
#include "formats/output_set.h"
#include "common/format.h"
#include "formats/readers/table_reader.h"
#include "plan/plan.h"

namespace brdfbake {

// What write() needs of a table bake() made: its job (family, spec, path) and the table itself.
struct TablePlanRecord {
  Job job;
  BakedTable baked;
};

namespace {

Table toTable(const Job& job, BakedTable baked) {
  Table t;
  t.path = job.path;
  t.kind = tableName(job.kind);
  const TableImage& img = baked.image;
  t.width = img.width;
  t.height = img.height;
  t.depth = baked.depth;
  t.channels = img.channels;
  t.planes = baked.volume.empty() ? img.planes : baked.volume;
  if (!baked.volume.empty()) {
    // a 3D table's header is its atlas's; the table itself is nx x ny x nz
    t.channels = {"R", "G", "B"};
  }
  t.texelBounds = baked.texelBounds;
  for (const auto& [k, v] : img.strings) t.metadata[k] = v;
  for (const auto& [k, v] : img.floats) t.metadata[k] = fmtG9(v);
  for (const auto& [k, v] : img.v2f) t.metadata[k] = fmtG9(v.first) + "," + fmtG9(v.second);
  if (img.floats.count("brdf.error")) t.errorBound = img.floats.at("brdf.error");
  // a 2D table's files claim their format's and precision's storage rounding too (a float16 file
  // 2.45e-4 where the values' bound is 6.71e-7): errorBound is what write() will claim, the largest
  // over the request's formats, planned as write() plans them
  if (baked.volume.empty() && job.is<TableJob>()) {
    FileSet scratch;
    BakedTable copy = baked;
    job.family->addBakedFiles(job, copy, scratch);
    for (const TableReport& r : scratch.reports) t.errorBound = std::max(t.errorBound, r.errorBound);
    t.metadata["brdf.error"] = fmtG9(t.errorBound);
  }
  t.internal = std::make_shared<TablePlanRecord>(TablePlanRecord{job, std::move(baked)});
  return t;
}

}  // namespace

std::vector<Table> bake(const BakeRequest& req) {
  Plan plan = makePlan(req);
  BakeContext ctx(plan.device, plan.observer);  // the observer hears of the device, programs and tables
  ctx.reuseLaunches();
  preflight(ctx, plan, "");
  buildKernels(ctx, plan);
  if (plan.observer && ctx.hasRunner())
    for (const KernelRunner::ProgramEvent& e : ctx.runner().programEvents())
      plan.observer->stage("program", e.program + ": " + e.how, e.seconds);
  std::vector<Table> out;
  for (const Job& j : plan.jobs) {
    const auto t0 = std::chrono::steady_clock::now();
    ctx.working(j.path);
    out.push_back(toTable(j, j.family->compute(ctx, j)));
    if (plan.observer)
      plan.observer->stage("table", j.path,
                           std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return out;
}

void write(const std::vector<Table>& tables, const std::string& dir) {
  FileSet set;
  std::string outDir = dir;
  for (const Table& t : tables) {
    if (!t.internal)
      throw Error(kExitUsage, "write: " + t.path + " was not made by bake() (read tables are already files)");
    const std::shared_ptr<const TablePlanRecord>& in = t.internal;
    Job job = in->job;
    if (!dir.empty()) {
      size_t slash = job.path.find_last_of('/');
      job.path = dir + "/" + (slash == std::string::npos ? job.path : job.path.substr(slash + 1));
    } else if (outDir.empty()) {
      size_t slash = job.path.find_last_of('/');
      outDir = slash == std::string::npos ? "." : job.path.substr(0, slash);
    }
    job.family->addBakedFiles(job, set.baked.emplace_back(in->baked), set);
  }
  if (outDir.empty()) outDir = ".";
  checkOutputDir(outDir);
  commitOutputs(outDir, set.files);
}

std::vector<TableReport> bakeToDirectory(const BakeRequest& req) { return runPlan(makePlan(req)); }

Table readTable(const std::string& path) {
  TableFile f = readTableFile(path);
  BakedTable b;
  b.image = f.table;
  Job job;
  job.path = path;
  b.depth = f.depth;
  Table t = toTable(job, std::move(b));
  t.kind = f.table.strings.count("brdf.table") ? f.table.strings.at("brdf.table") : "";
  t.internal.reset();
  return t;
}

}  // namespace brdfbake
