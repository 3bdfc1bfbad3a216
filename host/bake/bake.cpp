#include "bake/bake.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "bake/ashikhmin_textures.h"
#include "bake/dielectric_bake.h"
#include "bake/error_model.h"
#include "bake/interp_probe.h"
#include "bake/merl_bake.h"
#include "bake/format_outputs.h"
#include "bake/interp_estimate.h"
#include "bake/method_text.h"
#include "bake/output_set.h"
#include "bake/volume.h"
#include "cl/device.h"
#include "cl/runner.h"
#include "common/brdf_host.h"
#include "common/errors.h"
#include "common/format.h"
#include "common/material.h"
#include "common/models.h"
#include "formats/storage.h"
#include "version.h"

namespace brdfbake {

namespace {

// brdf.interp-error: the larger of the estimate from the texels and the probes' largest lookup
// error with this margin (the probes sample the wedge near the corner, not its every point)
constexpr double kProbeMargin = 1.5;
// The eta axis of fresnel-avg tables: both sides of an interface, glass (1.5) and its inverse.
constexpr double kEtaLo = 0.25, kEtaHi = 4.0;

}  // namespace
}  // namespace brdfbake
namespace brdfbake {
namespace {

std::string modelsOf(const TableJob& job) {
  if (job.ndf < 0) return diffuseNames()[job.diffuse];
  return ndfNames()[job.ndf] + "+" + gafNames()[job.gaf];
}

// How a kernel run's float arithmetic is accounted for in its texels' claims.
enum class Arith {
  Hemisphere,  // the hemisphere estimators: floatArithmeticError of the texel's largest moment
  HemiWeighted,  // the same with a Fresnel weight (E_F, F82-tint's C)
  HemiAvg,     // E_avg: its float error (measured on the averages), plus its double sum rounded to float
  HemiAvgFresnel,  // E_F,avg: the nodes' float error bounds averaged, plus the rounding
  Kp,          // k_p's rule
  HostDouble,  // computed in double on the host: the rounding to float
  Diffuse,     // the diffuse kernel: floatArithmeticError of E with its model's diffuseFloatModel
};

// Each texel's claim from one kernel run: its quadrature estimate plus its float arithmetic,
// merged (the largest) into `claim`.
void addClaims(std::vector<double>& claim, const KernelTable& t, Arith a, int ndf, int gaf, int diffuse = -1) {
  if (claim.empty()) claim.assign(t.err.size(), 0.0);
  for (size_t x = 0; x < t.err.size(); ++x) {
    double scale = 0;
    for (const auto& p : t.planes) scale = std::max(scale, std::fabs(static_cast<double>(p[x])));
    double arith = 0;
    switch (a) {
      case Arith::Hemisphere: arith = floatArithmeticError(scale, hemiFloatModel(ndf, gaf)); break;
      case Arith::HemiWeighted: arith = floatArithmeticError(scale, hemiFloatModel(ndf, gaf, true)); break;
      case Arith::HemiAvg: arith = avgFloatArithmeticError(scale, ndf, gaf); break;
      case Arith::HemiAvgFresnel: arith = avgFloatArithmeticError(scale, ndf, gaf, true); break;
      case Arith::Kp: arith = floatArithmeticError(scale, kKpFloat); break;
      case Arith::HostDouble: arith = floatArithmeticError(scale, kRoundToFloat); break;
      case Arith::Diffuse: arith = floatArithmeticError(scale, diffuseFloatModel(diffuse)); break;
    }
    claim[x] = std::max(claim[x], static_cast<double>(t.err[x]) + arith);
  }
}

}  // namespace

TableImage computeTable(KernelRunner& runner, const TableJob& job, double* seconds, std::vector<double>* texelBounds) {
  if (job.kind == TableKind::AshikhminShirley) {  // closed forms on the host, their own metadata
    auto t0 = std::chrono::steady_clock::now();
    TableImage img = ashikhminTexture(job.texture, job.width, job.half);
    *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return img;
  }
  if (job.ndf >= 0) runner.prepare(job.kind, job.ndf, job.gaf);
  auto t0 = std::chrono::steady_clock::now();
  KernelTable kt;
  TableImage img;
  std::string fresnel = "one", channels, axes = "r";
  const FresnelChoice& fc = job.fresnel;
  // one run per colour channel of a Fresnel model's parameters; every run's bound counts
  auto weight = [&](int c) {
    auto [x, y] = fc.kernelParams(c);
    return HemiWeight{HEMI_FRESNEL, fc.model, static_cast<float>(x), static_cast<float>(y)};
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
        channels = "R=G=B=E (sheen, F = 1: the split sum's second factor is the albedo; Filament's cloth DFG "
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
        addClaims(claim, t, Arith::HemiWeighted, job.ndf, job.gaf);
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
    case TableKind::Brdf3d:
      throw Error(kExitSoftware, "internal: a brdf3d table is written by bake/volume.cpp, not computeTable");
    case TableKind::FresnelAvg: {
      // F_avg(eta) on the host in double (1D, cheap): fresnelAverage, closed form or GK31
      kt.planes = {std::vector<float>(job.width)};
      kt.err.assign(job.width, 0.0f);
      for (int i = 0; i < job.width; ++i) {
        double t = job.nodeGrid ? i / (job.width - 1.0) : (i + 0.5) / job.width;
        double eta = kEtaLo + (kEtaHi - kEtaLo) * t, e = 0;
        kt.planes[0][i] = static_cast<float>(fresnelAverage(fc.model, eta, 0, &e));
        kt.err[i] = static_cast<float>(e);
      }
      addClaims(claim, kt, Arith::HostDouble, job.ndf, job.gaf);
      img.planes = {kt.planes[0]};
      channels = "R=G=B=F_avg (2 int F(mu) mu dmu)";
      axes = "eta";
      fresnel = fresnelNames()[fc.model];
      break;
    }
    case TableKind::AshikhminShirley:  // returned above
      break;
    case TableKind::Dielectric:
    case TableKind::DielectricAvg:
      throw Error(kExitSoftware, "internal: a dielectric table is baked by bake/dielectric_bake.cpp, not computeTable");
  }
  // One-value tables repeat it in R, G and B: a lone R channel reads back as zeros through
  // FreeImage, and three.js's EXRLoader takes only R, G, B, A and Y; R, G, B reads everywhere.
  if (img.planes.size() == 1) {
    img.channels = {"R", "G", "B"};
    img.planes = {img.planes[0], img.planes[0], img.planes[0]};
  }
  if (img.channels.empty()) img.channels = {"R", "G", "B"};  // one plane per colour channel
  *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  img.width = job.width;
  img.height = job.height;

  // every texel finite, or nothing is written
  for (size_t c = 0; c < img.planes.size(); ++c)
    for (size_t t = 0; t < img.planes[c].size(); ++t)
      if (!std::isfinite(img.planes[c][t]) || !std::isfinite(claim[t]))
        throw Error(kExitSoftware, "internal error: " + tableName(job.kind) + " " + modelsOf(job) + " texel (" + std::to_string(t % job.width) + ", " +
                                       std::to_string(t / job.width) + ") is not finite; nothing was written");
  // each texel's claim plus the file's storage rounding (formats/storage.h: the largest over the
  // table; 0 in float32, which holds the kernels' floats exactly, and whose rounding to float every
  // claim above already holds); the file's brdf.error is the largest
  double storage = 0;
  for (auto& p : img.planes) storage = std::max(storage, storageError(p, job.half ? Precision::Float16 : Precision::Float32));
  double bound = 0;
  for (double& c : claim) {
    c += storage;
    bound = std::max(bound, c);
  }
  if (texelBounds) *texelBounds = claim;

  img.strings["brdf.schema"] = "brdfbake/1";
  img.strings["brdf.table"] = tableName(job.kind);
  if (job.ndf >= 0) {
    img.strings["brdf.ndf"] = ndfNames()[job.ndf];
    img.strings["brdf.gaf"] = gafNames()[job.gaf];
    img.strings["brdf.roughness"] = roughnessMapping(job.ndf);
  }
  if (job.diffuse >= 0) img.strings["brdf.diffuse"] = diffuseNames()[job.diffuse];
  img.strings["brdf.fresnel"] = job.kind == TableKind::SplitSum || fc.isOne() ? fresnel : fresnelNames()[fc.model];
  if ((job.kind == TableKind::Albedo || job.kind == TableKind::AlbedoAvg) && !fc.isOne()) {
    for (const auto& [name, value] : fc.parameters()) img.strings["brdf.fresnel." + name] = value;
    // F_avg = 2 int F mu dmu, which Kulla-Conty's Fresnel term needs (host, double)
    std::string avg;
    for (int c = 0; c < fc.channels(); ++c) avg += (c ? "," : "") + fmtG9(fresnelAverage(fc, c));
    img.strings["brdf.fresnel.avg"] = avg;
  }
  img.strings["brdf.axes"] = axes;
  img.strings["brdf.grid"] = job.nodeGrid ? "node" : "texel-center";
  img.strings["brdf.channels"] = channels;
  img.strings["brdf.method"] = methodText(job.kind);
  img.strings["brdf.generator"] = std::string("brdfbake ") + BRDFBAKE_VERSION + " (git " + BRDFBAKE_GIT_REV + ")";
  if (job.kind == TableKind::FresnelAvg) {
    img.v2f["brdf.eta.range"] = {static_cast<float>(kEtaLo), static_cast<float>(kEtaHi)};
    img.strings["brdf.method"] = fc.model == FRESNEL_SCHLICK_TIR
                                     ? "closed form: (20 F0 + 1)/21, and (1 - eta^2) + eta^2 (20 F0 + 1)/21 for eta < 1"
                                     : "adaptive Gauss-Kronrod 31 in double on [sqrt(1-eta^2) or 0, 1], F = 1 below "
                                       "the critical angle; error: its estimate + storage rounding";
  } else if (job.kind == TableKind::Albedo && job.diffuse >= 0) {
    DiffuseAxis ax = diffuseAxis(job.diffuse);
    img.v2f["brdf." + ax.name + ".range"] = {static_cast<float>(ax.lo), static_cast<float>(ax.hi)};
    img.strings["brdf.method"] = diffuseMethod();
  } else {
    img.v2f["brdf.r.range"] = {0.0f, 1.0f};
  }
  if (axes == "mu,r") img.v2f["brdf.mu.range"] = {0.0f, 1.0f};
  // the x texels' spacing, stated on every table over (mu, ...): shader code and readers apply u = sqrt(mu)
  if (axes.rfind("mu,", 0) == 0)
    img.strings["brdf.mu.index"] = job.muSqrt ? "sqrt (x = sqrt(mu): texel i holds mu = x_i^2)" : "linear (x = mu)";
  img.floats["brdf.error"] = static_cast<float>(bound);
  // what the resolution costs a bilinear lookup (estimated from the table; brdf3d tables measure it)
  InterpEstimate ie = estimateInterpolation(img, job.nodeGrid);
  std::vector<ProbePlane> probe = probePlanes(job);  // and measured between texels where they cannot see
  double probed = probe.empty() ? 0 : probeInterpolation(runner, job, img, probe);
  img.floats["brdf.interp-error"] = static_cast<float>(std::max(ie.total(), kProbeMargin * probed));
  img.floats["brdf.interp-error.interior"] = static_cast<float>(ie.interior);
  if (!probe.empty()) img.floats["brdf.interp-error.probe"] = static_cast<float>(probed);
  return img;
}

std::vector<TableReport> runPlan(const Plan& plan) {
  if (isMerlPlan(plan)) return runMerlPlan(plan);  // a measured material: host only
  // Nothing is created before every table is computed and checked: a bad -o, a missing device
  // or an interrupt leaves the file system as it was.
  checkOutputDir(plan.outDir);
  checkVolumeSpace(plan.outDir, plan.volumes);
  DeviceEntry dev = selectDevice(plan.device);
  guardInterrupts("abandoned " + std::to_string(plan.jobs.size() + plan.volumes.size() + plan.dielectric.size()) +
                  " table(s) for " +
                  plan.outDir + "/");
  KernelRunner runner(dev.device);
  // every program (and kernel) the plan needs, built at once on parallel contexts
  std::vector<KernelRunner::TableNeed> needs;
  for (const TableJob& j : plan.jobs)
    if (j.ndf >= 0) needs.push_back({j.kind, j.ndf, j.gaf});
  for (const VolumeJob& v : plan.volumes) needs.push_back({TableKind::Brdf3d, v.spec.ndf, v.spec.gaf});
  for (const DielectricJob& d : plan.dielectric)
    needs.push_back({d.avg ? TableKind::DielectricAvg : TableKind::Dielectric, d.ndf, d.gaf});
  runner.prepareAll(needs);
  std::vector<TableImage> images;
  std::vector<TableReport> tables;
  images.reserve(plan.jobs.size());  // the files point into it
  for (const TableJob& job : plan.jobs) {
    TableReport r;
    images.push_back(computeTable(runner, job, &r.seconds));
    r.table = tableName(job.kind);
    r.ndf = job.ndf >= 0 ? ndfNames()[job.ndf] : "";
    r.gaf = job.gaf >= 0 ? gafNames()[job.gaf] : "";
    r.width = job.width;
    r.height = job.height;
    tables.push_back(r);
  }
  auto extras = [&](const std::string& path, TableImage& img) {
    auto it = plan.extraStrings.find(path);
    if (it != plan.extraStrings.end())
      for (const auto& [k, v] : it->second) img.strings[k] = v;
  };
  // one file per format of each table, every one checked (unorm ranges) before anything is written
  std::deque<TableImage> keep;
  std::vector<OutputFile> files;
  std::vector<TableReport> reports;
  for (size_t i = 0; i < plan.jobs.size(); ++i) {
    extras(plan.jobs[i].path, images[i]);
    addTableFiles(plan.jobs[i], images[i], tables[i], keep, files, reports);
  }
  // 3D tables: baked slab by slab while their files are written (never whole in memory), once
  // per file; the reports' kernel seconds accumulate while the set is written
  std::deque<TableImage> headers;
  std::deque<double> seconds;
  for (const VolumeJob& v : plan.volumes) {
    headers.push_back(volumeHeader(v));
    extras(v.path, headers.back());
    TableReport r;
    r.table = v.merl ? "brdf3d (merl)" : "brdf3d";
    r.ndf = ndfNames()[v.spec.ndf];
    r.gaf = gafNames()[v.spec.gaf];
    r.width = v.spec.nx;
    r.height = v.spec.ny;
    r.depth = v.spec.nz;
    double& secs = seconds.emplace_back(0.0);
    const bool exr = v.merl || std::find(v.formats.begin(), v.formats.end(), FileFormat::Exr) != v.formats.end();
    if (exr) {
      r.path = v.path;
      r.errorBound = headers.back().floats["brdf.error"];
      files.push_back(volumeOutput(runner, v, headers.back(), &secs));
      reports.push_back(r);
    }
    for (PlannedFile& pf : volumeFormatOutputs(runner, v, headers.back(), &secs)) {
      r.path = pf.file.path;
      r.errorBound = pf.errorBound;
      files.push_back(std::move(pf.file));
      reports.push_back(r);
    }
  }
  // rough dielectric tables: computed and checked whole before anything is written
  std::vector<DielectricTable> diel;
  diel.reserve(plan.dielectric.size());
  for (const DielectricJob& d : plan.dielectric) {
    TableReport r;
    diel.push_back(computeDielectric(runner, d, &r.seconds));
    extras(d.path, diel.back().image);
    r.path = d.path;
    r.table = d.avg ? "dielectric-avg" : "dielectric";
    r.ndf = ndfNames()[d.ndf];
    r.gaf = gafNames()[d.gaf];
    r.width = d.nx;
    r.height = d.ny;
    r.depth = d.nz;
    r.errorBound = diel.back().image.floats["brdf.error"];
    reports.push_back(r);
  }
  for (size_t i = 0; i < plan.dielectric.size(); ++i) files.push_back(dielectricOutput(plan.dielectric[i], diel[i]));
  commitOutputs(plan.outDir, files);
  // the kernel time of each 3D table, now that its files are written
  for (TableReport& r : reports)
    for (size_t vi = 0; vi < plan.volumes.size(); ++vi)
      if (r.table.rfind("brdf3d", 0) == 0 && pathStem(plan.volumes[vi].path) == pathStem(r.path)) r.seconds = seconds[vi];
  return reports;
}

}  // namespace brdfbake
