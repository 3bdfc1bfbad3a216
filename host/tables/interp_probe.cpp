#include "tables/interp_probe.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/brdf_host.h"
#include "brdfbake/table_kind.h"

namespace brdfbake {

std::vector<ProbePlane> probePlanes(const TableJob& job) {
  const FresnelChoice& fc = job.fresnel;
  const HemiWeight one{};
  if (job.kind == TableKind::SplitSum) {
    if (isSheenNdf(job.ndf)) return {{one, 2}, {one, 2}, {one, 2}};
    if (fc.model == FRESNEL_F82_TINT) return {{one, 0}, {one, 1}, {HemiWeight{HEMI_F82C, 0, 0, 0}, 1}};
    if (job.diffuse >= 0) return {{one, 0}, {one, 1}, {one, -1}};
    return {{one, 0}, {one, 1}, {one, 2}};
  }
  if (job.kind != TableKind::Albedo || job.diffuse >= 0) return {};
  if (fc.isOne()) return {{one, 2}};
  std::vector<ProbePlane> v;
  for (int c = 0; c < fc.channels(); ++c) {
    auto [x, y] = fc.kernelParams(c);
    v.push_back({fresnelWeight(fc.model, x, y), 1});
  }
  return v;
}

double probeInterpolation(KernelRunner& runner, const TableJob& job, const TableImage& img,
                          const std::vector<ProbePlane>& planes, int muTexels) {
  const int nx = img.width, ny = img.height;
  if (nx < 2 || ny < 2 || job.ndf < 0) return 0;
  // the probe points (mu, r), as floats the device evaluates
  std::vector<cl_float4> pts;
  const double rMax = std::max(0.3, 4.0 / ny);
  // The default budget only (a target no estimate exceeds): the lookup errors the probes find are
  // ~0.1 at 128^2 and ~1e-3 where they are smallest, the default budget's bounds ~1e-6, and each
  // point's bound is added to its lookup error below, so the refined budget would move the result
  // by less than its own bound. Measured on the default split sum: the probe takes 0.025 s here
  // against 0.054 s at the refined target, and finds 0.1079173 against 0.1079169 (`brdfbake bake --timings`).
  const float target = 1.0f;
  for (int k = 0; k <= static_cast<int>(std::ceil(rMax * 2 * ny)); ++k) {
    double r = std::min(1.0, k / (2.0 * ny));
    std::vector<double> mus;
    for (int q = 1; q <= 4 * std::min(muTexels, nx); ++q) {  // quarter-texel steps of the x coordinate
      double u = q / (4.0 * nx);
      mus.push_back(job.muSqrt ? u * u : u);
    }
    for (int e = -3; e <= 3; ++e) {  // the grazing layer: mu ~ alpha (and ~ r, charlie's scale)
      mus.push_back(r * r * std::ldexp(1.0, e));
      mus.push_back(r * std::ldexp(1.0, e));
    }
    for (double mu : mus)
      if (mu > 1e-7 && mu <= 1) pts.push_back({{static_cast<float>(mu), static_cast<float>(r), target, 0.0f}});
  }
  // the bilinear lookup a shader makes at (mu, r), as the generated code does (u = sqrt(mu) first
  // on a sqrt axis; texel centres clamp half a texel from the edges)
  auto lookup = [&](const std::vector<float>& p, double mu, double r) {
    const double tx = job.muSqrt ? std::sqrt(mu) : mu;
    const double px = std::clamp(job.nodeGrid ? tx * (nx - 1) : tx * nx - 0.5, 0.0, nx - 1.0);
    const double py = std::clamp(job.nodeGrid ? r * (ny - 1) : r * ny - 0.5, 0.0, ny - 1.0);
    const int x0 = std::min(static_cast<int>(px), nx - 2), y0 = std::min(static_cast<int>(py), ny - 2);
    const double fx = px - x0, fy = py - y0;
    auto at = [&](int x, int y) { return static_cast<double>(p[static_cast<size_t>(y) * nx + x]); };
    return (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x0 + 1, y0)) +
           fy * ((1 - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1));
  };
  double worst = 0;
  std::vector<std::vector<float>> out;
  const HemiWeight* last = nullptr;
  for (size_t c = 0; c < planes.size() && c < img.planes.size(); ++c) {
    const ProbePlane& pl = planes[c];
    if (pl.which < 0) continue;
    if (!last || last->moments != pl.w.moments || last->fresnel != pl.w.fresnel || last->x != pl.w.x ||
        last->y != pl.w.y) {
      out = runner.hemisphereNodes(job.ndf, job.gaf, pts, pl.w);
      last = &pl.w;
    }
    for (size_t k = 0; k < pts.size(); ++k) {
      double a = out[2][k], b = out[3][k];
      double v = pl.which == 0 ? a : pl.which == 1 ? b : a + b;
      if (!std::isfinite(v)) continue;
      // a point whose own bound is unknown leaves the probe's result unknown too
      if (!std::isfinite(out[1][k])) return std::numeric_limits<double>::infinity();
      // out[1]: the point's bound on the weighted moment (HEMI_FRESNEL) or on A + B, which bounds
      // either moment too
      double e = (std::fabs(lookup(img.planes[c], pts[k].s[0], pts[k].s[1]) - v) + std::fabs(out[1][k])) /
                 std::max(1.0, std::fabs(v));
      worst = std::max(worst, e);
    }
  }
  return worst;
}

}  // namespace brdfbake
