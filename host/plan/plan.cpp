#include "plan/plan.h"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "bake/ashikhmin_textures.h"
#include "bake/merl_bake.h"
#include "common/brdf_host.h"
#include "common/errors.h"

namespace brdfbake {

std::string fileName(const TableJob& job) {
  const std::string& t = tableName(job.kind);
  if (job.kind == TableKind::AshikhminShirley) return ashikhminFileName(job.texture);
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

std::string fileName(const VolumeJob& job) {
  const Brdf3dSpec& s = job.spec;
  std::string name = "brdf3d_" + ndfNames()[s.ndf] + "_" + gafNames()[s.gaf];
  if (!s.fresnel.isOne()) name += "_" + fresnelNames()[s.fresnel.model];
  if (s.diffuse >= 0) name += "_" + diffuseNames()[s.diffuse];
  if (job.merl) return name + ".binary";
  return name + (s.param == Brdf3dParam::Angles ? "_angles" : "_rusinkiewicz") + ".exr";
}

std::pair<int, int> atlasGrid(int depth) {
  for (int rows = static_cast<int>(std::sqrt(static_cast<double>(depth))); rows >= 1; --rows) {
    if (depth % rows != 0) continue;
    int cols = depth / rows;
    if (cols <= 4 * rows) return {cols, rows};
    break;
  }
  int cols = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(depth))));
  return {cols, (depth + cols - 1) / cols};
}

namespace {
// The brdf3d jobs of a request: one per NDF/GAF pair.
void planVolumes(const BakeRequest& req, Plan& plan) {
  const auto& v = req.volume;
  for (int ndf : req.ndfs) {
    for (int gaf : req.gafs) {
      VolumeJob job;
      Brdf3dSpec& s = job.spec;
      s.ndf = ndf;
      s.gaf = gaf;
      s.roughness = v.roughness;
      s.fresnel = req.fresnel;
      s.diffuse = req.diffuse;
      s.rho = v.rho;
      // the diffuse model's own parameter: F0 (the Shirley forms: the specular's, else 0.04),
      // sigma (oren-nayar, --sigma, default 0.5) or the specular's roughness (burley)
      if (req.diffuse == DIFFUSE_OREN_NAYAR || req.diffuse == DIFFUSE_OREN_NAYAR_AS_PRINTED)
        s.diffuseParam = req.sigma ? *req.sigma : 0.5;
      else if (req.diffuse == DIFFUSE_BURLEY)
        s.diffuseParam = v.roughness;
      else
        s.diffuseParam = req.fresnel.f0.empty() ? DIFFUSE_DEFAULT_F0 : req.fresnel.f0[0];
      s.param = v.param;
      s.thetaHSqrt = v.thetaHSqrt;
      s.timesCos = v.timesCos;
      job.merl = v.merl;
      job.half = req.half;
      if (v.merl) {
        s.grid = Brdf3dGrid::CellStart;
        s.nx = 90;
        s.ny = 90;
        s.nz = 180;
      } else {
        s.grid = req.nodeGrid ? Brdf3dGrid::Node : Brdf3dGrid::TexelCenter;
        if (req.size && *req.size > kMaxVolumeSize)
          throw Error(kExitUsage, "--size: each axis of a brdf3d table must be an integer in 1.." +
                                      std::to_string(kMaxVolumeSize) + ", got " + std::to_string(*req.size));
        std::array<int, 3> n = v.size ? *v.size : std::array<int, 3>{{req.size ? *req.size : 32, req.size ? *req.size : 32,
                                                                      req.size ? *req.size : 32}};
        if (req.nodeGrid && std::min({n[0], n[1], n[2]}) < 2)
          throw Error(kExitUsage, "--size: the node grid needs at least 2 samples per axis");
        s.nx = n[0];
        s.ny = n[1];
        s.nz = n[2];
        std::tie(job.cols, job.rows) = v.atlas ? *v.atlas : atlasGrid(s.nz);
        if (static_cast<long>(job.cols) * job.rows < s.nz)
          throw Error(kExitUsage, "--atlas " + std::to_string(job.cols) + "x" + std::to_string(job.rows) + " holds " +
                                      std::to_string(job.cols * job.rows) + " slices, fewer than the table's " +
                                      std::to_string(s.nz));
        if (static_cast<long>(job.cols) * s.nx > 65536 || static_cast<long>(job.rows) * s.ny > 65536)
          throw Error(kExitUsage, "--atlas: the atlas would be " + std::to_string(static_cast<long>(job.cols) * s.nx) + "x" +
                                      std::to_string(static_cast<long>(job.rows) * s.ny) +
                                      " texels; at most 65536 per side (choose fewer columns or rows)");
      }
      job.path = req.outDir + "/" + fileName(job);
      plan.volumes.push_back(job);
    }
  }
}
}  // namespace

