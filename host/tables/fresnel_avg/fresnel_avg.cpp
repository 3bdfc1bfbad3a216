// The fresnel-avg family: F_avg(eta) = 2 int F(mu) mu dmu of the dielectric Fresnel or Schlick's
// with total internal reflection, over eta on both sides of an interface, in double on the host.
#include <algorithm>
#include <chrono>

#include "common/brdf_host.h"
#include "common/errors.h"
#include "tables/error_model.h"
#include "common/material.h"
#include "tables/family.h"
#include "tables/registry.h"
#include "common/format.h"
#include "reference/reference.h"
#include "tables/ladder.h"
#include "tables/table2d.h"

namespace brdfbake {

namespace {

// The eta axis: both sides of an interface, glass (1.5) and its inverse.
constexpr double kEtaLo = 0.25, kEtaHi = 4.0;

class FresnelAvg final : public TableFamily {
 public:
  std::string name() const override { return "fresnel-avg"; }
  std::vector<KindInfo> describe() const override {
    KindInfo k{TableKind::FresnelAvg, "fresnel-avg"};
    k.defaultSize = 128;
    k.shaderValue = "Favg";
    return {k};
  }

  std::vector<Job> plan(const BakeRequest& req) const override {
    if (!req.merl.empty() || !req.preset.empty()) return {};
    if (std::find(req.tables.begin(), req.tables.end(), TableKind::FresnelAvg) == req.tables.end()) return {};
    const FresnelChoice& fresnel = fresnelOf(req);
    if (fresnel.model != FRESNEL_DIELECTRIC && fresnel.model != FRESNEL_SCHLICK_TIR)
      throw Error(kExitUsage,
                  "--table fresnel-avg runs over eta: it takes --fresnel dielectric or schlick-tir (for "
                  "other models brdfbake energy prints F_avg, and every Fresnel table records it as "
                  "brdf.fresnel.avg)");
    int n = req.size ? *req.size : brdfbake::defaultSize(TableKind::FresnelAvg);
    if (n < 2) throw Error(kExitUsage, "--size must be at least 2 for fresnel-avg, got " + std::to_string(n));
    TableJob job =
        TableJob::of(TableKind::FresnelAvg).texels(n, 1).onNodeGrid(req.nodeGrid).storingHalf(storesHalf(req));
    job.fresnel = fresnel;
    job.path = req.outDir + "/fresnel-avg_" + fresnelNames()[job.fresnel.model] + ".exr";
    applyFormats(req, job);
    return {makeJob(this, job.kind, job)};
  }

  // F_avg(eta) in double (1D, cheap): fresnelAverage, closed form or GK31; each entry's claim its
  // estimate plus the rounding to float.
  BakedTable compute(BakeContext&, const Job& j) const override {
    const TableJob job = j.get<TableJob>();
    const FresnelChoice& fc = job.fresnel;
    auto t0 = std::chrono::steady_clock::now();
    KernelTable kt;
    kt.planes = {std::vector<float>(job.width)};
    kt.err.assign(job.width, 0.0f);
    for (int i = 0; i < job.width; ++i) {
      double t = job.nodeGrid ? i / (job.width - 1.0) : (i + 0.5) / job.width;
      double eta = kEtaLo + (kEtaHi - kEtaLo) * t, e = 0;
      kt.planes[0][i] = static_cast<float>(fresnelAverage(fc.model, eta, 0, &e));
      kt.err[i] = static_cast<float>(e);
    }
    Table2d t;
    t.axes = "eta";
    addClaims(t.claim, kt, Arith::HostDouble, job.ndf, job.gaf);
    t.img.planes = {kt.planes[0]};
    t.img.strings["brdf.channels"] = "R=G=B=F_avg (2 int F(mu) mu dmu)";
    t.img.strings["brdf.fresnel"] = fresnelNames()[fc.model];
    t.img.v2f["brdf.eta.range"] = {static_cast<float>(kEtaLo), static_cast<float>(kEtaHi)};
    t.img.strings["brdf.method"] =
        fc.model == FRESNEL_SCHLICK_TIR
            ? "closed form: (20 F0 + 1)/21, and (1 - eta^2) + eta^2 (20 F0 + 1)/21 for eta < 1"
            : "adaptive Gauss-Kronrod 31 in double on [sqrt(1-eta^2) or 0, 1], F = 1 below "
              "the critical angle; error: its estimate + storage rounding";
    BakedTable out;
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    out.image = finishTable2d(nullptr, job, std::move(t), &out.texelBounds);
    return out;
  }

