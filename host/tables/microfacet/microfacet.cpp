// The microfacet family (tables/microfacet/microfacet.h): split sum, albedo, albedo-avg, k_p.
#include "tables/microfacet/microfacet.h"

#include <cstdio>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <tuple>

#include "tables/error_model.h"
#include "tables/method_text.h"
#include "common/brdf_host.h"
#include "common/errors.h"
#include "common/format.h"
#include "common/material.h"
#include "tables/family.h"
#include "tables/registry.h"
#include "tables/table2d.h"

namespace brdfbake {

namespace {

std::vector<KernelNeed> kernelsOf(const TableJob& job) {
  if (job.ndf < 0) return {};  // a diffuse model's albedo runs in any program (KernelRunner::diffuseAlbedo)
  if (job.kind == TableKind::Kp) return {{KernelNeed::Kp, job.ndf, job.gaf}};
  return {{KernelNeed::Hemisphere, job.ndf, job.gaf}};
}

bool asks(const BakeRequest& req, TableKind k) {
  return std::find(req.tables.begin(), req.tables.end(), k) != req.tables.end();
}

}  // namespace

// "-eta1.5", "-eta0.2_0.92_1.1-k3.9_2.45_2.14", "-f00.04-f820.8": the values in effect (defaults
// included), per channel, nine significant digits.
std::string fresnelNameParameters(const FresnelChoice& f) {
  const int m = f.model;
  const bool twoParams = m == FRESNEL_CONDUCTOR || m == FRESNEL_F82_TINT;
  const char* first = m == FRESNEL_SCHLICK || m == FRESNEL_F82_TINT ? "f0" : "eta";
  const char* second = m == FRESNEL_CONDUCTOR ? "k" : "f82";
  std::string xs, ys;
  for (int c = 0; c < f.channels(); ++c) {
    auto [x, y] = f.modelParams(c);
    char b[64];
    std::snprintf(b, sizeof b, "%s%.9g", c ? "_" : "", x);
    xs += b;
    std::snprintf(b, sizeof b, "%s%.9g", c ? "_" : "", y);
    ys += b;
  }
  return std::string("-") + first + xs + (twoParams ? std::string("-") + second + ys : std::string());
}

std::string microfacetFileName(const TableJob& job) {
  const std::string& t = tableName(job.kind);
  if (job.kind == TableKind::Albedo && job.diffuse >= 0) return t + "_" + diffuseNames()[job.diffuse] + ".exr";
  if (job.kind == TableKind::SplitSum && job.diffuse >= 0)
    return t + "_" + ndfNames()[job.ndf] + "_" + gafNames()[job.gaf] + "_" + diffuseNames()[job.diffuse] + ".exr";
  if (job.kind == TableKind::Kp) return t + "_" + ndfNames()[job.ndf] + ".exr";
  // a Fresnel other than the table's own default (F = 1; splitsum: Schlick's split) is named, with
  // the parameter values the table depends on (the split sum's F82 channel depends on none): two
  // bakes of other etas into one directory never replace each other
  const bool plain = job.fresnel.isOne() || (job.kind == TableKind::SplitSum && job.fresnel.model == FRESNEL_SCHLICK);
  std::string fresnel;
  if (!plain) {
    fresnel = "_" + fresnelNames()[job.fresnel.model];
    if (job.kind != TableKind::SplitSum) fresnel += fresnelNameParameters(job.fresnel);
  }
  // an engine's layout is its own file: two presets in one directory never replace each other
  return t + "_" + ndfNames()[job.ndf] + "_" + gafNames()[job.gaf] + fresnel +
         (job.layoutName.empty() ? "" : "_" + job.layoutName) + ".exr";
}

TableImage computeTable(KernelRunner& runner, const TableJob& job, double* seconds, std::vector<double>* texelBounds) {
  for (const KernelNeed& k : kernelsOf(job)) runner.prepare(k);
  auto t0 = std::chrono::steady_clock::now();
  KernelTable kt;
  TableImage img;
  std::string fresnel = "one", channels, axes = "r";
  const FresnelChoice& fc = job.fresnel;
  // one run per colour channel of a Fresnel model's parameters; every run's bound counts
  auto weight = [&](int c) {
    auto [x, y] = fc.kernelParams(c);
    return fresnelWeight(fc.model, x, y);
  };
  // each texel's claim (before storage), the largest over the runs that fill the table
  std::vector<double> claim;
  std::string perChannel = fc.channels() == 3 ? "R,G,B" : "R=G=B";
  switch (job.kind) {
    case TableKind::SplitSum:
      kt = runner.hemisphere(job.ndf, job.gaf, job.width, job.height, job.nodeGrid, {}, job.muSqrt);
      addClaims(claim, kt, Arith::Hemisphere, job.ndf, job.gaf);
      img.channels = {"R", "G", "B"};
      axes = "mu,r";
      if (fc.model == FRESNEL_F82_TINT) {
        // C = int f_{F=1} o.h (1 - o.h)^6 (n.i) dw_i: the F82-tint albedo is F0 A + B - b C
        KernelTable c = runner.hemisphere(job.ndf, job.gaf, job.width, job.height, job.nodeGrid,
                                          HemiWeight{HEMI_F82C, 0, 0, 0}, job.muSqrt);
        addClaims(claim, c, Arith::HemiWeighted, job.ndf, job.gaf);
        img.planes = {kt.planes[0], kt.planes[1], c.planes[1]};
        fresnel = "f82-tint";
        channels = "R=A,G=B,B=C (F82-tint albedo = F0 A + B - b C, b = F_schlick(1/7)(1-tint)/((1/7)(6/7)^6))";
      } else if (isSheenNdf(job.ndf)) {
        // sheen has no Fresnel to split (F = 1): the split sum's second factor is the albedo itself
        img.planes = {kt.planes[2], kt.planes[2], kt.planes[2]};
        fresnel = "one";
        channels =
            "R=G=B=E (sheen, F = 1: the split sum's second factor is the albedo; Filament's cloth DFG "
            "channel dfg.z, the glTF Sample Viewer's charlie LUT .b)";
      } else if (job.diffuse >= 0) {
        // the diffuse albedo over (mu, r) in B, as HDRP's pre-integrated FGD table keeps it
        KernelTable d = runner.diffuseAlbedo(job.diffuse, job.width, job.height, 0.0f, 1.0f, job.nodeGrid);
        addClaims(claim, d, Arith::Diffuse, job.ndf, job.gaf, job.diffuse);
        img.planes = {kt.planes[0], kt.planes[1], d.planes[0]};
        fresnel = "schlick";
        channels = "R=A,G=B,B=E_d (" + diffuseNames()[job.diffuse] + " diffuse albedo at roughness r)";
      } else {
        img.planes = {kt.planes[0], kt.planes[1], kt.planes[2]};
        fresnel = "schlick";
        channels = "R=A,G=B,B=A+B";
      }
      break;
    case TableKind::Albedo:
      axes = "mu,r";
      if (job.diffuse >= 0) {
        DiffuseAxis ax = diffuseAxis(job.diffuse);
        kt = runner.diffuseAlbedo(job.diffuse, job.width, job.height, static_cast<float>(ax.lo),
                                  static_cast<float>(ax.hi), job.nodeGrid);
        addClaims(claim, kt, Arith::Diffuse, job.ndf, job.gaf, job.diffuse);
        img.planes = {kt.planes[0]};
        channels = "R=G=B=E_d (" + diffuseNames()[job.diffuse] + " diffuse albedo, rho = 1)";
        axes = "mu," + ax.name;
        break;
      }
      if (fc.isOne()) {
        kt = runner.hemisphere(job.ndf, job.gaf, job.width, job.height, job.nodeGrid, {}, job.muSqrt);
        addClaims(claim, kt, Arith::Hemisphere, job.ndf, job.gaf);
        img.planes = {kt.planes[2]};
        channels = "R=G=B=E";
        break;
      }
      for (int c = 0; c < fc.channels(); ++c) {
        KernelTable t = runner.hemisphere(job.ndf, job.gaf, job.width, job.height, job.nodeGrid, weight(c), job.muSqrt);
        img.planes.push_back(t.planes[1]);
        addClaims(claim, t, weightCancels(fc.model) ? Arith::HemiWeightedCancel : Arith::HemiWeighted, job.ndf,
                  job.gaf);
        if (c == 0) kt = t;
      }
      fresnel = fc.describe();
      channels = perChannel + "=E_F (the albedo with Fresnel " + fresnelNames()[fc.model] + ")";
      break;
    case TableKind::AlbedoAvg:
      if (fc.isOne()) {
        kt = runner.albedoAvg(job.ndf, job.gaf, job.width, job.nodeGrid);
        addClaims(claim, kt, Arith::HemiAvg, job.ndf, job.gaf);
        img.planes = {kt.planes[0]};
        channels = "R=G=B=E_avg";
        break;
      }
      for (int c = 0; c < fc.channels(); ++c) {
        KernelTable t = runner.albedoAvg(job.ndf, job.gaf, job.width, job.nodeGrid, weight(c));
        img.planes.push_back(t.planes[0]);
        addClaims(claim, t, Arith::HemiAvgFresnel, job.ndf, job.gaf);
        if (c == 0) kt = t;
      }
      fresnel = fc.describe();
      channels = perChannel + "=E_F,avg (2 int E_F(mu) mu dmu with Fresnel " + fresnelNames()[fc.model] + ")";
      break;
    case TableKind::Kp:
      kt = runner.kp(job.ndf, job.width, job.nodeGrid);
      addClaims(claim, kt, Arith::Kp, job.ndf, job.gaf);
      img.planes = {kt.planes[0]};
      channels = "R=G=B=k_p";
      break;
    default:
      throw Error(kExitSoftware, "internal: " + tableName(job.kind) + " is not a microfacet table");
  }
  *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  img.strings["brdf.channels"] = channels;
  img.strings["brdf.fresnel"] = job.kind == TableKind::SplitSum || fc.isOne() ? fresnel : fresnelNames()[fc.model];
  if ((job.kind == TableKind::Albedo || job.kind == TableKind::AlbedoAvg) && !fc.isOne()) {
    for (const auto& [name, value] : fc.parameters()) img.strings["brdf.fresnel." + name] = value;
    // F_avg = 2 int F mu dmu, which Kulla-Conty's Fresnel term needs (host, double)
    std::string avg;
    for (int c = 0; c < fc.channels(); ++c) avg += (c ? "," : "") + fmtG9(fresnelAverage(fc, c));
    img.strings["brdf.fresnel.avg"] = avg;
  }
  if (job.kind == TableKind::Albedo && job.diffuse >= 0) {
    DiffuseAxis ax = diffuseAxis(job.diffuse);
    img.v2f["brdf." + ax.name + ".range"] = {static_cast<float>(ax.lo), static_cast<float>(ax.hi)};
    img.strings["brdf.method"] = diffuseMethod();
  } else {
    img.strings["brdf.method"] = methodText(job.kind);
    img.v2f["brdf.r.range"] = {0.0f, 1.0f};
  }
  return finishTable2d(&runner, job, Table2d{std::move(img), std::move(claim), axes}, texelBounds);
}

namespace {

class Microfacet final : public TableFamily {
 public:
  std::string name() const override { return "microfacet"; }
  std::vector<KindInfo> describe() const override {
    KindInfo splitsum{TableKind::SplitSum, "splitsum"};
    splitsum.defaultSize = 128;
    splitsum.energy = "A+B", splitsum.energyChannel = "B";
    splitsum.shader = ShaderLookup::SplitSum;
    splitsum.inScenes = splitsum.furnace = splitsum.muRAxes = splitsum.layouts = splitsum.inDefaultSet = true;
    splitsum.sceneUses = kUseIbl | kUseSheenIbl;
    KindInfo albedo{TableKind::Albedo, "albedo"};
    albedo.energy = "E", albedo.energyChannel = "R";
    albedo.shaderValue = "E";
    albedo.inScenes = albedo.furnace = albedo.muRAxes = albedo.inDefaultSet = albedo.albedo = true;
    albedo.sceneUses = kUseIblFresnel | kUseMultiscatter | kUseAlbedoScaling | kUseSheen;
    KindInfo avg{TableKind::AlbedoAvg, "albedo-avg"};
    avg.energy = "E_avg", avg.energyChannel = "R";
    avg.shaderValue = "Eavg";
    avg.inScenes = avg.furnace = avg.inDefaultSet = avg.albedo = avg.average = true;
    avg.sceneUses = kUseMultiscatter | kUseAlbedoScaling;
    KindInfo kp{TableKind::Kp, "kp"};
    kp.shaderValue = "Kp";
    kp.inScenes = kp.inDefaultSet = true;
    kp.sceneUses = kUseNormalisation;
    return {splitsum, albedo, avg, kp};
  }

