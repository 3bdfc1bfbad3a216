// The rough-dielectric family (--table dielectric, dielectric-avg; Walter et al. 2007): E_R and E_T
// of rough glass over (mu, r, eta) as an EXR atlas of eta slices, and their averages over mu over
// (r, eta). The computation lives in bake/dielectric_bake.h and bake/dielectric_avg.h.
#include <algorithm>
#include <tuple>

#include "bake/dielectric_bake.h"
#include "common/brdf_host.h"
#include "common/errors.h"
#include "common/format.h"
#include "tables/brdf3d.h"
#include "tables/family.h"

namespace brdfbake {

namespace {

// --table dielectric, dielectric-avg: one per NDF/GAF pair, for the models the BTDF supports.
std::vector<Job> planDielectric(const TableFamily* family, const BakeRequest& req) {
  std::vector<Job> jobs;
  bool cube = std::find(req.tables.begin(), req.tables.end(), TableKind::Dielectric) != req.tables.end();
  bool avg = std::find(req.tables.begin(), req.tables.end(), TableKind::DielectricAvg) != req.tables.end();
  if (!cube && !avg) {
    if (req.etaRange) throw Error(kExitUsage, "--eta-range: only --table dielectric and dielectric-avg take it");
    return jobs;
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
        jobs.push_back(makeJob(family, j.avg ? TableKind::DielectricAvg : TableKind::Dielectric, j));
      }
  return jobs;
}

class Dielectric final : public TableFamily {
 public:
  std::string name() const override { return "dielectric"; }
  std::vector<TableKind> kinds() const override { return {TableKind::Dielectric, TableKind::DielectricAvg}; }

  std::vector<Job> plan(const BakeRequest& req) const override {
    if (!req.merl.empty() || !req.preset.empty()) return {};
    return planDielectric(this, req);
  }

  std::vector<KernelNeed> kernels(const Job& job) const override {
    const DielectricJob& d = job.get<DielectricJob>();
    return {{d.avg ? KernelNeed::DielectricNodes : KernelNeed::Dielectric, d.ndf, d.gaf}};
  }

  BakedTable compute(BakeContext& ctx, const Job& job) const override {
    const DielectricJob d = job.get<DielectricJob>();
    BakedTable t;
    DielectricTable dt = computeDielectric(ctx.runner(), d, &t.seconds);
    t.image = std::move(dt.image);
    t.volume = std::move(dt.cube);
    t.depth = d.nz;
    return t;
  }

  // Computed and checked whole before anything is written (the default addFiles: compute, then these).
  void addBakedFiles(const Job& job, BakedTable& baked, FileSet& set) const override {
    const DielectricJob d = job.get<DielectricJob>();
    auto it = set.extraStrings.find(job.path);
    if (it != set.extraStrings.end())
      for (const auto& [k, v] : it->second) baked.image.strings[k] = v;
    TableReport r;
    r.path = d.path;
    r.table = d.avg ? "dielectric-avg" : "dielectric";
    r.ndf = ndfNames()[d.ndf];
    r.gaf = gafNames()[d.gaf];
    r.width = d.nx;
    r.height = d.ny;
    r.depth = d.nz;
    r.seconds = baked.seconds;
    r.errorBound = baked.image.floats["brdf.error"];
    set.reports.push_back(r);
    // dielectricOutput's writer reads the table through a pointer: `baked` lives in the set
    auto table = std::make_shared<DielectricTable>();
    table->image = baked.image;
    table->cube = baked.volume;
    OutputFile f = dielectricOutput(d, *table);
    auto write = f.write;
    if (write) f.write = [write, table](const std::string& tmp) { write(tmp); };
    else f.image = &set.keep.emplace_back(table->image);
    set.files.push_back(std::move(f));
  }

  std::string key(const Job& job) const override {
    const DielectricJob d = job.get<DielectricJob>();
    return std::string("table=") + (d.avg ? "dielectric-avg" : "dielectric") + ";ndf=" + std::to_string(d.ndf) +
           ";gaf=" + std::to_string(d.gaf) + ";size=" + std::to_string(d.nx) + "x" + std::to_string(d.ny) + "x" +
           std::to_string(d.nz) + ";eta=" + fmtG9(d.etaLo) + "," + fmtG9(d.etaHi) + ";grid=" + (d.nodeGrid ? "node" : "texel") +
           ";half=" + (d.half ? "1" : "0");
  }

  JobSummary summary(const Job& job) const override {
    const DielectricJob d = job.get<DielectricJob>();
    JobSummary s;
    s.table = d.avg ? "dielectric-avg" : "dielectric";
    s.models = ndfNames()[d.ndf] + " + " + gafNames()[d.gaf] + ", eta " + fmtG(d.etaLo) + ".." + fmtG(d.etaHi);
    s.size = std::to_string(d.nx) + "x" + std::to_string(d.ny) + (d.avg ? "" : "x" + std::to_string(d.nz));
    s.texels = static_cast<double>(d.nx) * d.ny * d.nz;
    s.cost = s.texels * (d.avg ? 0.05 : 5e-3);  // measured: 4.8 ms per texel of E; the averages ~50 ms per entry
    return s;
  }
};

}  // namespace

const TableFamily& dielectricFamily() {
  static const Dielectric family;
  return family;
}

}  // namespace brdfbake