void applyFormats(const BakeRequest& req, Plan& plan) {
  const Precision p = req.precision ? *req.precision : req.half ? Precision::Float16 : Precision::Float32;
  const std::vector<FileFormat> formats = req.formats.empty() ? std::vector<FileFormat>{FileFormat::Exr} : req.formats;
  for (TableJob& j : plan.jobs) {
    j.formats = formats;
    j.precision = p;
    j.layout = req.layout;
  }
  for (VolumeJob& v : plan.volumes) {
    if (v.merl) continue;
    v.formats = formats;
    v.precision = p;
  }
}

namespace {
// --preset gltf: what glTF's reference shading samples (docs/MODELS.md "Sheen"): the GGX split-sum
// (lut_ggx: R = A, G = B), the sheen IBL term E of charlie + neubelt (Filament's cloth DFG channel,
// whose visibility is Ashikhmin's = Neubelt's), and KHR_materials_sheen's albedo-scaling table E of
// charlie + charlie-smith (its "Charlie" visibility).
Plan makePresetPlan(const BakeRequest& req) {
  Plan plan;
  plan.outDir = req.outDir;
  plan.device = req.device;
  const std::tuple<TableKind, int, int> tables[] = {{TableKind::SplitSum, NDF_GGX, GAF_SMITH_CORRELATED},
                                                    {TableKind::SplitSum, NDF_CHARLIE, GAF_NEUBELT},
                                                    {TableKind::Albedo, NDF_CHARLIE, GAF_CHARLIE_SMITH}};
  for (const auto& [kind, ndf, gaf] : tables) {
    int n = req.size ? *req.size : defaultSize(kind);
    if (req.nodeGrid)
      throw Error(kExitUsage, "--preset gltf --grid node: the sheen tables are infinite at mu = 0 (charlie-smith's "
                              "Lambda is finite at grazing; neubelt's corner mu = r = 0), the node grid's first column; "
                              "the preset bakes texel centres, which texture(lut, vec2(NdotV, roughness)) samples");
    TableJob job{kind, ndf, gaf, n, n, false, req.half, "", FresnelChoice{}, -1, -1, {FileFormat::Exr}, Precision::Float32};
    job.path = req.outDir + "/" + fileName(job);
    plan.jobs.push_back(job);
  }
  applyFormats(req, plan);
  return plan;
}

// --table dielectric, dielectric-avg: one per NDF/GAF pair, for the models the BTDF supports.
void planDielectric(const BakeRequest& req, Plan& plan) {
  bool cube = std::find(req.tables.begin(), req.tables.end(), TableKind::Dielectric) != req.tables.end();
  bool avg = std::find(req.tables.begin(), req.tables.end(), TableKind::DielectricAvg) != req.tables.end();
  if (!cube && !avg) {
    if (req.etaRange) throw Error(kExitUsage, "--eta-range: only --table dielectric and dielectric-avg take it");
    return;
  }
  const std::string t = cube ? "--table dielectric" : "--table dielectric-avg";
  for (int ndf : req.ndfs)
    if (ndf != NDF_GGX && ndf != NDF_BECKMANN)
      throw Error(kExitUsage, t + ": the rough dielectric (Walter et al. 2007) takes --ndf ggx or beckmann, not " +
                                  ndfNames()[ndf]);
  for (int gaf : req.gafs)
    if (gaf != GAF_SMITH && gaf != GAF_SMITH_CORRELATED)
      throw Error(kExitUsage, t + ": the rough dielectric takes --gaf smith or smith-correlated (Smith's G for "
                                  "reflection and transmission), not " + gafNames()[gaf]);
  if (req.fresnelGiven || req.diffuse >= 0 || !req.fresnel.eta.empty() || !req.fresnel.f0.empty())
    throw Error(kExitUsage, t + ": the Fresnel is the exact dielectric one over the eta axis (--eta-range); leave "
                                "--fresnel, --eta, --f0 and --diffuse out");
  if (req.volume.size) throw Error(kExitUsage, t + ": --size takes one N (N^3 texels; dielectric-avg N^2)");
  int n = req.size ? *req.size : 32;
  if (n > kMaxVolumeSize)
    throw Error(kExitUsage, "--size: each axis of a dielectric table must be an integer in 1.." +
                                std::to_string(kMaxVolumeSize) + ", got " + std::to_string(n));
  if (req.nodeGrid && n < 2) throw Error(kExitUsage, "--size: the node grid needs at least 2 samples per axis");
  for (int ndf : req.ndfs)
    for (int gaf : req.gafs)
      for (int a = 0; a < 2; ++a) {
        if (!(a ? avg : cube)) continue;
        DielectricJob j;
        j.ndf = ndf;
        j.gaf = gaf;
        j.avg = a == 1;
        j.nx = n;
        j.ny = n;
        j.nz = j.avg ? 1 : n;
        j.nodeGrid = req.nodeGrid;
        j.half = req.half;
        if (req.etaRange) std::tie(j.etaLo, j.etaHi) = *req.etaRange;
        if (!j.avg) std::tie(j.cols, j.rows) = atlasGrid(j.nz);
        j.path = req.outDir + "/" + (j.avg ? "dielectric-avg_" : "dielectric_") + ndfNames()[ndf] + "_" +
                 gafNames()[gaf] + ".exr";
        plan.dielectric.push_back(j);
      }
}
}  // namespace

