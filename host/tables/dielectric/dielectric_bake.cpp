#include "tables/dielectric/dielectric_bake.h"

#include <Imath/half.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>

#include "tables/dielectric_avg.h"
#include "tables/volume.h"
#include "cl/runner.h"
#include "common/brdf_host.h"
#include "common/errors.h"
#include "common/format.h"
#include "common/models.h"
#include "version.h"

namespace brdfbake {

namespace {
// The device program runs in double (cl_khr_fp64; PoCL has it). Its arithmetic, measured: the
// device's float values equal the host's double rule rounded to float at every one of 2048 texels
// (16^2 at 8 etas from 0.4 to 2.5), so the two differ by far less than a float's
// half-ulp; 1e-9 covers that with room. Without fp64 it runs in float, for which the 2D tables' unmeasured 1e-6
// allowance is kept.
constexpr double kDoubleAllowance = 1e-9, kFloatAllowance = 1e-6;
// The 3D table's storage: the device rounds E_R and E_T to float, 2^-25 for values below 1, and
// E_R + E_T is summed from those in float: three roundings. Half rounds each float once more, 2^-12
// below 1.
double storageRounding(bool half) { return 3 * std::ldexp(1.0, -25) + (half ? std::ldexp(1.0, -12) : 0.0); }

// The value a float entry is stored as (float, or half: the EXR writer's Imath conversion).
double stored(float v, bool half) { return half ? static_cast<float>(Imath::half(v)) : v; }

std::string coordText() {
  return "s = (eta - 1)/(eta + 1) = sign(eta - 1) sqrt(F0), F0 = ((eta - 1)/(eta + 1))^2 the normal-incidence "
         "reflectance; sampled uniformly in s (texel centres or nodes), eta = (1 + s)/(1 - s)";
}

std::string methodText(bool avg) {
  std::string m =
      "h-space quadrature in double on the device (kernels/integrate/dielectric.h): theta_h on the NDF's CDF "
      "coordinate, phi split at every x = i.h feature (domain edges, TIR at sqrt(1 - eta^2), n.o_t = 0, a graded "
      "Fresnel layer of width sqrt(|eta^2 - 1|) near eta = 1), GK15 panels under a smoothstep substitution, outer "
      "axis refined adaptively; bound per texel: |K15 - G7| rescaled as QUADPACK's qk15 does, panels and inner panels, "
      "plus a floor of 1e-9 of the value, E_R's and E_T's summed";
  if (avg)
    m += "; averages 2 int E mu dmu by an adaptive rule in mu (host/tables/dielectric_avg.cpp): panels split at the "
         "critical cosine sqrt(1 - eta^2), at mu = eta and at 16 alpha, smoothstep-mapped GK15, halved where the "
         "estimate is largest, nodes per (r, eta), each to 1e-7 per lobe; bound: the panels' rescaled |K15 - G7| "
         "(|K15 - G7| on panels starting within 16 alpha above 0 or above the critical cosine) + weighted node "
         "bounds, E_R's and E_T's summed; brdf.error: the largest of each entry's bound plus its own rounding to "
         "the stored precision, + arithmetic allowance";
  return m + (avg ? "" : "; brdf.error: the largest bound + arithmetic allowance + storage rounding");
}
}  // namespace

double dielectricCoord(double eta) { return (eta - 1) / (eta + 1); }
double dielectricEta(double s) { return (1 + s) / (1 - s); }

std::vector<double> dielectricEtas(const DielectricJob& job, int z0, int n) {
  int nz = job.avg ? job.ny : job.nz;
  double s0 = dielectricCoord(job.etaLo), s1 = dielectricCoord(job.etaHi);
  std::vector<double> etas(n);
  for (int k = 0; k < n; ++k) {
    int z = z0 + k;
    double t = job.nodeGrid ? (nz > 1 ? static_cast<double>(z) / (nz - 1) : 0.0) : (z + 0.5) / nz;
    etas[k] = z == 0 && job.nodeGrid ? job.etaLo
                                     : (job.nodeGrid && z == nz - 1 ? job.etaHi : dielectricEta(s0 + (s1 - s0) * t));
  }
  return etas;
}

namespace {
const char* const kSlabKernel = "bake_dielectric";
const char* const kPointsKernel = "bake_dielectric_points";

// One of the rough dielectric's kernels, in the pair's dielectric program, with its warm arguments.
KernelNeed dielectricNeed(const char* kernel, int ndf, int gaf, std::vector<LaunchArg> warm) {
  return {KernelNeed::Own, ndf, gaf, ProgramKey::Dielectric, kernel, std::move(warm)};
}
}  // namespace

KernelNeed dielectricKernel(int ndf, int gaf) {
  using A = LaunchArg;
  // (out, etas, nx, ny, zn, grid, target): zn = 0, nothing to do
  return dielectricNeed(kSlabKernel, ndf, gaf,
                        {A::output(0), A::noInput(A::InReals), A::of(0), A::of(0), A::of(0), A::of(0), A::of(0.0f)});
}

KernelNeed dielectricPointsKernel(int ndf, int gaf) {
  using A = LaunchArg;
  // (out, mus, rs, etas, n, target): n = 0, nothing to do
  return dielectricNeed(kPointsKernel, ndf, gaf,
                        {A::outputReals(0), A::noInput(A::InReals), A::noInput(A::InReals), A::noInput(A::InReals),
                         A::of(0), A::of(0.0f)});
}

std::vector<std::vector<float>> dielectricSlab(KernelRunner& runner, int ndf, int gaf, int nx, int ny,
                                               const std::vector<double>& etas, bool nodeGrid, float target) {
  const int zn = static_cast<int>(etas.size());
  const size_t plane = static_cast<size_t>(nx) * ny * zn;
  using A = LaunchArg;
  std::vector<float> all =
      runner
          .launch(ProgramKey::Dielectric, ndf, gaf, kSlabKernel,
                  LaunchShape{static_cast<size_t>(nx), static_cast<size_t>(ny) * zn, LaunchShape::Texels},
                  {A::output(plane * 3), A::inputReals(etas), A::of(nx), A::of(ny), A::of(zn), A::of(nodeGrid ? 1 : 0),
                   A::of(target)})
          .floats.at(0);
  std::vector<std::vector<float>> planes(3);
  for (int ch = 0; ch < 3; ++ch)
    planes[ch].assign(all.begin() + static_cast<std::ptrdiff_t>(ch * plane),
                      all.begin() + static_cast<std::ptrdiff_t>((ch + 1) * plane));
  return planes;
}

std::vector<std::vector<double>> dielectricPoints(KernelRunner& runner, int ndf, int gaf,
                                                  const std::vector<double>& mus, const std::vector<double>& rs,
                                                  const std::vector<double>& etas, float target) {
  const size_t n = mus.size();
  std::vector<std::vector<double>> planes(4);
  if (n == 0) return planes;
  using A = LaunchArg;
  std::vector<double> all =
      runner
          .launch(ProgramKey::Dielectric, ndf, gaf, kPointsKernel, LaunchShape{n, 0, LaunchShape::Texels},
                  {A::outputReals(n * 4), A::inputReals(mus), A::inputReals(rs), A::inputReals(etas),
                   A::of(static_cast<int>(n)), A::of(target)})
          .reals.at(0);
  for (size_t ch = 0; ch < 4; ++ch)
    planes[ch].assign(all.begin() + static_cast<std::ptrdiff_t>(ch * n),
                      all.begin() + static_cast<std::ptrdiff_t>((ch + 1) * n));
  return planes;
}

DielectricEval dielectricDeviceEval(KernelRunner& runner, int ndf, int gaf, float target) {
  return [&runner, ndf, gaf, target](const DielectricPoints& p) {
    auto pl = dielectricPoints(runner, ndf, gaf, p.mu, p.r, p.eta, target);
    return DielectricValues{pl[0], pl[1], pl[2], pl[3]};
  };
}

DielectricTable computeDielectric(KernelRunner& runner, const DielectricJob& job, double* seconds) {
  auto t0 = std::chrono::steady_clock::now();
  DielectricTable out;
  TableImage& img = out.image;
  // per texel or entry: the quadrature's bound, and the claim (with storage rounding) it makes
  std::vector<double> quadrature, claims;
  if (job.avg) {
    // the averages' rule (tables/dielectric_avg.h) on (r, eta) = (x, y), its nodes on the device
    std::vector<double> etas = dielectricEtas(job, 0, job.ny), rs, es;
    for (int y = 0; y < job.ny; ++y)
      for (int x = 0; x < job.nx; ++x) {
        rs.push_back(job.nodeGrid ? (job.nx > 1 ? static_cast<double>(x) / (job.nx - 1) : 0.0) : (x + 0.5) / job.nx);
        es.push_back(etas[y]);
      }
    DielectricAverages av = dielectricAverages(
        dielectricDeviceEval(runner, job.ndf, job.gaf, kDielectricAvgNodeTarget), rs, es, kDielectricAvgTarget,
        [&runner](double settled, double total) { runner.progress("entries settled", settled, total); });
    // The averages are formed in double from the nodes' unrounded values (in float without fp64:
    // the float allowance covers that) and rounded once as stored, so each entry's storage term
    // is its own rounding, known exactly: a channel's claim is its bound plus that.
    img.planes.assign(3, std::vector<float>(rs.size()));
    for (size_t t = 0; t < rs.size(); ++t) {
      const double v[3] = {av.er[t], av.et[t], av.er[t] + av.et[t]}, b[3] = {av.br[t], av.bt[t], av.bound[t]};
      double claim = 0;
      for (int c = 0; c < 3; ++c) {
        img.planes[c][t] = static_cast<float>(v[c]);
        claim = std::max(claim, b[c] + std::fabs(stored(img.planes[c][t], job.half) - v[c]));
      }
      quadrature.push_back(av.bound[t]);
      claims.push_back(claim);
      out.nodes += av.nodes[t];
    }
    img.width = job.nx;
    img.height = job.ny;
  } else {
    out.cube.assign(3, {});
    for (int z0 = 0; z0 < job.nz; z0 += job.cols) {
      int zn = std::min(job.cols, job.nz - z0);
      auto p = dielectricSlab(runner, job.ndf, job.gaf, job.nx, job.ny, dielectricEtas(job, z0, zn), job.nodeGrid,
                              kDielectricTarget);
      runner.progress("eta slices", z0 + zn, job.nz);
      out.cube[0].insert(out.cube[0].end(), p[0].begin(), p[0].end());
      out.cube[1].insert(out.cube[1].end(), p[1].begin(), p[1].end());
      for (float b : p[2]) {
        quadrature.push_back(b);
        claims.push_back(b + storageRounding(job.half));
      }
    }
    out.cube[2].resize(out.cube[0].size());
    for (size_t t = 0; t < out.cube[0].size(); ++t) out.cube[2][t] = out.cube[0][t] + out.cube[1][t];
    img.width = job.nx * job.cols;
    img.height = job.ny * job.rows;
  }
  if (seconds) *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const std::string what =
      std::string(job.avg ? "dielectric-avg " : "dielectric ") + ndfNames()[job.ndf] + "+" + gafNames()[job.gaf];
  for (const auto& p : job.avg ? img.planes : out.cube)
    for (float v : p)
      if (!std::isfinite(v))
        throw Error(kExitSoftware, "internal error: " + what + " has a value that is not finite; nothing was written");
  double maxClaim = 0;
  for (size_t t = 0; t < claims.size(); ++t) {
    if (!std::isfinite(claims[t]))
      throw Error(kExitSoftware, "internal error: " + what + " has a bound that is not finite; nothing was written");
    out.maxBound = std::max(out.maxBound, quadrature[t]);
    maxClaim = std::max(maxClaim, claims[t]);
  }

  img.channels = {"R", "G", "B"};
  auto& str = img.strings;
  str["brdf.schema"] = "brdfbake/1";
  str["brdf.table"] = job.avg ? "dielectric-avg" : "dielectric";
  str["brdf.ndf"] = ndfNames()[job.ndf];
  str["brdf.gaf"] = gafNames()[job.gaf];
  str["brdf.roughness"] = roughnessMapping(job.ndf);
  str["brdf.fresnel"] = "dielectric";
  str["brdf.btdf"] = "Walter et al. 2007; transmission G: " +
                     std::string(job.gaf == GAF_SMITH ? "G1(i) G1(o)" : "B(1 + Lambda_i, 1 + Lambda_o) (Heitz 2014)");
  str["brdf.axes"] = job.avg ? "r,s" : "mu,r,s";
  str["brdf.eta.coordinate"] = coordText();
  img.v2f["brdf.eta.range"] = {static_cast<float>(job.etaLo), static_cast<float>(job.etaHi)};
  img.v2f["brdf.s.range"] = {static_cast<float>(dielectricCoord(job.etaLo)),
                             static_cast<float>(dielectricCoord(job.etaHi))};
  img.v2f["brdf.r.range"] = {0.0f, 1.0f};
  if (!job.avg) img.v2f["brdf.mu.range"] = {0.0f, 1.0f};
  str["brdf.grid"] = job.nodeGrid ? "node" : "texel-center";
  str["brdf.size"] = job.avg ? std::to_string(job.nx) + "x" + std::to_string(job.ny)
                             : std::to_string(job.nx) + "x" + std::to_string(job.ny) + "x" + std::to_string(job.nz);
  if (!job.avg) {
    str["brdf.atlas"] = std::to_string(job.cols) + "x" + std::to_string(job.rows);
    img.floats["brdf.depth"] = static_cast<float>(job.nz);
    str["brdf.atlas.order"] = "slice z (eta axis) at column z % " + std::to_string(job.cols) + ", row z / " +
                              std::to_string(job.cols) + "; texel (x = mu, y = r) of a slice at pixel (column * " +
                              std::to_string(job.nx) + " + x, row * " + std::to_string(job.ny) +
                              " + y); unused slots hold 0";
  }
  str["brdf.channels"] = job.avg ? "R = E_R,avg, G = E_T,avg (2 int E mu dmu), B = E_R,avg + E_T,avg"
                                 : "R = E_R (reflected albedo), G = E_T (transmitted albedo: the fraction of energy "
                                   "transmitted, eta^2 radiance factor included), B = E_R + E_T (<= 1)";
  str["brdf.method"] = methodText(job.avg);
  str["brdf.generator"] = std::string("brdfbake ") + BRDFBAKE_VERSION + " (git " + BRDFBAKE_GIT_REV + ")";
  double allowance = runner.hasDouble() ? kDoubleAllowance : kFloatAllowance;
  img.floats["brdf.error"] = static_cast<float>(maxClaim + allowance);
  img.floats["brdf.error.quadrature"] = static_cast<float>(out.maxBound);
  return out;
}

OutputFile dielectricOutput(const DielectricJob& job, const DielectricTable& table) {
  OutputFile f;
  f.path = job.path;
  f.half = job.half;
  if (job.avg) {
    f.image = &table.image;
    return f;
  }
  const DielectricTable* t = &table;
  f.write = [t, job](const std::string& tmp) {
    size_t slice = static_cast<size_t>(job.nx) * job.ny;
    auto slab = [t, slice](int z0, int zn) {
      std::vector<std::vector<float>> p(3);
      for (int c = 0; c < 3; ++c)
        p[c].assign(t->cube[c].begin() + static_cast<std::ptrdiff_t>(z0 * slice),
                    t->cube[c].begin() + static_cast<std::ptrdiff_t>((z0 + zn) * slice));
      return p;
    };
    writeAtlasTemporary(tmp, job.path, t->image, job.half, {job.nx, job.ny, job.nz}, job.cols, slab,
                        "dielectric " + ndfNames()[job.ndf] + "+" + gafNames()[job.gaf]);
  };
  return f;
}

}  // namespace brdfbake
