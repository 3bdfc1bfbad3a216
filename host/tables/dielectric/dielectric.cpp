// The rough-dielectric family (--table dielectric, dielectric-avg; Walter et al. 2007): E_R and E_T
// of rough glass over (mu, r, eta) as an EXR atlas of eta slices, and their averages over mu over
// (r, eta). The computation lives in tables/dielectric/dielectric_bake.h and tables/dielectric_avg.h.
#include <algorithm>
#include <array>
#include <tuple>

#include "tables/dielectric/dielectric_bake.h"
#include "common/brdf_host.h"
#include "common/errors.h"
#include "common/format.h"
#include "tables/brdf3d/brdf3d.h"
#include "tables/family.h"
#include "tables/ladder.h"
#include "reference/dielectric_reference.h"
#include <cmath>
#include <cstdio>

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
      throw Error(kExitUsage, t +
                                  ": the rough dielectric takes --gaf smith or smith-correlated (Smith's G for "
                                  "reflection and transmission), not " +
                                  gafNames()[gaf]);
  if (req.fresnel || req.diffuse >= 0)
    throw Error(kExitUsage, t + ": the Fresnel is the exact dielectric one over the eta axis (--eta-range); leave "
                                "--fresnel, --eta, --f0 and --diffuse out");
  // --size NX,NY,NZ: the cube's own axes (mu, r, eta slices), e.g. a slice or two around one
  // material's eta; the averages take one N
  if (req.volume.size && avg)
    throw Error(kExitUsage, "--size NX,NY,NZ: --table dielectric-avg takes one N (N^2 entries over r and eta)");
  int n = req.size ? *req.size : 32;
  const std::array<int, 3> cubeN = req.volume.size ? *req.volume.size : std::array<int, 3>{n, n, n};
  for (int a : {n, cubeN[0], cubeN[1], cubeN[2]}) {
    if (a > kMaxVolumeSize)
      throw Error(kExitUsage, "--size: each axis of a dielectric table must be an integer in 1.." +
                                  std::to_string(kMaxVolumeSize) + ", got " + std::to_string(a));
    if (req.nodeGrid && a < 2) throw Error(kExitUsage, "--size: the node grid needs at least 2 samples per axis");
  }
  for (int ndf : req.ndfs)
    for (int gaf : req.gafs)
      for (int a = 0; a < 2; ++a) {
        if (!(a ? avg : cube)) continue;
        DielectricJob j;
        j.ndf = ndf;
        j.gaf = gaf;
        j.avg = a == 1;
        j.nx = j.avg ? n : cubeN[0];
        j.ny = j.avg ? n : cubeN[1];
        j.nz = j.avg ? 1 : cubeN[2];
        j.nodeGrid = req.nodeGrid;
        j.half = storesHalf(req);
        if (req.etaRange) std::tie(j.etaLo, j.etaHi) = *req.etaRange;
        if (!j.avg) std::tie(j.cols, j.rows) = atlasGrid(j.nz);
        j.path = req.outDir + "/" + (j.avg ? "dielectric-avg_" : "dielectric_") + ndfNames()[ndf] + "_" +
                 gafNames()[gaf] + ".exr";
        jobs.push_back(makeJob(family, j.avg ? TableKind::DielectricAvg : TableKind::Dielectric, j));
      }
  return jobs;
}

// The etas the ladders measure at: inside glass (TIR), water, glass; or --eta-range's ends.
std::vector<double> ladderEtas(const BakeRequest& req) {
  if (req.etaRange) {
    if (req.etaRange->first == 1 || req.etaRange->second == 1)
      throw Error(kExitUsage,
                  "--eta-range: convergence measures at its ends, and at eta = 1 the transmitted lobe is a "
                  "delta (no integral to converge); give ends other than 1");
    return {req.etaRange->first, req.etaRange->second};
  }
  return {1 / 1.5, 1.33, 1.5};
}
std::string etaText(const std::vector<double>& etas) {
  std::string s;
  for (double e : etas) s += (s.empty() ? "" : ", ") + fmtG(e, 3);
  return s;
}