  std::vector<Job> plan(const BakeRequest& req) const override {
    if (!req.merl.empty()) return {};
    if (!req.preset.empty()) return presetPlan(req);
    std::vector<Job> jobs;
    const int gafNone = 0;
    if (req.fresnel) {
      // where the chosen Fresnel makes no sense
      const std::string f = "--fresnel " + fresnelNames()[req.fresnel->model];
      for (TableKind kind : req.tables) {
        if (kind == TableKind::Kp)
          throw Error(kExitUsage,
                      f + ": --table kp is the NDF's normalisation, which has no Fresnel; bake it without --fresnel");
        if (kind == TableKind::SplitSum && req.fresnel->model != FRESNEL_SCHLICK &&
            req.fresnel->model != FRESNEL_F82_TINT)
          throw Error(kExitUsage, f + ": --table splitsum is Schlick's split (F0 A + B); it takes --fresnel schlick or "
                                      "f82-tint (a third channel); bake --table albedo for this model");
      }
    }
    if (req.diffuse >= 0) {
      const std::string d = "--diffuse " + diffuseNames()[req.diffuse];
      for (TableKind kind : req.tables) {
        if (kind == TableKind::AlbedoAvg || kind == TableKind::Kp)
          throw Error(kExitUsage, d + ": --table " + tableName(kind) +
                                      " has no diffuse form; a diffuse model bakes "
                                      "--table albedo (its albedo) or splitsum (burley in channel B)");
        if (kind == TableKind::SplitSum && req.diffuse != DIFFUSE_BURLEY)
          throw Error(kExitUsage, d + ": --table splitsum takes --diffuse burley only (its parameter is the table's "
                                      "roughness r); bake --table albedo for this model");
        if (kind == TableKind::Albedo && req.fresnel)
          throw Error(kExitUsage, d + ": --table albedo bakes the diffuse model's albedo, --fresnel the specular's; "
                                      "bake them in two runs (or check the whole material with brdfbake energy)");
      }
      if (asks(req, TableKind::Albedo)) {
        int n = req.size ? *req.size : defaultSize(TableKind::Albedo);
        if (req.nodeGrid && n < 2) throw Error(kExitUsage, "--size: the node grid needs at least 2 samples per axis");
        TableJob job =
            TableJob::of(TableKind::Albedo).texels(n, n).onNodeGrid(req.nodeGrid).storingHalf(storesHalf(req));
        job.diffuse = req.diffuse;
        jobs.push_back(add(req, job));
      }
    }
    for (int ndf : req.ndfs) {
      for (TableKind kind : req.tables) {
        if (req.diffuse >= 0 && kind == TableKind::Albedo) continue;  // baked once above
        if (!mine(kind)) continue;                                    // another family's
        int n = req.size ? *req.size : defaultSize(kind);
        if (req.nodeGrid && n < 2) throw Error(kExitUsage, "--size: the node grid needs at least 2 samples per axis");
        bool twoD = kind == TableKind::SplitSum || kind == TableKind::Albedo;
        // k_p involves the NDF alone: one table per NDF, whatever GAFs were asked for
        std::vector<int> gafs = kind == TableKind::Kp ? std::vector<int>{gafNone} : req.gafs;
        for (int gaf : gafs) {
          if (twoD && req.nodeGrid && gaf == gafNone)
            throw Error(kExitUsage,
                        "--grid node: gaf 'none' (G = 1) has infinite albedo at mu = 0, the grid's first "
                        "column; use --grid texel-center for " +
                            tableName(kind));
          if (twoD && req.nodeGrid && isSheenGaf(gaf))
            throw Error(kExitUsage,
                        "--grid node: charlie + " + gafNames()[gaf] + " has infinite albedo at mu = 0 (" +
                            (gaf == GAF_NEUBELT ? "at the corner r = 0: E(0, r) grows like 1/(r sqrt(2 pi))"
                                                : "its fitted Lambda is finite at grazing, so G/(n.o) is not") +
                            "), the grid's first column; use --grid texel-center for " + tableName(kind));
          TableJob job = TableJob::of(kind)
                             .forPair(ndf, gaf)
                             .texels(n, twoD ? n : 1)
                             .onNodeGrid(req.nodeGrid)
                             .storingHalf(storesHalf(req));
          job.fresnel = fresnelOf(req);
          job.diffuse = kind == TableKind::SplitSum ? req.diffuse : -1;
          job.muSqrt = twoD && req.muSqrt.value_or(false);  // validated: cli/layout_args.cpp
          jobs.push_back(add(req, job));
        }
      }
    }
    return jobs;
  }

