#include "tables/table2d.h"

#include <algorithm>
#include <cmath>

#include "tables/error_model.h"
#include "tables/interp_estimate.h"
#include "tables/interp_probe.h"
#include "common/brdf_host.h"
#include "common/errors.h"
#include "formats/storage.h"
#include "version.h"

namespace brdfbake {

std::string modelsOf(const TableJob& job) {
  if (job.ndf < 0) return diffuseNames()[job.diffuse];
  return ndfNames()[job.ndf] + "+" + gafNames()[job.gaf];
}

void addClaims(std::vector<double>& claim, const KernelTable& t, Arith a, int ndf, int gaf, int diffuse) {
  if (claim.empty()) claim.assign(t.err.size(), 0.0);
  for (size_t x = 0; x < t.err.size(); ++x) {
    double scale = 0;
    for (const auto& p : t.planes) scale = std::max(scale, std::fabs(static_cast<double>(p[x])));
    double arith = 0;
    switch (a) {
      case Arith::Hemisphere:
        arith = floatArithmeticError(scale, hemiFloatModel(ndf, gaf));
        break;
      case Arith::HemiWeighted:
      case Arith::HemiWeightedCancel:  // planes: A = int H (1 - w), B = int H w, E = int H
        arith = weightedFloatError(t.planes[1][x], t.planes[2][x], scale, ndf, gaf, a == Arith::HemiWeightedCancel);
        break;
      case Arith::HemiAvg:
        arith = avgFloatArithmeticError(scale, ndf, gaf);
        break;
      case Arith::HemiAvgFresnel:
        arith = avgFloatArithmeticError(scale, ndf, gaf, true);
        break;
      case Arith::Kp:
        arith = floatArithmeticError(scale, kKpFloat);
        break;
      case Arith::HostDouble:
        arith = floatArithmeticError(scale, kRoundToFloat);
        break;
      case Arith::Diffuse:
        arith = floatArithmeticError(scale, diffuseFloatModel(diffuse));
        break;
    }
    claim[x] = std::max(claim[x], static_cast<double>(t.err[x]) + arith);
  }
}

TableImage finishTable2d(KernelRunner* runner, const TableJob& job, Table2d t, std::vector<double>* texelBounds) {
  TableImage& img = t.img;
  std::vector<double>& claim = t.claim;
  // One-value tables repeat it in R, G and B: a lone R channel reads back as zeros through
  // FreeImage, and three.js's EXRLoader takes only R, G, B, A and Y; R, G, B reads everywhere.
  if (img.planes.size() == 1) {
    img.channels = {"R", "G", "B"};
    img.planes = {img.planes[0], img.planes[0], img.planes[0]};
  }
  if (img.channels.empty()) img.channels = {"R", "G", "B"};  // one plane per colour channel
  img.width = job.width;
  img.height = job.height;

  // every texel finite, or nothing is written
  for (size_t c = 0; c < img.planes.size(); ++c)
    for (size_t x = 0; x < img.planes[c].size(); ++x)
      if (!std::isfinite(img.planes[c][x]) || !std::isfinite(claim[x]))
        throw Error(kExitSoftware, "internal error: " + tableName(job.kind) + " " + modelsOf(job) + " texel (" +
                                       std::to_string(x % job.width) + ", " + std::to_string(x / job.width) +
                                       ") is not finite; nothing was written");
  // each texel's claim plus the file's storage rounding (formats/storage.h: the largest over the
  // table; 0 in float32, which holds the kernels' floats exactly, and whose rounding to float every
  // claim above already holds); the file's brdf.error is the largest
  double storage = 0;
  for (auto& p : img.planes)
    storage = std::max(storage, storageError(p, job.half ? Precision::Float16 : Precision::Float32));
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
  img.strings["brdf.axes"] = t.axes;
  img.strings["brdf.grid"] = job.nodeGrid ? "node" : "texel-center";
  img.strings["brdf.generator"] = std::string("brdfbake ") + BRDFBAKE_VERSION + " (git " + BRDFBAKE_GIT_REV + ")";
  if (t.axes == "mu,r") img.v2f["brdf.mu.range"] = {0.0f, 1.0f};
  // the x texels' spacing, stated on every table over (mu, ...): shader code and readers apply u = sqrt(mu)
  if (t.axes.rfind("mu,", 0) == 0)
    img.strings["brdf.mu.index"] = job.muSqrt ? "sqrt (x = sqrt(mu): texel i holds mu = x_i^2)" : "linear (x = mu)";
  img.floats["brdf.error"] = static_cast<float>(bound);
  // what the resolution costs a bilinear lookup (estimated from the table; brdf3d tables measure it)
  InterpEstimate ie = estimateInterpolation(img, job.nodeGrid);
  std::vector<ProbePlane> probe = runner ? probePlanes(job) : std::vector<ProbePlane>{};  // and measured between texels
  double probed = probe.empty() ? 0 : probeInterpolation(*runner, job, img, probe);
  img.floats["brdf.interp-error"] = static_cast<float>(std::max(ie.total(), kProbeMargin * probed));
  img.floats["brdf.interp-error.interior"] = static_cast<float>(ie.interior);
  if (!probe.empty()) img.floats["brdf.interp-error.probe"] = static_cast<float>(probed);
  return img;
}

}  // namespace brdfbake
