// The measured-material family (--brdf merl:FILE): a MERL file's directional albedo over mu as
// --table albedo and splitsum (its second factor), and its average as albedo-avg (1 x 1), on the
// host (materials/merl_albedo.h). Files <table>_merl-<name>.exr.
#include <algorithm>
#include <chrono>

#include "tables/measured/merl_bake.h"
#include "common/errors.h"
#include "formats/merl.h"
#include "materials/merl_albedo.h"
#include "tables/family.h"
#include "common/format.h"
#include "tables/ladder.h"
#include "tables/registry.h"

namespace brdfbake {

namespace {

// What merlTable computes for a kind: E(mu) for albedo and splitsum (the same values, two uses), E_avg
// for albedo-avg.
MerlTableSpec merlSpec(TableKind kind) {
  MerlTableSpec s;
  s.table = tableName(kind);
  s.average = kind == TableKind::AlbedoAvg;
  s.channels = kind == TableKind::Albedo
                   ? "R,G,B=E (the measured material's directional albedo per colour channel)"
                   : "R,G,B=E (the split sum's second factor of a measured material: its directional albedo, Fresnel "
                     "and colour included; shade with prefiltered radiance times E(mu))";
  return s;
}

class Measured final : public TableFamily {
 public:
  std::string name() const override { return "measured"; }
  std::vector<TableKind> kinds() const override {
    return {TableKind::Albedo, TableKind::AlbedoAvg, TableKind::SplitSum};
  }

  bool takes(const BakeRequest& req) const override { return !req.merl.empty(); }

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
      TableJob job = TableJob::of(kind).texels(n, 1).onNodeGrid(req.nodeGrid).storingHalf(storesHalf(req));
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
      t.image = dynamic_cast<const ComputedTable&>(*it->second).image;
      t.image.strings["brdf.table"] = tableName(job.kind);
      if (job.kind != TableKind::AlbedoAvg) t.image.strings["brdf.channels"] = merlSpec(job.kind).channels;
    } else {
      // progress through the request's observer: a terminal's line, or nothing in a log
      BakeObserver* obs = ctx.observer();
      const std::string what = "merl:" + merlMaterialName(job.merl) + " " + tableName(job.kind);
      ProgressFn progress;
      if (obs)
        progress = [obs, what](double done, double total, double seconds) {
          obs->progress(what, "texels", done, total, seconds);
        };
      t.image = merlTable(data(ctx, job.merl), merlMaterialName(job.merl), merlSpec(job.kind), job.width, job.nodeGrid,
                          job.half, progress);
      ctx.cache[key] = std::make_shared<const ComputedTable>(t.image);
    }
    t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return t;
  }

