#include "plan/plan.h"

#include <algorithm>

#include "bake/merl_bake.h"
#include "common/brdf_host.h"
#include "common/errors.h"

namespace brdfbake {

std::string fileName(const TableJob& job) {
  const std::string& t = tableName(job.kind);
  if (job.kind == TableKind::FresnelAvg) return t + "_" + fresnelNames()[job.fresnel.model] + ".exr";
  if (job.kind == TableKind::Albedo && job.diffuse >= 0) return t + "_" + diffuseNames()[job.diffuse] + ".exr";
  if (job.kind == TableKind::SplitSum && job.diffuse >= 0)
    return t + "_" + ndfNames()[job.ndf] + "_" + gafNames()[job.gaf] + "_" + diffuseNames()[job.diffuse] + ".exr";
  if (job.kind == TableKind::Kp) return t + "_" + ndfNames()[job.ndf] + ".exr";
  // a Fresnel other than the table's own default (F = 1; splitsum: Schlick's split) is named
  bool plain = job.fresnel.isOne() || (job.kind == TableKind::SplitSum && job.fresnel.model == FRESNEL_SCHLICK);
  return t + "_" + ndfNames()[job.ndf] + "_" + gafNames()[job.gaf] +
         (plain ? "" : "_" + fresnelNames()[job.fresnel.model]) + ".exr";
}

Plan makePlan(const BakeRequest& req) {
  if (!req.merl.empty()) return makeMerlPlan(req);
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
  if (std::find(req.tables.begin(), req.tables.end(), TableKind::FresnelAvg) != req.tables.end()) {
    if (req.fresnel.model != FRESNEL_DIELECTRIC && req.fresnel.model != FRESNEL_SCHLICK_TIR)
      throw Error(kExitUsage, "--table fresnel-avg runs over eta: it takes --fresnel dielectric or schlick-tir (for "
                              "other models brdfbake energy prints F_avg, and every Fresnel table records it as "
                              "brdf.fresnel.avg)");
    int n = req.size ? *req.size : defaultSize(TableKind::FresnelAvg);
    if (n < 2) throw Error(kExitUsage, "--size must be at least 2 for fresnel-avg, got " + std::to_string(n));
    TableJob job{TableKind::FresnelAvg, -1, -1, n, 1, req.nodeGrid, req.half, "", req.fresnel, -1};
    job.path = req.outDir + "/" + fileName(job);
    plan.jobs.push_back(job);
  }
  if (req.diffuse >= 0) {
    const std::string d = "--diffuse " + diffuseNames()[req.diffuse];
    for (TableKind kind : req.tables) {
      if (kind == TableKind::AlbedoAvg || kind == TableKind::Kp)
        throw Error(kExitUsage, d + ": --table " + tableName(kind) + " has no diffuse form; a diffuse model bakes "
                                    "--table albedo (its albedo) or splitsum (burley in channel B)");
      if (kind == TableKind::SplitSum && req.diffuse != DIFFUSE_BURLEY)
        throw Error(kExitUsage, d + ": --table splitsum takes --diffuse burley only (its parameter is the table's "
                                    "roughness r); bake --table albedo for this model");
      if (kind == TableKind::Albedo && req.fresnelGiven)
        throw Error(kExitUsage, d + ": --table albedo bakes the diffuse model's albedo, --fresnel the specular's; "
                                    "bake them in two runs (or check the whole material with brdfbake energy)");
    }
    if (std::find(req.tables.begin(), req.tables.end(), TableKind::Albedo) != req.tables.end()) {
      int n = req.size ? *req.size : defaultSize(TableKind::Albedo);
      if (req.nodeGrid && n < 2) throw Error(kExitUsage, "--size: the node grid needs at least 2 samples per axis");
      TableJob job{TableKind::Albedo, -1, -1, n, n, req.nodeGrid, req.half, "", {}, req.diffuse};
      job.path = req.outDir + "/" + fileName(job);
      plan.jobs.push_back(job);
    }
  }
  for (int ndf : req.ndfs) {
    for (TableKind kind : req.tables) {
      if (req.diffuse >= 0 && kind == TableKind::Albedo) continue;  // baked once above
      if (kind == TableKind::FresnelAvg) continue;                      // likewise
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
        TableJob job{kind, ndf, gaf, n, twoD ? n : 1, req.nodeGrid, req.half, "", req.fresnel,
                     kind == TableKind::SplitSum ? req.diffuse : -1};
        job.path = req.outDir + "/" + fileName(job);
        plan.jobs.push_back(job);
      }
    }
  }
  return plan;
}

}  // namespace brdfbake
