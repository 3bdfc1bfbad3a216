// The measured-material family (--brdf merl:FILE): a MERL file's directional albedo over mu as
// --table albedo and splitsum (its second factor), and its average as albedo-avg (1 x 1), on the
// host (materials/merl_albedo.h). Files <table>_merl-<name>.exr.
#include <algorithm>
#include <chrono>

#include "bake/merl_bake.h"
#include "common/errors.h"
#include "formats/merl.h"
#include "materials/merl_albedo.h"
#include "tables/family.h"
#include "tables/registry.h"

namespace brdfbake {

namespace {

class Measured final : public TableFamily {
 public:
  std::string name() const override { return "measured"; }
  std::vector<TableKind> kinds() const override { return {TableKind::Albedo, TableKind::AlbedoAvg, TableKind::SplitSum}; }

  std::vector<Job> plan(const BakeRequest& req) const override {
    if (req.merl.empty()) return {};
    std::vector<Job> jobs;
    for (TableKind kind : req.tables) {
      if (kind != TableKind::Albedo && kind != TableKind::AlbedoAvg && kind != TableKind::SplitSum)
        throw Error(kExitUsage, "--brdf merl:" + req.merl + ": --table " + tableName(kind) +
                                    " has no measured form; a measured material bakes albedo, albedo-avg or splitsum");
      int n = kind == TableKind::AlbedoAvg ? 1 : req.size ? *req.size : brdfbake::defaultSize(kind);
      if (req.nodeGrid && kind != TableKind::AlbedoAvg && n < 2)
        throw Error(kExitUsage, "--size: the node grid needs at least 2 samples per axis");
      TableJob job{kind, -1, -1, n, 1, req.nodeGrid, req.half, "", {}, -1};
      job.path = req.outDir + "/" + tableName(kind) + "_merl-" + merlMaterialName(req.merl) + ".exr";
      job.merl = req.merl;
      applyFormats(req, job);
      jobs.push_back(makeJob(this, kind, job));
    }
    return jobs;
  }

  // The MERL file, read once (Error 66 missing or unreadable, 65 wrong size, header or values).
  void preflight(BakeContext& ctx, const std::string&, const std::vector<const Job*>& jobs) const override {
    for (const Job* j : jobs) data(ctx, j->get<TableJob>().merl);
  }

  BakedTable compute(BakeContext& ctx, const Job& j) const override {
    const TableJob job = j.get<TableJob>();
    auto t0 = std::chrono::steady_clock::now();
    // albedo and splitsum of a measured material hold the same values (its directional albedo,
    // labelled for each use): computed once when both are asked for
    const std::string key = "measured:" + job.merl + ":" + std::to_string(job.width) + (job.nodeGrid ? "n" : "t") +
                            (job.half ? "h" : "f") + (job.kind == TableKind::AlbedoAvg ? "avg" : "E");
    BakedTable t;
    auto it = ctx.cache.find(key);
    if (it != ctx.cache.end()) {
      t.image = *std::static_pointer_cast<TableImage>(it->second);
      t.image.strings["brdf.table"] = tableName(job.kind);
      t.image.strings["brdf.channels"] = merlChannels(job.kind);
    } else {
      t.image = merlTable(data(ctx, job.merl), merlMaterialName(job.merl), job.kind, job.width, job.nodeGrid, job.half);
      ctx.cache[key] = std::make_shared<TableImage>(t.image);
    }
    t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return t;
  }

  std::string key(const Job& job) const override { return tableJobKey(job.get<TableJob>()); }
  JobSummary summary(const Job& job) const override { return tableJobSummary(job.get<TableJob>()); }

 private:
  static const MerlData& data(BakeContext& ctx, const std::string& path) {
    std::shared_ptr<void>& slot = ctx.cache["merl:" + path];
    if (!slot) slot = std::make_shared<MerlData>(readMerl(path));
    return *std::static_pointer_cast<MerlData>(slot);
  }
};

}  // namespace

const TableFamily& measuredFamily() {
  static const Measured family;
  return family;
}

}  // namespace brdfbake