  // albedo (and splitsum, the same values) over n texel centres in mu: the h-space rules (k, k - 1)
  // for k in kMerlLadder (levels L take its L-th rule) and the bake's adaptive climb, against the
  // (30, 29) rule: a MERL file's interpolant has no closed form, and the rules converge to it
  // (docs/merl.md, brdfbake-bench --merl). albedo-avg: the direct rule's n nodes per bin and piece.
  Ladder convergence(BakeContext& ctx, const BakeRequest& req, TableKind kind,
                     const LadderBudgets& budgets) const override {
    const MerlData& d = data(ctx, req.merl);
    const RusinkiewiczFn f = merlFunction(d);
    Ladder L;
    if (kind == TableKind::AlbedoAvg) {
      L.table = "albedo-avg of merl:" + merlMaterialName(req.merl) + " (R, G, B)";
      double t0 = ladder::now();
      std::array<double, 3> truth = directAlbedoAvgRule(f, 10, 2);
      const double refSeconds = ladder::now() - t0;
      std::vector<double> ref(truth.begin(), truth.end()), prev;
      for (int level : budgets.levels) {
        const int nodes = kMerlAvgLadder[std::min<size_t>(static_cast<size_t>(level), kMerlAvgLadder.size() - 1)];
        double secs = ladder::now();
        std::array<double, 3> v = directAlbedoAvgRule(f, nodes, 2);
        secs = ladder::now() - secs;
        std::vector<double> vals(v.begin(), v.end());
        const std::vector<double> e = ladder::changeFrom(prev, vals);
        prev = vals;
        L.rungs.push_back(
            ladder::rung("direct rule (host, double)", std::to_string(nodes) + " nodes per piece", secs, vals, e, ref));
      }
      L.note = "The reference: the same coordinates' rule at 10 nodes per bin and piece, above the ladder (" +
               fmt3(refSeconds) + " s)\n";
      return L;
    }
    const int n = ladder::pointsPerAxis(req, 6, 1, 64, "a measured albedo");
    L.table = tableName(kind) + " of merl:" + merlMaterialName(req.merl) + " (R, G, B), " + std::to_string(n) +
              " texel centres in mu";
    std::vector<double> ref(static_cast<size_t>(n) * 3);
    double t0 = ladder::now();
    ladder::onTwoThreads(static_cast<size_t>(n), [&](size_t i) {
      std::array<double, 3> e = hSpaceIntegral(f, ladder::centre(static_cast<int>(i), n), HSpaceRule{30, 29});
      for (int c = 0; c < 3; ++c) ref[3 * i + c] = e[c];
    });
    const double refSeconds = ladder::now() - t0;
    std::vector<double> prev;
    for (int level : budgets.levels) {
      const int k = kMerlLadder[std::min<size_t>(static_cast<size_t>(level) * 2, kMerlLadder.size() - 1)];
      std::vector<double> v(ref.size());
      double secs = ladder::now();
      ladder::onTwoThreads(static_cast<size_t>(n), [&](size_t i) {
        std::array<double, 3> x = hSpaceIntegral(f, ladder::centre(static_cast<int>(i), n), HSpaceRule{k, k - 1});
        for (int c = 0; c < 3; ++c) v[3 * i + c] = x[c];
      });
      secs = ladder::now() - secs;
      const std::vector<double> e = ladder::changeFrom(prev, v);
      prev = v;
      L.rungs.push_back(ladder::rung("h-space rule (host, double)",
                                     "(" + std::to_string(k) + ", " + std::to_string(k - 1) + ")", secs, v, e, ref));
    }
    {
      std::vector<double> v(ref.size()), e(ref.size());
      double secs = ladder::now();
      ladder::onTwoThreads(static_cast<size_t>(n), [&](size_t i) {
        AlbedoEstimate a = hSpaceAlbedo(f, ladder::centre(static_cast<int>(i), n));
        for (int c = 0; c < 3; ++c) v[3 * i + c] = a.e[c], e[3 * i + c] = a.err[c];
      });
      L.rungs.push_back(ladder::rung("the bake's climb (host, double)", "adaptive", ladder::now() - secs, v, e, ref));
    }
    L.note = "The reference: the (30, 29) rule, above the ladder (" + fmt3(refSeconds) +
             " s); a fixed rule's estimate is "
             "its change from the previous rung\n";
    return L;
  }

  std::string key(const Job& job) const override { return tableJobKey(job.get<TableJob>()); }
  JobSummary summary(const Job& job) const override { return tableJobSummary(job.get<TableJob>()); }

 private:
  // A table computed once per bake (splitsum's values are albedo's), and a MERL file read once.
  struct ComputedTable : FamilyData {
    explicit ComputedTable(TableImage i) : image(std::move(i)) {}
    TableImage image;
  };
  struct MerlFile : FamilyData {
    explicit MerlFile(MerlData d) : data(std::move(d)) {}
    MerlData data;
  };
  static const MerlData& data(BakeContext& ctx, const std::string& path) {
    std::shared_ptr<const FamilyData>& slot = ctx.cache["merl:" + path];
    if (!slot) slot = std::make_shared<const MerlFile>(readMerl(path));
    return dynamic_cast<const MerlFile&>(*slot).data;
  }
};

}  // namespace

const TableFamily& measuredFamily() {
  static const Measured family;
  return family;
}

}  // namespace brdfbake