// dielectric over n x n texel centres in (mu, r) at three etas: the device's quadrature at
// per-texel targets 1e-4 10^-L (levels L) and at the bake's, against the o-space reference.
Ladder cubeLadder(BakeContext& ctx, const BakeRequest& req, const LadderBudgets& budgets, int ndf, int gaf) {
  const int n = ladder::pointsPerAxis(req, 3, 1, 16, "dielectric");
  const std::vector<double> etas = ladderEtas(req);
  Ladder L;
  L.table = "dielectric (E_R and E_T) of " + ndfNames()[ndf] + "+" + gafNames()[gaf] + ", " + std::to_string(n) + "x" +
            std::to_string(n) + " texel centres in (mu, r) at eta " + etaText(etas);
  const size_t texels = static_cast<size_t>(n) * n * etas.size();
  std::fprintf(stderr, "convergence: reference at %zu points\n", texels);
  std::vector<double> ref(texels * 2);
  double t0 = ladder::now();
  ladder::onTwoThreads(texels, [&](size_t k) {
    size_t x = k % n, y = (k / n) % n, z = k / (static_cast<size_t>(n) * n);
    reference::DielectricAlbedo a = reference::dielectricAlbedo(ndf, gaf, ladder::centre(static_cast<int>(x), n),
                                                                ladder::centre(static_cast<int>(y), n), etas[z]);
    ref[2 * k] = a.r;
    ref[2 * k + 1] = a.t;
  });
  const double refSeconds = ladder::now() - t0;
  KernelRunner& kr = ctx.runner();
  kr.prepare(dielectricKernel(ndf, gaf));
  std::vector<float> targets;
  for (int level : budgets.levels) targets.push_back(static_cast<float>(1e-4 * std::pow(10.0, -level)));
  targets.push_back(kDielectricTarget);
  dielectricSlab(kr, ndf, gaf, n, n, etas, false, targets.front());  // warm
  for (size_t i = 0; i < targets.size(); ++i) {
    std::vector<std::vector<float>> p;
    double secs = ladder::best3([&] { p = dielectricSlab(kr, ndf, gaf, n, n, etas, false, targets[i]); });
    std::vector<double> v(texels * 2), e(texels);
    for (size_t k = 0; k < texels; ++k) {
      v[2 * k] = p[0][k];
      v[2 * k + 1] = p[1][k];
      // + what the bake adds to each texel's bound (tables/dielectric/dielectric_bake.cpp): E_R and E_T rounded to
      // float, 2^-25 each below 1 (the sum's third rounding is not measured here), and the fp64 program's 1e-9
      e[k] = p[2][k] + 2 * std::ldexp(1.0, -25) + 1e-9;
    }
    L.rungs.push_back(ladder::rung("quadrature (device)",
                                   (i + 1 == targets.size() ? "the bake's target " : "target ") + fmt3(targets[i]),
                                   secs, v, e, ref));
  }
  L.note =
      "The reference (Walter et al.'s BSDF integrated over the scattered direction by nested adaptive Gauss-Kronrod "
      "in double, host/reference/dielectric_reference.cpp) took " +
      fmt3(refSeconds) + " s for " + std::to_string(texels) + " points\n";
  return L;
}