  // Over n texel centres in eta: the bake's rule (closed form, or adaptive GK31 split at the critical
  // angle) and composite Gauss-Legendre of 2 mu F(mu) over [0, 1] without the split (levels L: 4^L
  // panels of 8 nodes), against the reference (complex Fresnel amplitudes, adaptive GK in double).
  Ladder convergence(BakeContext&, const BakeRequest& req, TableKind, const LadderBudgets& budgets) const override {
    const int model = fresnelOf(req).model;
    if (model != FRESNEL_DIELECTRIC && model != FRESNEL_SCHLICK_TIR)
      throw Error(kExitUsage, "--table fresnel-avg runs over eta: it takes --fresnel dielectric or schlick-tir");
    const int n = ladder::pointsPerAxis(req, 8, 1, 256, "fresnel-avg");
    std::vector<double> eta(n), ref(n);
    for (int i = 0; i < n; ++i) eta[i] = kEtaLo + (kEtaHi - kEtaLo) * (i + 0.5) / n;
    Ladder L;
    L.table = "fresnel-avg of " + fresnelNames()[model] + ", " + std::to_string(n) + " texel centres in eta " +
              fmtG(kEtaLo) + ".." + fmtG(kEtaHi);
    double t0 = ladder::now();
    for (int i = 0; i < n; ++i) ref[i] = reference::fresnelAvg(reference::FresnelSpec{model, eta[i], 0});
    const double refSeconds = ladder::now() - t0;
    {
      std::vector<double> v(n), e(n);
      double secs = ladder::best3([&] {
        for (int i = 0; i < n; ++i) v[i] = fresnelAverage(model, eta[i], 0, &e[i]);
      });
      for (int i = 0; i < n; ++i) e[i] += floatArithmeticError(std::fabs(v[i]), kRoundToFloat);
      L.rungs.push_back(ladder::rung("the bake's rule (host, double)", "adaptive", secs, v, e, ref));
    }
    std::vector<double> prev;
    for (int level : budgets.levels) {
      const int panels = 1 << (2 * level);
      std::vector<double> v(n);
      double secs = ladder::best3([&] {
        for (int i = 0; i < n; ++i)
          v[i] = ladder::gaussLegendre([&](double mu) { return 2 * mu * brdf64::fresnel_F(model, eta[i], 0, mu); }, 0,
                                       1, panels);
      });
      const std::vector<double> e = ladder::changeFrom(prev, v);
      prev = v;
      L.rungs.push_back(
          ladder::rung("Gauss-Legendre in mu (host, double)", std::to_string(panels) + " x 8 nodes", secs, v, e, ref));
    }
    L.note =
        "The reference (F from complex amplitudes, 2 int F mu dmu by adaptive Gauss-Kronrod in double, host/reference) "
        "took " +
        fmt3(refSeconds) + " s for " + std::to_string(n) +
        " values; a Gauss-Legendre rung's estimate is its "
        "change from the previous rung\n";
    return L;
  }

  // eta -> 1 (the dielectric reflects nothing: F_avg -> 0, exactly 0 at 1), eta -> 0 and large
  // (total reflection from inside, and a dense medium), against the reference.
  void stress(BakeContext&, std::vector<StressPoint>& out) const override {
    // (eta = 0.9999: the critical cosine at 0.014, F's square-root end next to it)
    for (double eta : {1.0001, 1.0, 0.9999, 0.2, 0.01, 100.0}) {
      double e = 0;
      const double v = static_cast<float>(fresnelAverage(FRESNEL_DIELECTRIC, eta, 0, &e));
      StressPoint s = stressPoint("fresnel-avg dielectric", "eta=" + fmtG(eta), v,
                                  reference::fresnelAvg(reference::FresnelSpec{FRESNEL_DIELECTRIC, eta, 0}),
                                  e + floatArithmeticError(std::fabs(v), kRoundToFloat), 1e-12);
      if (std::fabs(eta - 1) < 1e-3) {
        s.limit = "F_avg -> 0 as eta -> 1";
        // F_avg grows like |eta - 1| next to 1 (3.3e-5 at 1.0001; 2.3e-4 at 0.9999, where total
        // internal reflection below mu = sqrt(1 - eta^2) alone gives 1 - eta^2), and is 0 at 1 but
        // for rounding
        s.limitMet = s.finite && std::fabs(s.value) <= 3 * std::fabs(eta - 1) + 1e-12;
      } else if (eta < 0.1) {
        s.limit = "F_avg -> 1 as eta -> 0 (total internal reflection)";
        s.limitMet = s.finite && std::fabs(s.value - 1) <= 1e-3;
      }
      out.push_back(s);
    }
  }

  std::string key(const Job& job) const override { return tableJobKey(job.get<TableJob>()); }
  JobSummary summary(const Job& job) const override { return tableJobSummary(job.get<TableJob>()); }
};

}  // namespace

const TableFamily& fresnelAvgFamily() {
  static const FresnelAvg family;
  return family;
}

}  // namespace brdfbake
