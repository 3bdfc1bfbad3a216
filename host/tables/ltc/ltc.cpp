// The LTC family (--table ltc): linearly transformed cosines fitted to every lobe a scene shades
// under area lights (tables/ltc/ltc_fit.h, kernels/integrate/ltc_fit.h), two files per lobe in the
// engines' layout:
//   ltc1_<lobe>: RGBA = M^-1 / M^-1_11 entries (inv00, inv20, inv02, inv22), three.js's LTC_MAT_1;
//   ltc2_<lobe>: RGBA = (E, B, TV, below): the magnitude and Fresnel moment (three.js's LTC_MAT_2 .x
//                and .y), the fit's total-variation distance and the LTC's mass below the horizon.
// x = roughness r = x/(n - 1), y = sqrt(1 - mu) = y/(n - 1) (nodes; theta_v capped at 1.57).
#include <algorithm>
#include <chrono>
#include <cmath>

#include "common/brdf_host.h"
#include "common/errors.h"
#include "common/format.h"
#include "common/material.h"
#include "formats/format_outputs.h"
#include "tables/family.h"
#include "tables/ladder.h"
#include "tables/ltc/ltc_checks.h"
#include "tables/ltc/ltc_fit.h"
#include "tables/ltc/ltc_shader.h"
#include "tables/registry.h"
#include "tables/table2d.h"

namespace brdfbake {

namespace {

constexpr int kMinLtcSize = 2, kMaxLtcSize = 256;

struct LtcJob : JobSpec {
  LtcLobeSpec lobe;
  int n = 64;
  bool half = false;
  std::vector<FileFormat> formats = {FileFormat::Exr};
  Precision precision = Precision::Float32;
};

// What compute() hands addBakedFiles: the two images and their claims.
struct LtcTables : FamilyData {
  TableImage m, amp;
  std::vector<double> mBounds, ampBounds;
  std::string note;  // the bake report's line under ltc1
};

// The fit's target: a texel farther than this from its lobe is named in the bake's report (with its
// distance, kept as fitted). 0.1 is where the fit tries its second start (kernels/ltc.cl).
constexpr double kLtcTarget = 0.1;

// A fit kept for the bake: the exact-Smith GAFs of ggx and beckmann are the same lobes as smith's
// (gaf_canonical, kernels/brdf/gaf.h), fitted once.
struct KeptFit : FamilyData {
  LtcFit fit;
};

std::string dirOf(const std::string& path) {
  const size_t s = path.find_last_of('/');
  return s == std::string::npos ? "." : path.substr(0, s);
}

// File `file` (1: M^-1's entries, 2: the magnitudes) of the job planned at DIR/ltc_<lobe>.exr:
// DIR/ltc<file>_<lobe>.exr, the extension the writers replace per format.
std::string ltcFilePath(const std::string& jobPath, int file) {
  const std::string dir = dirOf(jobPath);
  return dir + "/ltc" + std::to_string(file) + "_" + jobPath.substr(dir.size() + 5);
}

class LtcFamily final : public TableFamily {
 public:
  std::string name() const override { return "ltc"; }
  std::vector<KindInfo> describe() const override {
    KindInfo k{TableKind::Ltc, "ltc"};
    k.defaultSize = 64;
    k.shader = ShaderLookup::Family;
    k.shaderCode = ltcShaderCode();
    return {k};
  }

  std::vector<Job> plan(const BakeRequest& req) const override {
    if (std::find(req.tables.begin(), req.tables.end(), TableKind::Ltc) == req.tables.end()) return {};
    if (!req.merl.empty() || !req.preset.empty()) return {};
    if (req.fresnel)
      throw Error(kExitUsage, "--fresnel " + fresnelNames()[req.fresnel->model] +
                                  ": --table ltc stores the magnitude and Schlick's Fresnel moment, as engines "
                                  "read them (F0 enters in the shader); bake it without --fresnel");
    const int n = req.size ? *req.size : brdfbake::defaultSize(TableKind::Ltc);
    if (n < kMinLtcSize || n > kMaxLtcSize)
      throw Error(kExitUsage, "--size " + std::to_string(n) + ": --table ltc takes " + std::to_string(kMinLtcSize) +
                                  " to " + std::to_string(kMaxLtcSize) +
                                  " texels per axis (a fit per texel: 64 is "
                                  "the engines' size)");
    if (req.diffuse == DIFFUSE_LAMBERT)
      throw Error(kExitUsage,
                  "--diffuse lambert: its LTC is the clamped cosine itself (M = identity); --table ltc fits "
                  "the other diffuse models (" +
                      joinNames(std::vector<std::string>(diffuseNames().begin() + 1, diffuseNames().end())) + ")");
    std::vector<Job> jobs;
    auto add = [&](const LtcLobeSpec& lobe) {
      LtcJob j;
      j.lobe = lobe;
      j.n = n;
      j.half = storesHalf(req);
      j.precision = req.precision.value_or(Precision::Float32);
      j.formats = req.formats.empty() ? std::vector<FileFormat>{FileFormat::Exr} : req.formats;
      j.path = req.outDir + "/ltc_" + lobe.name() + ".exr";
      jobs.push_back(makeJob(this, TableKind::Ltc, j));
    };
    if (req.diffuse >= 0) {
      LtcLobeSpec d;
      d.diffuse = req.diffuse;
      add(d);
    }
    for (int ndf : req.ndfs)
      for (int gaf : req.gafs)
        if (pairSupported(ndf, gaf)) add(LtcLobeSpec{ndf, gaf});
    return jobs;
  }