Plan makePlan(const BakeRequest& given) {
  if (!given.preset.empty()) return makePresetPlan(given);
  if (!given.merl.empty()) return makeMerlPlan(given);
  // a layout preset's size, where the request gives none (its format and precision: parseArgs)
  BakeRequest req = given;
  if (req.layoutPreset && !req.size) req.size = layoutPreset(*req.layoutPreset).size;
  Plan plan;
  planDielectric(req, plan);
  plan.outDir = req.outDir;
  plan.device = req.device;
  const int gafNone = 0;
  if (req.fresnelGiven) {
    // where the chosen Fresnel makes no sense
    const std::string f = "--fresnel " + fresnelNames()[req.fresnel.model];
    for (TableKind kind : req.tables) {
      if (kind == TableKind::AshikhminShirley)
        throw Error(kExitUsage, f + ": --table ashikhmin-shirley holds Schlick's F split as R_s R + G (R_s enters in "
                                    "the shader); bake it without --fresnel");
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
  if (std::find(req.tables.begin(), req.tables.end(), TableKind::AshikhminShirley) != req.tables.end()) {
    // closed forms on the host (bake/ashikhmin_textures.h): no NDF, GAF or program; one file per texture
    int n = req.size ? *req.size : defaultSize(TableKind::AshikhminShirley);
    checkAshikhminRequest(n, req.half, req.nodeGrid);
    for (int t = 0; t < kAsTextures; ++t) {
      TableJob job{TableKind::AshikhminShirley, -1, -1, n, n, false, req.half, "", {}, -1, t};
      job.path = req.outDir + "/" + fileName(job);
      plan.jobs.push_back(job);
    }
  }
  if (req.diffuse >= 0) {
    const std::string d = "--diffuse " + diffuseNames()[req.diffuse];
    for (TableKind kind : req.tables) {
      if (kind == TableKind::AshikhminShirley)
        throw Error(kExitUsage, d + ": --table ashikhmin-shirley has its own diffuse texture (Tex0); bake it "
                                    "without --diffuse");
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
  if (std::find(req.tables.begin(), req.tables.end(), TableKind::Brdf3d) != req.tables.end()) planVolumes(req, plan);
  for (int ndf : req.ndfs) {
    for (TableKind kind : req.tables) {
      if (req.diffuse >= 0 && kind == TableKind::Albedo) continue;  // baked once above
      if (kind == TableKind::FresnelAvg || kind == TableKind::Brdf3d || kind == TableKind::AshikhminShirley ||
          kind == TableKind::Dielectric || kind == TableKind::DielectricAvg)
        continue;  // likewise
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
        if (twoD && req.nodeGrid && isSheenGaf(gaf))
          throw Error(kExitUsage, "--grid node: charlie + " + gafNames()[gaf] + " has infinite albedo at mu = 0 (" +
                                      (gaf == GAF_NEUBELT ? "at the corner r = 0: E(0, r) grows like 1/(r sqrt(2 pi))"
                                                          : "its fitted Lambda is finite at grazing, so G/(n.o) is not") +
                                      "), the grid's first column; use --grid texel-center for " + tableName(kind));
        TableJob job{kind, ndf, gaf, n, twoD ? n : 1, req.nodeGrid, req.half, "", req.fresnel,
                     kind == TableKind::SplitSum ? req.diffuse : -1};
        job.muSqrt = twoD && req.muSqrt.value_or(false);  // validated: cli/layout_args.cpp
        job.path = req.outDir + "/" + fileName(job);
        plan.jobs.push_back(job);
      }
    }
  }
  applyFormats(req, plan);
  return plan;
}

}  // namespace brdfbake
