#include "plan/plan.h"

#include <algorithm>

#include "common/errors.h"

namespace brdfbake {

std::string fileName(const TableJob& job) {
  const std::string& t = tableName(job.kind);
  if (job.kind == TableKind::Kp) return t + "_" + ndfNames()[job.ndf] + ".exr";
  return t + "_" + ndfNames()[job.ndf] + "_" + gafNames()[job.gaf] + ".exr";
}

Plan makePlan(const BakeRequest& req) {
  Plan plan;
  plan.outDir = req.outDir;
  plan.device = req.device;
  const int gafNone = 0;
  for (int ndf : req.ndfs) {
    for (TableKind kind : req.tables) {
      int n = req.size ? *req.size : defaultSize(kind);
      if (req.nodeGrid && n < 2)
        throw Error(kExitUsage, "--size: the node grid needs at least 2 samples per axis");
      bool twoD = kind == TableKind::SplitSum || kind == TableKind::Albedo;
      // k_p involves the NDF alone: one table per NDF, whatever GAFs were asked for
      std::vector<int> gafs = kind == TableKind::Kp ? std::vector<int>{gafNone} : req.gafs;
      for (int gaf : gafs) {
        if (twoD && req.nodeGrid && gaf == gafNone)
          throw Error(kExitUsage, "--grid node: gaf 'none' (G = 1) has infinite albedo at mu = 0, the grid's first "
                                  "column; use --grid texel-center for " + tableName(kind));
        TableJob job{kind, ndf, gaf, n, twoD ? n : 1, req.nodeGrid, req.half, ""};
        job.path = req.outDir + "/" + fileName(job);
        plan.jobs.push_back(job);
      }
    }
  }
  return plan;
}

}  // namespace brdfbake