  std::vector<KernelNeed> kernels(const Job& job) const override {
    const LtcJob j = job.get<LtcJob>();
    std::vector<KernelNeed> needs;
    if (!j.lobe.isDiffuse()) needs.push_back({KernelNeed::Hemisphere, j.lobe.ndf, j.lobe.gaf});
    KernelNeed own{KernelNeed::Own, j.lobe.isDiffuse() ? NDF_GGX : j.lobe.ndf,
                   j.lobe.isDiffuse() ? GAF_SMITH_CORRELATED : j.lobe.gaf, ProgramKey::Ltc, "ltc_fit_row"};
    needs.push_back(own);
    return needs;
  }

  BakedTable compute(BakeContext& ctx, const Job& job) const override {
    const LtcJob j = job.get<LtcJob>();
    KernelRunner& runner = ctx.runner();
    const std::string fitKey =
        "ltc-fit:" +
        (j.lobe.isDiffuse()
             ? j.lobe.name()
             : std::to_string(j.lobe.ndf) + "+" + std::to_string(brdf64::gaf_canonical(j.lobe.ndf, j.lobe.gaf))) +
        ":" + std::to_string(j.n);
    auto kept = ctx.cache.find(fitKey);
    const bool reused = kept != ctx.cache.end();
    if (!reused) {
      auto k = std::make_shared<KeptFit>();
      k->fit = fitLtc(runner, j.lobe, j.n);
      kept = ctx.cache.emplace(fitKey, k).first;
    }
    const LtcFit& f = std::static_pointer_cast<const KeptFit>(kept->second)->fit;
    const size_t texels = static_cast<size_t>(j.n) * j.n;
    for (size_t t = 0; t < texels; ++t) {
      bool finite = std::isfinite(f.tv[t]) && std::isfinite(f.e[t]) && std::isfinite(f.b[t]);
      for (const auto& s : f.store) finite = finite && std::isfinite(s[t]);
      if (!finite)
        throw Error(kExitSoftware, "internal error: the LTC fit of " + j.lobe.name() + " is not finite at texel (" +
                                       std::to_string(t % j.n) + ", " + std::to_string(t / j.n) +
                                       "); nothing was written");
    }
    // the fit's summary: the largest distance, where, its estimate's error, the mass below
    size_t worst = 0;
    double tvErrMax = 0, belowMax = 0, tvSum = 0, litMax = 0;
    int negligible = 0;
    for (size_t t = 0; t < texels; ++t) {
      if (f.tv[t] > f.tv[worst]) worst = t;
      if (f.e[t] < kLtcNegligibleE)
        ++negligible;
      else
        litMax = std::max<double>(litMax, f.tv[t]);
      tvErrMax = std::max<double>(tvErrMax, f.tvErr[t]);
      belowMax = std::max<double>(belowMax, f.below[t]);
      tvSum += f.tv[t];
    }
    auto common = [&](TableImage& img) {
      img.strings["ltc.lobe"] = j.lobe.name();
      img.strings["ltc.axes"] = "x = r (alpha = max(r^2, 1e-5)), y = sqrt(1 - mu) (theta_v <= 1.57); nodes";
      img.floats["ltc.distance.max"] = f.tv[worst];
      img.floats["ltc.distance.mean"] = static_cast<float>(tvSum / texels);
      img.floats["ltc.distance.error"] = static_cast<float>(tvErrMax);
      img.v2f["ltc.distance.max.at"] = {static_cast<float>(ltcRoughness(static_cast<int>(worst % j.n), j.n)),
                                        static_cast<float>(ltcMu(static_cast<int>(worst / j.n), j.n))};
      img.floats["ltc.below.max"] = static_cast<float>(belowMax);
      // texels whose lobe carries less than 1e-6 of the light state distance 1 (any LTC meets it)
      img.floats["ltc.negligible"] = static_cast<float>(negligible);
      img.floats["ltc.distance.max.lit"] = static_cast<float>(litMax);
      img.strings["ltc.method"] =
          "Nelder-Mead on M = R_y(phi) [[m11, 0, m13], [0, m22, 0], [0, 0, 1]] minimising the total-variation "
          "distance 1/2 int |p - D| over the sphere, estimated by multiple importance sampling (GGX visible "
          "normals, cosine, the LTC; rank-1 lattice points), started from the row above "
          "(host/tables/ltc/ltc_fit.cpp, kernels/integrate/ltc_fit.h); distance: 16 hashed shifts of a lattice "
          "of 3 x 256 points (in double on the host where u/(alpha mu) > 2e-5), error 4 standard errors, a tenth of "
          "the distance and E's claim; an estimate above 1 is replaced by the reference "
          "quadrature's (1 - int min(p, D), adaptive, in double; host/tables/ltc/ltc_reference.cpp)";
    };
    auto tableJobOf = [&](const std::string& path) {
      TableJob tj = TableJob::of(TableKind::Ltc).texels(j.n, j.n).onNodeGrid(true).storingHalf(j.half);
      if (!j.lobe.isDiffuse()) tj.forPair(j.lobe.ndf, j.lobe.gaf);
      tj.diffuse = j.lobe.diffuse;
      tj.path = path;
      return tj;
    };
    auto data = std::make_shared<LtcTables>();
    // one file's table: its planes, each texel's claim, what its channels hold
    auto table = [&](std::vector<std::vector<float>> planes, std::vector<double> claim, const std::string& file,
                     const std::string& channels, std::vector<double>* bounds) {
      Table2d t;
      t.axes = "r,sqrt(1-mu)";
      t.img.channels = {"R", "G", "B", "A"};
      t.img.planes = std::move(planes);
      t.claim = std::move(claim);
      t.img.strings["brdf.channels"] = channels;
      t.img.strings["ltc.file"] = file;
      common(t.img);
      return finishTable2d(nullptr, tableJobOf(j.path), std::move(t), bounds);
    };
    // the entries define the LTC: a texel's claim is its distance to the lobe and that distance's
    // estimate error (ltc2's B channel holds the distance)
    std::vector<double> fitClaim(texels);
    for (size_t k = 0; k < texels; ++k) fitClaim[k] = static_cast<double>(f.tv[k]) + f.tvErr[k];
    data->m = table({f.store[0], f.store[1], f.store[2], f.store[3]}, fitClaim, "matrix",
                    "R,G,B,A = M^-1 entries (0,0), (2,0), (0,2), (2,2) divided by (1,1): GLSL mat3(vec3(R, 0, G), "
                    "vec3(0, 1, 0), vec3(B, 0, A)); brdf.error: the largest distance to the lobe plus its estimate's "
                    "error",
                    &data->mBounds);
    data->amp = table({f.e, f.b, f.tv, f.below}, f.eBound, "magnitude",
                      "R = E (the lobe's magnitude, F = 1), G = B (Fresnel moment, int f (1 - o.h)^5 cos: F0 R + "
                      "(1 - F0) G is Schlick's), B = the fit's total-variation distance, A = the LTC's mass below the "
                      "horizon",
                      &data->ampBounds);
    // the summary line: distances, and the texels past the fit target (named, up to five)
    {
      std::vector<size_t> past;
      for (size_t t = 0; t < texels; ++t)
        if (f.e[t] >= kLtcNegligibleE && f.tv[t] > kLtcTarget) past.push_back(t);
      std::sort(past.begin(), past.end(), [&](size_t a, size_t b) { return f.tv[a] > f.tv[b]; });
      std::string note = "distance (TV) mean " + fmt4(tvSum / texels) + ", largest " + fmt4(f.tv[worst]) +
                         " (r = " + fmt3(ltcRoughness(static_cast<int>(worst % j.n), j.n)) +
                         ", mu = " + fmtG(ltcMu(static_cast<int>(worst / j.n), j.n)) + ")";
      if (negligible) note += "; " + std::to_string(negligible) + " texels with E < 1e-6 state 1";
      if (f.byReference) note += "; " + std::to_string(f.byReference) + " from the reference quadrature";
      note += "; " + std::to_string(past.size()) + " texels past " + fmtG(kLtcTarget);
      for (size_t k = 0; k < past.size() && k < 5; ++k)
        note += std::string(k ? ", " : ": ") + fmt3(f.tv[past[k]]) + " at (r " +
                fmt3(ltcRoughness(static_cast<int>(past[k] % j.n), j.n)) + ", mu " +
                fmtG(ltcMu(static_cast<int>(past[k] / j.n), j.n)) + ")";
      if (past.size() > 5) note += ", ...";
      data->note = note;
    }
    BakedTable out;
    out.seconds = reused ? 0.0 : f.seconds + f.magnitudeSeconds;  // a reused fit cost nothing here
    out.image = data->amp;  // the report's table; the matrices ride in the cache entry
    ctx.cache["ltc:" + job.path] = data;
    return out;
  }