// dielectric-avg over n texel centres in r at three etas: the bake's averages rule (panels over mu
// with E on the device) at entry targets 1e-4 10^-L (levels L) and at the bake's, against
// 2 int E mu dmu of the o-space reference's E by adaptive Gauss-Kronrod, split at the critical mu.
Ladder avgLadder(BakeContext& ctx, const BakeRequest& req, const LadderBudgets& budgets, int ndf, int gaf) {
  const int n = ladder::pointsPerAxis(req, 2, 1, 16, "dielectric-avg");
  Ladder L;
  L.table = "dielectric-avg (E_R,avg and E_T,avg) of " + ndfNames()[ndf] + "+" + gafNames()[gaf] + ", " +
            std::to_string(n) + " texel centres in r at eta " + etaText(ladderEtas(req));
  std::vector<double> rs, etas;
  for (double eta : ladderEtas(req))
    for (int j = 0; j < n; ++j) rs.push_back(ladder::centre(j, n)), etas.push_back(eta);
  const size_t entries = rs.size();
  std::fprintf(stderr, "convergence: reference at %zu entries\n", entries);
  std::vector<double> ref(entries * 2);
  double t0 = ladder::now();
  ladder::onTwoThreads(entries, [&](size_t k) {
    // E(mu) has a square-root end at the critical cosine (eta < 1) and changes on the scale of
    // alpha next to mu = 0: 8-point Gauss-Legendre on panels graded geometrically (ratio 1/2, 9
    // levels) towards both ends of each piece, so that both endpoint features converge.
    const double muc = dielectricCriticalMu(etas[k]);
    std::vector<double> edges = {0.0};
    auto piece = [&](double a, double b) {
      for (int g = 9; g >= 1; --g) edges.push_back(a + (b - a) * std::ldexp(1.0, -g));
      for (int g = 2; g <= 9; ++g) edges.push_back(b - (b - a) * std::ldexp(1.0, -g));
      edges.push_back(b);
    };
    if (muc > 0)
      piece(0, muc), piece(muc, 1);
    else
      piece(0, 1);
    double sum[2] = {0, 0};
    for (size_t e = 0; e + 1 < edges.size(); ++e)
      for (const ladder::Node& x : ladder::gaussLegendreNodes(edges[e], edges[e + 1], 1)) {
        reference::DielectricAlbedo a = reference::dielectricAlbedo(ndf, gaf, x.x, rs[k], etas[k]);
        sum[0] += x.w * 2 * x.x * a.r;
        sum[1] += x.w * 2 * x.x * a.t;
      }
    ref[2 * k] = sum[0];
    ref[2 * k + 1] = sum[1];
  });
  const double refSeconds = ladder::now() - t0;
  KernelRunner& kr = ctx.runner();
  kr.prepare(dielectricPointsKernel(ndf, gaf));
  std::vector<std::pair<double, float>> targets;  // entry target, node target
  for (int level : budgets.levels) {
    double t = 1e-4 * std::pow(10.0, -level);
    targets.push_back({t, static_cast<float>(std::max(t, 1e-7))});
  }
  targets.push_back({kDielectricAvgTarget, kDielectricAvgNodeTarget});
  for (size_t i = 0; i < targets.size(); ++i) {
    DielectricAverages a;
    double secs = ladder::now();
    a = dielectricAverages(dielectricDeviceEval(kr, ndf, gaf, targets[i].second), rs, etas, targets[i].first);
    secs = ladder::now() - secs;
    std::vector<double> v(entries * 2), e(entries);
    for (size_t k = 0; k < entries; ++k) {
      v[2 * k] = a.er[k];
      v[2 * k + 1] = a.et[k];
      e[k] = std::max(a.br[k], a.bt[k]);
    }
    L.rungs.push_back(ladder::rung(
        "the averages' rule (device E)",
        (i + 1 == targets.size() ? "the bake's target " : "target ") + fmt3(targets[i].first), secs, v, e, ref));
  }
  L.note =
      "The reference (2 int E mu dmu by 8-point Gauss-Legendre on panels graded towards 0, the critical mu and 1, "
      "of the o-space reference's E, host/reference/dielectric_reference.cpp) took " +
      fmt3(refSeconds) + " s for " + std::to_string(entries) + " entries\n";
  return L;
}

class Dielectric final : public TableFamily {
 public:
  std::string name() const override { return "dielectric"; }
  std::vector<KindInfo> describe() const override {
    KindInfo cube{TableKind::Dielectric, "dielectric"};
    cube.shader = ShaderLookup::EtaVolume;
    cube.inScenes = cube.furnace = true;
    cube.sizeAxes = 3;
    cube.sceneUses = kUseTransmission;
    KindInfo avg{TableKind::DielectricAvg, "dielectric-avg"};
    avg.shader = ShaderLookup::EtaAverages;
    avg.inScenes = avg.furnace = avg.average = true;
    avg.sceneUses = kUseTransmission;
    return {cube, avg};
  }

  std::vector<Job> plan(const BakeRequest& req) const override {
    if (!req.merl.empty() || !req.preset.empty()) return {};
    return planDielectric(this, req);
  }

  std::vector<KernelNeed> kernels(const Job& job) const override {
    const DielectricJob& d = job.get<DielectricJob>();
    return {d.avg ? dielectricPointsKernel(d.ndf, d.gaf) : dielectricKernel(d.ndf, d.gaf)};
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
    table->cube = std::move(baked.volume);  // the set keeps `baked` only for its files; the writer reads `table`
    OutputFile f = dielectricOutput(d, *table);
    auto write = f.write;
    if (write)
      f.write = [write, table](const std::string& tmp) { write(tmp); };
    else
      f.image = &set.keep.emplace_back(table->image);
    set.files.push_back(std::move(f));
  }