  std::vector<KernelNeed> kernels(const Job& job) const override { return kernelsOf(job.get<TableJob>()); }
  bool usesDevice(const Job&) const override { return true; }

  BakedTable compute(BakeContext& ctx, const Job& job) const override {
    BakedTable t;
    t.image = computeTable(ctx.runner(), job.get<TableJob>(), &t.seconds, &t.texelBounds);
    return t;
  }

  Ladder convergence(BakeContext& ctx, const BakeRequest& req, TableKind kind,
                     const LadderBudgets& budgets) const override {
    return microfacetLadder(ctx, req, kind, budgets);
  }

  void stress(BakeContext& ctx, std::vector<StressPoint>& out) const override { microfacetStress(ctx.runner(), out); }

  std::string key(const Job& job) const override { return tableJobKey(job.get<TableJob>()); }

  JobSummary summary(const Job& job) const override {
    const TableJob j = job.get<TableJob>();
    JobSummary s = tableJobSummary(j);
    std::string m = j.ndf >= 0 ? ndfNames()[j.ndf] + (j.kind == TableKind::Kp ? "" : " + " + gafNames()[j.gaf]) : "";
    if (j.diffuse >= 0) m += (m.empty() ? "" : ", ") + diffuseNames()[j.diffuse];
    if (j.kind == TableKind::SplitSum)
      m += j.fresnel.model == FRESNEL_F82_TINT ? ", F82-tint split (F0 A + B - b C: no F0 or tint in the table)"
                                               : ", Schlick split (F0 A + B: no F0 in the table)";
    else if (!j.fresnel.isOne() && j.kind != TableKind::Kp)
      m += ", " + j.fresnel.describe();
    s.models = m;
    // Estimated seconds (PoCL, 2 cores; measured on ggx and beckmann tables of 64^2)
    double perTexel = j.ndf == NDF_GGX ? 4e-6 : 1.5e-5;
    if (j.kind == TableKind::AlbedoAvg)
      s.cost = s.texels * 31 * perTexel * 0.5;
    else if (j.kind == TableKind::Kp)
      s.cost = s.texels * 1e-6;
    else
      s.cost = s.texels * perTexel * (j.fresnel.channels() == 3 ? 3 : 1);
    return s;
  }