  void addFiles(BakeContext& ctx, const Job& job, FileSet& set) const override {
    BakedTable& t = set.baked.emplace_back(compute(ctx, job));
    auto data = std::static_pointer_cast<const LtcTables>(ctx.cache.at("ltc:" + job.path));
    ctx.cache.erase("ltc:" + job.path);
    const LtcJob j = job.get<LtcJob>();
    const TableImage& m = set.keep.emplace_back(data->m);
    const TableImage& amp = set.keep.emplace_back(data->amp);
    for (int file = 0; file < 2; ++file) {
      const std::string path = ltcFilePath(job.path, file + 1);
      TableReport r;
      r.table = "ltc";
      r.ndf = j.lobe.isDiffuse() ? diffuseNames()[j.lobe.diffuse] : ndfNames()[j.lobe.ndf];
      r.gaf = j.lobe.isDiffuse() ? "" : gafNames()[j.lobe.gaf];
      r.width = r.height = j.n;
      r.seconds = file == 0 ? t.seconds : 0;
      r.note = file == 0 ? data->note : "";
      for (PlannedFile& pf :
           tableOutputs(FileSpec{path, j.formats, j.precision, j.half, TableLayout{}, ""}, file ? amp : m, set.keep)) {
        r.path = pf.file.path;
        r.errorBound = pf.errorBound;
        set.reports.push_back(r);
        set.files.push_back(std::move(pf.file));
      }
    }
  }

