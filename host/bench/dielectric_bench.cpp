// brdfbake-bench --dielectric: the 32^3 rough-dielectric table (ggx + smith-correlated, texel
// centres, eta in [0.4, 2.5] uniform in s = (eta - 1)/(eta + 1), as `brdfbake --table dielectric`
// bakes it) timed against a Monte Carlo estimator with the budget renderers use for their glass
// tables (Cycles: 2^23 samples per cell), in the same run. MC on 27 documented cells (3 per axis)
// and its time scaled to the whole table; both against the independent o-space reference
// (reference/dielectric_reference.h) on those cells.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "tables/dielectric_avg.h"
#include "tables/dielectric/dielectric_bake.h"
#include "bench/bench_util.h"
#include "tables/mc_common.h"
#include "cl/runner.h"
#include "common/brdf_host.h"
#include "common/models.h"
#include "reference/dielectric_reference.h"

namespace brdfbake {
namespace {

// GGX Smith Lambda (Heitz 2014 eq. 72) of a direction with cosine c (either side).
double ggxLambda(double a2, double c) {
  c = std::fabs(c);
  return 0.5 * (std::sqrt(1 + a2 * (1 - c * c) / (c * c)) - 1);
}

// Exact unpolarised dielectric Fresnel (Walter et al. 2007 eq. 22), c = |i.m|, relative IOR eta.
double fresnel(double eta, double c) {
  double g2 = (eta - 1) * (eta + 1) + c * c;
  if (g2 < 0) return 1;
  double g = std::sqrt(g2), a = (g - c) / (g + c), b = (c * (g + c) - 1) / (c * (g - c) + 1);
  return 0.5 * a * a * (1 + b * b);
}

struct Vec {
  double x, y, z;
};
double dot(Vec a, Vec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// The renderers' estimator (Walter et al. 2007 sec. 5.3): m sampled from D(m) (m.n) (GGX:
// tan^2 theta_m = alpha^2 u1/(1 - u1), phi = 2 pi u2; Hammersley points), o reflected about m or
// refracted through it (Walter eq. 40), weight |i.m| G/(|i.n| |m.n|) (Walter eq. 41). Both branches
// are scored, with weights F and 1 - F, instead of choosing one at random. Height-correlated G:
// 1/(1 + L_i + L_o) reflected (Heitz 2014 eq. 99), B(1 + L_i, 1 + L_o) transmitted.
void monteCarlo(double mu, double r, double eta, int samples, double* er, double* et) {
  double a2 = r * r * r * r, li = ggxLambda(a2, mu);
  Vec i{std::sqrt((1 - mu) * (1 + mu)), 0, mu};
  double sr = 0, st = 0;
  for (int k = 0; k < samples; ++k) {
    double u1 = (k + 0.5) / samples, u2 = mc::radicalInverse2(static_cast<std::uint32_t>(k));
    double t2 = a2 * u1 / (1 - u1), cm = 1 / std::sqrt(1 + t2), sm = std::sqrt(t2) * cm, phi = 2 * M_PI * u2;
    Vec m{sm * std::cos(phi), sm * std::sin(phi), cm};
    double c = dot(i, m);
    if (c <= 0) continue;
    double f = fresnel(eta, c), w = c / (mu * cm);
    Vec o{2 * c * m.x - i.x, 2 * c * m.y - i.y, 2 * c * m.z - i.z};
    if (o.z > 0) sr += f * w / (1 + li + ggxLambda(a2, o.z));
    double d = 1 + (c * c - 1) / (eta * eta);
    if (d <= 0) continue;  // total internal reflection
    double kk = c / eta - std::sqrt(d);
    Vec t{kk * m.x - i.x / eta, kk * m.y - i.y / eta, kk * m.z - i.z / eta};
    if (t.z >= 0 || dot(t, m) >= 0) continue;
    double lo = ggxLambda(a2, t.z);
    double g = std::exp(std::lgamma(1 + li) + std::lgamma(1 + lo) - std::lgamma(2 + li + lo));
    st += (1 - f) * w * g;
  }
  *er = sr / samples;
  *et = st / samples;
}
}  // namespace

int dielectricBench(KernelRunner& runner, int samplesLog2) {
  const int n = 32, ndf = NDF_GGX, gaf = GAF_SMITH_CORRELATED, samples = 1 << samplesLog2;
  DielectricJob job;
  job.ndf = ndf;
  job.gaf = gaf;
  std::vector<double> etas = dielectricEtas(job, 0, n);
  dielectricSlab(runner, ndf, gaf, 1, 1, {1.5}, false, kDielectricTarget);  // builds the program: not timed
  auto t0 = std::chrono::steady_clock::now();
  auto table = dielectricSlab(runner, ndf, gaf, n, n, etas, false, kDielectricTarget);
  double tTable = bench::seconds(t0);
  double maxBound = 0;
  for (float b : table[2]) maxBound = std::max(maxBound, static_cast<double>(b));

  const int pick[3] = {1, 15, 29};  // texel indices of each axis (mu, r, eta) the MC and the reference run at
  struct Cell {
    int x, y, z;
    double mu, r, eta, mcR, mcT, refR, refT;
  };
  std::vector<Cell> cells;
  for (int z : pick)
    for (int y : pick)
      for (int x : pick) cells.push_back({x, y, z, (x + 0.5) / n, (y + 0.5) / n, etas[z], 0, 0, 0, 0});
  t0 = std::chrono::steady_clock::now();
  bench::onTwoThreads(cells.size(), [&](size_t k) {
    monteCarlo(cells[k].mu, cells[k].r, cells[k].eta, samples, &cells[k].mcR, &cells[k].mcT);
  });
  double tMc = bench::seconds(t0);
  bench::onTwoThreads(cells.size(), [&](size_t k) {
    auto ref = reference::dielectricAlbedo(ndf, gaf, cells[k].mu, cells[k].r, cells[k].eta);
    cells[k].refR = ref.r;
    cells[k].refT = ref.t;
  });

  std::printf("rough dielectric, ggx + smith-correlated, %d^3 texel centres, eta in [%.1f, %.1f] uniform in s\n", n,
              job.etaLo, job.etaHi);
  std::printf("%4s %4s %4s %7s %6s %7s | %11s %11s | %9s %9s | %9s %9s\n", "x", "y", "z", "mu", "r", "eta", "ref E_R",
              "ref E_T", "table err", "(bound)", "MC err", "MC/table");
  double tabMax = 0, mcMax = 0, tabSq = 0, mcSq = 0;
  for (const Cell& c : cells) {
    size_t k = (static_cast<size_t>(c.z) * n + c.y) * n + c.x;
    double te = std::max(bench::rel(table[0][k], c.refR), bench::rel(table[1][k], c.refT));
    double me = std::max(bench::rel(c.mcR, c.refR), bench::rel(c.mcT, c.refT));
    tabMax = std::max(tabMax, te);
    mcMax = std::max(mcMax, me);
    tabSq += te * te;
    mcSq += me * me;
    std::printf("%4d %4d %4d %7.4f %6.4f %7.4f | %11.8f %11.8f | %9.2e %9.2e | %9.2e %9.1f\n", c.x, c.y, c.z, c.mu, c.r,
                c.eta, c.refR, c.refT, te, table[2][k], me, me / std::max(te, 1e-12));
  }
  double cellsAll = static_cast<double>(n) * n * n, nc = static_cast<double>(cells.size());
  std::printf(
      "table (device, double, adaptive): %.2f s for %d cells (%.3f ms/cell); error against the reference max "
      "%.2e rms %.2e on the %zu cells; largest bound of the table %.2e\n",
      tTable, n * n * n, 1e3 * tTable / cellsAll, tabMax, std::sqrt(tabSq / nc), cells.size(), maxBound);
  std::printf(
      "Monte Carlo (host, 2 threads, 2^%d samples per cell): %.2f s for %zu cells -> %.0f s for the whole "
      "table (scaled); error max %.2e rms %.2e\n",
      samplesLog2, tMc, cells.size(), tMc * cellsAll / nc, mcMax, std::sqrt(mcSq / nc));
  std::printf("table / MC: %.1fx faster, %.0fx smaller max error\n", tMc * cellsAll / nc / tTable,
              mcMax / std::max(tabMax, 1e-12));
  return tabMax <= maxBound + 1e-6 ? 0 : 1;
}

}  // namespace brdfbake

namespace brdfbake {

// brdfbake-bench --dielectric-avg [--size N] [--pair NDF+GAF]: how tight dielectric-avg's claim is.
// The N x N table (default 8, ggx + smith-correlated, eta in [0.4, 2.5]) baked as brdfbake bakes it
// (computeDielectric: float storage, brdf.error), every stored value (E_R,avg, E_T,avg, their sum)
// against the same rule run tight on the device: nodes to 2e-9 per lobe, entries to 1e-8. That
// reference is not independent of the kernel (the E(mu) it averages is checked against the o-space
// reference by Dielectric.KernelMatchesReference); its own largest bound is printed. Exit 1 if an
// error exceeds brdf.error plus that bound.
int dielectricAvgBench(KernelRunner& runner, int n, int ndf, int gaf) {
  DielectricJob job;
  job.ndf = ndf;
  job.gaf = gaf;
  job.avg = true;
  job.nx = job.ny = n;
  job.nz = 1;
  dielectricPoints(runner, ndf, gaf, {0.5}, {0.5}, {1.5}, kDielectricAvgNodeTarget);  // builds the program: not timed
  double tBake = 0;
  DielectricTable table = computeDielectric(runner, job, &tBake);
  std::vector<double> etas = dielectricEtas(job, 0, n), rs, es;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      rs.push_back((x + 0.5) / n);
      es.push_back(etas[y]);
    }
  std::fprintf(stderr, "dielectric-avg: baked in %.1f s; the tight reference (%d entries) takes about %d s more...\n",
               tBake, n * n, 3 * n * n);
  auto t0 = std::chrono::steady_clock::now();
  DielectricAverages ref = dielectricAverages(dielectricDeviceEval(runner, ndf, gaf, 2e-9f), rs, es, 1e-8);
  double tRef = bench::seconds(t0);
  const TableImage& img = table.image;
  const double claim = img.floats.at("brdf.error");
  double worst = 0, refBound = 0;
  size_t at = 0;
  int channel = 0, over = 0;
  for (size_t j = 0; j < rs.size(); ++j) {
    const double want[3] = {ref.er[j], ref.et[j], ref.er[j] + ref.et[j]};
    refBound = std::max(refBound, ref.bound[j]);
    for (int c = 0; c < 3; ++c) {
      double e = std::fabs(img.planes[c][j] - want[c]);
      if (e > claim) ++over;
      if (e > worst) worst = e, at = j, channel = c;
    }
  }
  const char* names[3] = {"E_R,avg", "E_T,avg", "E_R,avg + E_T,avg"};
  std::printf("dielectric-avg %dx%d, %s + %s, eta in [%.1f, %.1f] uniform in s\n", n, n, ndfNames()[ndf].c_str(),
              gafNames()[gaf].c_str(), job.etaLo, job.etaHi);
  std::printf(
      "bake (as brdfbake bakes it): %.1f s, %lld E(mu) evaluations; reference (the same rule, tight): %.1f s, "
      "its largest bound %.2e\n",
      tBake, table.nodes, tRef, refBound);
  std::printf(
      "largest error of a stored value %.3e (%s at r %.4f, eta %.4f); brdf.error %.3e (quadrature %.3e): "
      "claim / error %.2f; values over the claim: %d\n",
      worst, names[channel], rs[at], es[at], claim, img.floats.at("brdf.error.quadrature"),
      claim / std::max(worst, 1e-300), over);
  return worst <= claim + refBound ? 0 : 1;
}

}  // namespace brdfbake