 private:
  bool mine(TableKind k) const {
    const std::vector<TableKind> all = kinds();
    return std::find(all.begin(), all.end(), k) != all.end();
  }

  Job add(const BakeRequest& req, TableJob job) const {
    applyFormats(req, job);
    job.path = req.outDir + "/" + microfacetFileName(job);
    return makeJob(this, job.kind, job);
  }

  // --preset gltf: what glTF's reference shading samples (docs/MODELS.md "Sheen"): the GGX split-sum
  // (lut_ggx: R = A, G = B), the sheen IBL term E of charlie + neubelt (Filament's cloth DFG channel,
  // whose visibility is Ashikhmin's = Neubelt's), and KHR_materials_sheen's albedo-scaling table E of
  // charlie + charlie-smith (its "Charlie" visibility).
  std::vector<Job> presetPlan(const BakeRequest& req) const {
    std::vector<Job> jobs;
    const std::tuple<TableKind, int, int> tables[] = {{TableKind::SplitSum, NDF_GGX, GAF_SMITH_CORRELATED},
                                                      {TableKind::SplitSum, NDF_CHARLIE, GAF_NEUBELT},
                                                      {TableKind::Albedo, NDF_CHARLIE, GAF_CHARLIE_SMITH}};
    for (const auto& [kind, ndf, gaf] : tables) {
      int n = req.size ? *req.size : defaultSize(kind);
      if (req.nodeGrid)
        throw Error(kExitUsage,
                    "--preset gltf --grid node: the sheen tables are infinite at mu = 0 (charlie-smith's "
                    "Lambda is finite at grazing; neubelt's corner mu = r = 0), the node grid's first column; "
                    "the preset bakes texel centres, which texture(lut, vec2(NdotV, roughness)) samples");
      TableJob job = TableJob::of(kind).forPair(ndf, gaf).texels(n, n).storingHalf(storesHalf(req));
      jobs.push_back(add(req, job));
    }
    return jobs;
  }
};

}  // namespace

const TableFamily& microfacetFamily() {
  static const Microfacet family;
  return family;
}

}  // namespace brdfbake