  Ladder convergence(BakeContext& ctx, const BakeRequest& req, TableKind, const LadderBudgets&) const override {
    return ltcLadder(ctx, req);
  }
  void stress(BakeContext& ctx, std::vector<StressPoint>& out) const override { ltcStress(ctx, out); }

  std::string key(const Job& job) const override {
    const LtcJob j = job.get<LtcJob>();
    std::string k = "table=ltc;lobe=" + j.lobe.name() + ";size=" + std::to_string(j.n) +
                    ";half=" + (j.half ? "1" : "0") + ";formats=";
    for (FileFormat f : j.formats) k += std::to_string(static_cast<int>(f)) + ",";
    return k;
  }
  JobSummary summary(const Job& job) const override {
    const LtcJob j = job.get<LtcJob>();
    JobSummary s;
    s.table = "ltc";
    s.models = j.lobe.isDiffuse() ? diffuseNames()[j.lobe.diffuse] + " diffuse"
                                  : ndfNames()[j.lobe.ndf] + " + " + gafNames()[j.lobe.gaf];
    s.size = std::to_string(j.n) + "x" + std::to_string(j.n);
    s.texels = static_cast<double>(j.n) * j.n;
    // measured: 1000 s for the 52 microfacet pairs' 64^2 tables and 94 s for charlie's 4 on two
    // cores (docs/ltc.md), 4.8 ms a texel (the fit), against 1 us for an integral
    s.cost = s.texels * 4.8e-3;
    const std::string ext = formatExtension(j.formats.empty() ? FileFormat::Exr : j.formats.front());
    for (int file = 1; file <= 2; ++file) {
      const std::string path = ltcFilePath(job.path, file);
      s.files.push_back(path.substr(0, path.size() - 4) + ext);  // .exr replaced
    }
    return s;
  }
};

}  // namespace

const TableFamily& ltcFamily() {
  static const LtcFamily family;
  return family;
}

}  // namespace brdfbake