  Ladder convergence(BakeContext& ctx, const BakeRequest& req, TableKind kind,
                     const LadderBudgets& budgets) const override {
    if (req.ndfs.size() != 1 || req.gafs.size() != 1)
      throw Error(kExitUsage, "convergence measures one pair: give one --ndf and one --gaf");
    BakeRequest r = req;
    r.tables = {kind};
    planDielectric(this, r);  // the same model checks as a bake
    const int ndf = req.ndfs[0], gaf = req.gafs[0];
    return kind == TableKind::Dielectric ? cubeLadder(ctx, req, budgets, ndf, gaf)
                                         : avgLadder(ctx, req, budgets, ndf, gaf);
  }

  // Near the interface's limits: eta -> 1 (E_R -> 0, E_T -> the eta = 1 closed form), a nearly
  // smooth interface, grazing views, a dense medium; the device's values in double (the averages'
  // nodes, bake_dielectric_points) against the o-space reference.
  void stress(BakeContext& ctx, std::vector<StressPoint>& out) const override {
    KernelRunner& kr = ctx.runner();
    const int ndf = NDF_GGX, gaf = GAF_SMITH_CORRELATED;
    kr.prepare(dielectricPointsKernel(ndf, gaf));
    struct Case {
      double mu, r, eta;
      const char* sweep;
    };
    const Case cases[] = {{0.5, 0.5, 1.0001, "dielectric eta -> 1"}, {0.5, 0.5, 0.9999, "dielectric eta -> 1"},
                          {0.5, 0.05, 1.5, "dielectric r -> 0"},     {1e-4, 0.5, 1.5, "dielectric mu -> 0"},
                          {0.5, 1.0, 1.5, "dielectric rough"},       {0.2, 0.3, 0.6, "dielectric eta < 1 (TIR)"},
                          {0.5, 1.0, 2.5, "dielectric dense, rough"}};
    std::vector<double> mus, rs, etas;
    for (const Case& c : cases) mus.push_back(c.mu), rs.push_back(c.r), etas.push_back(c.eta);
    std::vector<std::vector<double>> p = dielectricPoints(kr, ndf, gaf, mus, rs, etas, kDielectricAvgNodeTarget);
    for (size_t k = 0; k < mus.size(); ++k) {
      reference::DielectricAlbedo a = reference::dielectricAlbedo(ndf, gaf, mus[k], rs[k], etas[k]);
      const bool nearOne = std::fabs(etas[k] - 1) < 1e-3;
      const reference::DielectricAlbedo eta1 = reference::dielectricAlbedoEta1(ndf, gaf, mus[k], rs[k]);
      for (int lobe = 0; lobe < 2; ++lobe) {
        // the node's bound (absolute, E <= 1), the fp64 program's 1e-9 (tables/dielectric/dielectric_bake.cpp), and
        // the reference's own accuracy near its limits (1e-8, as the averages' tests allow it)
        StressPoint s = stressPoint(
            cases[k].sweep,
            std::string(lobe ? "E_T" : "E_R") + " mu=" + fmt4(mus[k]) + " r=" + fmt4(rs[k]) + " eta=" + fmtG(etas[k]),
            lobe ? p[1][k] : p[0][k], lobe ? a.t : a.r, p[2 + lobe][k] + 1e-9, 1e-8);
        if (nearOne) {
          s.limit = lobe ? "E_T -> (1 + L) G_T(L, L) as eta -> 1" : "E_R -> 0 as eta -> 1";
          s.limitMet = s.finite && std::fabs(s.value - (lobe ? eta1.t : 0.0)) <= 1e-3;
        }
        out.push_back(s);
      }
    }
  }

  std::string key(const Job& job) const override {
    const DielectricJob d = job.get<DielectricJob>();
    return std::string("table=") + (d.avg ? "dielectric-avg" : "dielectric") + ";ndf=" + std::to_string(d.ndf) +
           ";gaf=" + std::to_string(d.gaf) + ";size=" + std::to_string(d.nx) + "x" + std::to_string(d.ny) + "x" +
           std::to_string(d.nz) + ";eta=" + fmtG9(d.etaLo) + "," + fmtG9(d.etaHi) +
           ";grid=" + (d.nodeGrid ? "node" : "texel") + ";half=" + (d.half ? "1" : "0");
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
