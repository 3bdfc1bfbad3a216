#include "plan/plan.h"

#include <algorithm>

#include "common/brdf_host.h"
#include "common/errors.h"

namespace brdfbake {

std::string fileName(const TableJob& job) {
  const std::string& t = tableName(job.kind);
  if (job.kind == TableKind::Kp) return t + "_" + ndfNames()[job.ndf] + ".exr";
  // a Fresnel other than the table's own default (F = 1; splitsum: Schlick's split) is named
  bool plain = job.fresnel.isOne() || (job.kind == TableKind::SplitSum && job.fresnel.model == FRESNEL_SCHLICK);
  return t + "_" + ndfNames()[job.ndf] + "_" + gafNames()[job.gaf] +
         (plain ? "" : "_" + fresnelNames()[job.fresnel.model]) + ".exr";
}

Plan makePlan(const BakeRequest& req) {
  Plan plan;
  plan.outDir = req.outDir;
  plan.device = req.device;
  const int gafNone = 0;
  if (req.fresnelGiven) {
    // where the chosen Fresnel makes no sense
    const std::string f = "--fresnel " + fresnelNames()[req.fresnel.model];
    for (TableKind kind : req.tables) {
      if (kind == TableKind::Kp)
        throw Error(kExitUsage, f + ": --table kp is the NDF's normalisation, which has no Fresnel; bake it without --fresnel");
      if (kind == TableKind::SplitSum && req.fresnel.model != FRESNEL_SCHLICK && req.fresnel.model != FRESNEL_F82_TINT)
        throw Error(kExitUsage, f + ": --table splitsum is Schlick's split (F0 A + B); it takes --fresnel schlick or "
                                    "f82-tint (a third channel); bake --table albedo for this model");
    }
  }
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
        TableJob job{kind, ndf, gaf, n, twoD ? n : 1, req.nodeGrid, req.half, "", req.fresnel};
        job.path = req.outDir + "/" + fileName(job);
        plan.jobs.push_back(job);
      }
    }
  }
  return plan;
}

}  // namespace brdfbake
