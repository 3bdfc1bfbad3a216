#include "bake/bake.h"

#include <Imath/half.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "cl/device.h"
#include "cl/runner.h"
#include "common/errors.h"
#include "common/models.h"
#include "version.h"

namespace brdfbake {

namespace {

// Allowance for evaluating the integrand in float on the device: the |K15 - G7| bounds cover
// the quadrature, not rounding. Where the quadrature bound is far below it, kernel-vs-reference
// errors stay under 3e-7 (tests/accuracy_test.cpp, every pair; brdfbake-bench: 2.3e-7 on the
// default table); the allowance keeps a 3x margin, and those tests check bound + allowance.
constexpr double kFloatArithmeticAllowance = 1e-6;

const char* kMethod =
    "h-space quadrature: theta_h by v=-log(1-CDF_ndf) in GK15 panels (breaks 1,3,7,15,40 and at the "
    "visible-domain limits, sqrt ends substituted), phi_h by 16-interval trapezoid on the full "
    "circle or GK15 per smooth arc; texels bounded above 8e-6 redone with a doubled budget; error "
    "|K15-G7| + inner bounds + float allowance";

void ensureOutputDir(const std::string& dir) {
  struct stat st {};
  if (stat(dir.c_str(), &st) != 0) {
    if (mkdir(dir.c_str(), 0777) != 0)
      throw Error(kExitCantCreat, "-o: cannot create output directory '" + dir + "': " + std::strerror(errno));
  } else if (!S_ISDIR(st.st_mode)) {
    throw Error(kExitCantCreat, "-o: '" + dir + "' exists and is not a directory");
  }
  if (access(dir.c_str(), W_OK | X_OK) != 0)
    throw Error(kExitCantCreat, "-o: output directory '" + dir + "' is not writable");
}

// The largest relative error that storing `v` in the file's pixel type adds.
double storageError(const std::vector<float>& v, bool half) {
  double worst = 0;
  for (float x : v) {
    double stored = half ? static_cast<double>(static_cast<float>(Imath::half(x))) : static_cast<double>(x);
    worst = std::max(worst, std::fabs(stored - x) / std::max(1.0, std::fabs(static_cast<double>(x))));
  }
  // float itself: the kernel's double sum rounded to float, at most half an ulp
  return worst + std::ldexp(1.0, -24);
}

}  // namespace

TableImage computeTable(KernelRunner& runner, const TableJob& job, double* seconds) {
  runner.prepare(job.ndf, job.kind == TableKind::Kp ? 0 : job.gaf);
  auto t0 = std::chrono::steady_clock::now();
  KernelTable kt;
  TableImage img;
  std::string fresnel = "one", channels, axes = "r";
  switch (job.kind) {
    case TableKind::SplitSum:
      kt = runner.hemisphere(job.ndf, job.gaf, job.width, job.height, job.nodeGrid);
      img.channels = {"R", "G", "B"};
      img.planes = {kt.planes[0], kt.planes[1], kt.planes[2]};
      fresnel = "schlick";
      channels = "R=A,G=B,B=A+B";
      axes = "mu,r";
      break;
    case TableKind::Albedo:
      kt = runner.hemisphere(job.ndf, job.gaf, job.width, job.height, job.nodeGrid);
      img.channels = {"R"};
      img.planes = {kt.planes[2]};
      channels = "R=E";
      axes = "mu,r";
      break;
    case TableKind::AlbedoAvg:
      kt = runner.albedoAvg(job.ndf, job.gaf, job.width, job.nodeGrid);
      img.channels = {"R"};
      img.planes = {kt.planes[0]};
      channels = "R=E_avg";
      break;
    case TableKind::Kp:
      kt = runner.kp(job.ndf, job.width, job.nodeGrid);
      img.channels = {"R"};
      img.planes = {kt.planes[0]};
      channels = "R=k_p";
      break;
  }
  *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  img.width = job.width;
  img.height = job.height;

  // every texel finite, or nothing is written
  for (size_t c = 0; c < img.planes.size(); ++c)
    for (size_t t = 0; t < img.planes[c].size(); ++t)
      if (!std::isfinite(img.planes[c][t]) || !std::isfinite(kt.err[t]))
        throw Error(kExitSoftware, "internal error: " + tableName(job.kind) + " " + ndfNames()[job.ndf] + "+" +
                                       gafNames()[job.gaf] + " texel (" + std::to_string(t % job.width) + ", " +
                                       std::to_string(t / job.width) + ") is not finite; nothing was written");
  double quad = 0;
  for (float e : kt.err) quad = std::max(quad, static_cast<double>(e));
  double storage = 0;
  for (auto& p : img.planes) storage = std::max(storage, storageError(p, job.half));
  double bound = quad + kFloatArithmeticAllowance + storage;

  img.strings["brdf.schema"] = "brdfbake/1";
  img.strings["brdf.table"] = tableName(job.kind);
  img.strings["brdf.ndf"] = ndfNames()[job.ndf];
  img.strings["brdf.gaf"] = gafNames()[job.gaf];
  img.strings["brdf.fresnel"] = fresnel;
  img.strings["brdf.axes"] = axes;
  img.strings["brdf.grid"] = job.nodeGrid ? "node" : "texel-center";
  img.strings["brdf.roughness"] = roughnessMapping(job.ndf);
  img.strings["brdf.channels"] = channels;
  img.strings["brdf.method"] = kMethod;
  img.strings["brdf.generator"] = std::string("brdfbake ") + BRDFBAKE_VERSION + " (git " + BRDFBAKE_GIT_REV + ")";
  img.v2f["brdf.r.range"] = {0.0f, 1.0f};
  if (axes == "mu,r") img.v2f["brdf.mu.range"] = {0.0f, 1.0f};
  img.floats["brdf.error"] = static_cast<float>(bound);
  return img;
}

std::vector<TableReport> runPlan(const Plan& plan) {
  ensureOutputDir(plan.outDir);
  DeviceEntry dev = selectDevice(plan.device);
  KernelRunner runner(dev.device);
  std::vector<TableImage> images;
  std::vector<TableReport> reports;
  for (const TableJob& job : plan.jobs) {
    TableReport r;
    images.push_back(computeTable(runner, job, &r.seconds));
    r.path = job.path;
    r.table = tableName(job.kind);
    r.ndf = ndfNames()[job.ndf];
    r.gaf = gafNames()[job.gaf];
    r.width = job.width;
    r.height = job.height;
    r.errorBound = images.back().floats["brdf.error"];
    reports.push_back(r);
  }
  for (size_t i = 0; i < plan.jobs.size(); ++i) writeTableExr(plan.jobs[i].path, images[i], plan.jobs[i].half);
  return reports;
}

std::string formatReport(const std::vector<TableReport>& reports) {
  std::string s;
  char line[512];
  std::snprintf(line, sizeof line, "%-44s %-10s %9s %10s %9s\n", "file", "table", "size", "max error", "seconds");
  s += line;
  for (const auto& r : reports) {
    std::snprintf(line, sizeof line, "%-44s %-10s %4dx%-4d %10.2e %9.3f\n", r.path.c_str(), r.table.c_str(), r.width,
                  r.height, r.errorBound, r.seconds);
    s += line;
  }
  return s;
}

}  // namespace brdfbake
