#include "bake/merl_bake.h"

#include <chrono>

#include "bake/format_outputs.h"
#include "bake/output_set.h"
#include "common/errors.h"
#include "formats/merl.h"
#include "materials/merl_albedo.h"

namespace brdfbake {

std::string merlMaterialName(const std::string& path) {
  size_t slash = path.find_last_of('/');
  std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  const std::string ext = ".binary";
  if (name.size() > ext.size() && name.compare(name.size() - ext.size(), ext.size(), ext) == 0)
    name.resize(name.size() - ext.size());
  return name;
}

Plan makeMerlPlan(const BakeRequest& req) {
  Plan plan;
  plan.outDir = req.outDir;
  plan.device = req.device;
  plan.merl = req.merl;
  for (TableKind kind : req.tables) {
    if (kind != TableKind::Albedo && kind != TableKind::AlbedoAvg && kind != TableKind::SplitSum)
      throw Error(kExitUsage, "--brdf merl:" + req.merl + ": --table " + tableName(kind) +
                                  " has no measured form; a measured material bakes albedo, albedo-avg or splitsum");
    int n = kind == TableKind::AlbedoAvg ? 1 : req.size ? *req.size : defaultSize(kind);
    if (req.nodeGrid && kind != TableKind::AlbedoAvg && n < 2)
      throw Error(kExitUsage, "--size: the node grid needs at least 2 samples per axis");
    TableJob job{kind, -1, -1, n, 1, req.nodeGrid, req.half, "", {}, -1};
    job.path = req.outDir + "/" + tableName(kind) + "_merl-" + merlMaterialName(req.merl) + ".exr";
    plan.jobs.push_back(job);
  }
  applyFormats(req, plan);
  return plan;
}

bool isMerlPlan(const Plan& plan) { return !plan.merl.empty(); }

std::vector<TableReport> runMerlPlan(const Plan& plan) {
  checkOutputDir(plan.outDir);
  MerlData data = readMerl(plan.merl);
  guardInterrupts("abandoned " + std::to_string(plan.jobs.size()) + " table(s) for " + plan.outDir + "/");
  std::vector<TableImage> images;
  std::vector<TableReport> tables;
  images.reserve(plan.jobs.size());  // the files point into it
  for (const TableJob& job : plan.jobs) {
    auto t0 = std::chrono::steady_clock::now();
    // albedo and splitsum of a measured material hold the same values (its directional albedo,
    // labelled for each use): computed once when both are asked for
    const TableImage* same = nullptr;
    for (size_t k = 0; k < images.size(); ++k) {
      const TableJob& o = plan.jobs[k];
      bool pair = (o.kind == TableKind::Albedo && job.kind == TableKind::SplitSum) ||
                  (o.kind == TableKind::SplitSum && job.kind == TableKind::Albedo);
      if (pair && o.width == job.width && o.nodeGrid == job.nodeGrid && o.half == job.half) same = &images[k];
    }
    if (same) {
      TableImage img = *same;
      img.strings["brdf.table"] = tableName(job.kind);
      img.strings["brdf.channels"] = merlChannels(job.kind);
      images.push_back(img);
    } else {
      images.push_back(merlTable(data, merlMaterialName(plan.merl), job.kind, job.width, job.nodeGrid, job.half));
    }
    TableReport r;
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    r.table = tableName(job.kind);
    r.width = job.width;
    r.height = job.height;
    tables.push_back(r);
  }
  std::deque<TableImage> keep;
  std::vector<OutputFile> files;
  std::vector<TableReport> reports;
  for (size_t i = 0; i < plan.jobs.size(); ++i) addTableFiles(plan.jobs[i], images[i], tables[i], keep, files, reports);
  commitOutputs(plan.outDir, files);
  return reports;
}

}  // namespace brdfbake
