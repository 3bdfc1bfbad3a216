// brdfbake-bench --bounds: how tight the claimed error bounds are. For each model pair it bakes
// the default set's tables as brdfbake does (computeTable: split-sum 128x128, albedo 32x32,
// albedo-avg 32, k_p 32 once per NDF; texel centres, float) and measures, against the host
// reference (adaptive GK in double):
//   - per table: the file's brdf.error, the largest true error, and their ratio;
//   - per texel: the claimed bound (what brdf.error is the largest of) over the true error:
//     its smallest value (below 1 = a dishonest bound) and its median;
//   - for the hemisphere tables, the error split into its parts: the float arithmetic
//     |device - the same rule in double| and the quadrature |rule in double - reference|, each
//     beside the part of the bound meant to cover it.
// usage: brdfbake-bench --bounds [--pair NDF+GAF]... [--size N] [--stride K] [--csv FILE]
//   --stride K: the 2D tables' errors on every K-th texel per axis plus every edge texel
//               (default 1: all); the 1D tables always on every entry.
//   --csv FILE: one line per measured texel.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "tables/microfacet/microfacet.h"
#include "bench/bench_util.h"
#include "cl/runner.h"
#include "common/brdf_host.h"
#include "common/errors.h"
#include "brdfbake/table_kind.h"
#include "common/models.h"
#include "reference/reference.h"

namespace brdfbake {

int boundsBench(KernelRunner& runner, const std::vector<std::pair<int, int>>& pairs, int size, int stride,
                const std::string& csv);

namespace {

using bench::onTwoThreads;
using bench::rel;

struct TexelRow {
  int i = 0, j = 0;
  double mu = 0, r = 0;
  double value = 0;  // the largest |value| over the channels measured
  double claim = 0, truth = 0;
  double flt = -1, quad = -1, quadBound = -1;  // hemisphere tables: the parts (-1: not split)
};

struct TableRow {
  std::string pair, table;
  double claimed = 0;  // brdf.error
  std::vector<TexelRow> texels;
};

// The quadrature's own bound of the same rule in double (kernels/integrate/hemisphere.h),
// relative like the kernel's, at the budget the device most likely chose (the one whose double
// value is closer to the device's), and that rule's value in each channel.
struct DoubleRule {
  double v[3];
  double bound;
};
DoubleRule doubleRule(int ndf, int gaf, double mu, double r, int level) {
  brdf64::BrdfParams p = brdf64::hemisphere_texel_params(ndf, gaf, mu, r);
  brdf64::HemiResult h = brdf64::hemisphere_moments(ndf, gaf, p, mu, level);
  return {{h.a, h.b, h.a + h.b}, brdf64::hemi_rel_error(h)};
}

TableRow measure(KernelRunner& runner, TableKind kind, int ndf, int gaf, int n, int stride) {
  TableJob job = TableJob();
  job.kind = kind;
  job.ndf = ndf;
  job.gaf = kind == TableKind::Kp ? GAF_NONE : gaf;
  job.width = n;
  job.height = kind == TableKind::SplitSum || kind == TableKind::Albedo ? n : 1;
  job.nodeGrid = false;
  job.half = false;
  job.path = "bench.exr";
  double secs = 0;
  std::vector<double> bounds;
  TableImage img = computeTable(runner, job, &secs, &bounds);
  TableRow row;
  row.pair = kind == TableKind::Kp ? ndfNames()[ndf] : ndfNames()[ndf] + "+" + gafNames()[gaf];
  row.table = tableName(kind);
  row.claimed = img.floats["brdf.error"];
  const bool twoD = job.height > 1;
  std::vector<std::pair<int, int>> texels;
  if (twoD)
    texels = bench::sampledTexels(n, stride);
  else
    for (int i = 0; i < n; ++i) texels.push_back({i, 0});
  row.texels.resize(texels.size());
  onTwoThreads(texels.size(), [&](size_t k) {
    auto [i, j] = texels[k];
    TexelRow& t = row.texels[k];
    size_t x = static_cast<size_t>(j) * n + i;
    t.i = i;
    t.j = j;
    t.claim = bounds[x];
    if (!twoD) {
      t.r = (i + 0.5) / n;
      double v = img.planes[0][x];
      t.value = std::fabs(v);
      double want = kind == TableKind::Kp ? reference::kp(ndf, t.r) : reference::albedoAvg(ndf, gaf, t.r);
      t.truth = rel(v, want);
      return;
    }
    t.mu = (i + 0.5) / n;
    t.r = (j + 0.5) / n;
    reference::Moments ref = reference::albedo(ndf, gaf, t.r, t.mu);
    const double want[3] = {ref.a, ref.b, ref.e()};
    // split-sum: R = A, G = B, B = A + B; albedo, and sheen's split sum (F = 1): E in every channel
    const bool moments = kind == TableKind::SplitSum && !isSheenNdf(ndf);
    const int c0 = moments ? 0 : 2;
    double got[3];
    for (int c = 0; c < 3; ++c) got[c] = img.planes[moments ? c : 0][x];
    for (int c = c0; c < 3; ++c) {
      t.truth = std::max(t.truth, rel(got[c], want[c]));
      t.value = std::max(t.value, std::fabs(got[c]));
    }
    // the parts: the same rule in double, at the budget the bake picks (hemisphere_moments_to)
    DoubleRule d = doubleRule(ndf, gaf, t.mu, t.r, 0);
    if (d.bound > HEMI_BAKE_TARGET) {
      DoubleRule d1 = doubleRule(ndf, gaf, t.mu, t.r, 1);
      if (d1.bound < d.bound) d = d1;
    }
    t.flt = t.quad = 0;
    t.quadBound = d.bound;
    for (int c = c0; c < 3; ++c) {
      t.flt = std::max(t.flt, rel(got[c], d.v[c]));
      t.quad = std::max(t.quad, rel(d.v[c], want[c]));
    }
  });
  return row;
}

double median(std::vector<double> v) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int boundsBench(KernelRunner& runner, const std::vector<std::pair<int, int>>& pairs, int size, int stride,
                const std::string& csv, const std::vector<TableKind>& tables) {
  // the tables the rows are for (of splitsum, albedo, albedo-avg and kp), or every one
  auto wanted = [&](TableKind kind) {
    return tables.empty() || std::find(tables.begin(), tables.end(), kind) != tables.end();
  };
  std::vector<TableRow> rows;
  std::vector<int> kpDone;
  std::printf(
      "claimed bounds against true errors (reference: adaptive GK in double); split-sum %dx%d on every "
      "%d-th texel + edges, albedo 32x32 likewise, albedo-avg and k_p (32) on every entry\n",
      size, size, stride);
  // a markdown table, as docs/accuracy.md shows it
  std::printf(
      "| pair | table | claimed | true max | ratio | tx min | tx med | over | max flt | max quad | max qbnd |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|\n");
  int over = 0;
  for (auto [ndf, gaf] : pairs) {
    std::vector<std::pair<TableKind, int>> kinds = {
        {TableKind::SplitSum, size}, {TableKind::Albedo, 32}, {TableKind::AlbedoAvg, 32}};
    if (std::find(kpDone.begin(), kpDone.end(), ndf) == kpDone.end()) {
      kinds.push_back({TableKind::Kp, 32});
      kpDone.push_back(ndf);
    }
    for (auto [kind, n] : kinds) {
      if (!wanted(kind)) continue;
      TableRow row =
          measure(runner, kind, ndf, gaf, n, kind == TableKind::SplitSum || kind == TableKind::Albedo ? stride : 1);
      double worst = 0, maxFlt = -1, maxQuad = -1, maxQb = -1;
      std::vector<double> ratios;
      int bad = 0;
      double minRatio = 1e30;
      for (const TexelRow& t : row.texels) {
        worst = std::max(worst, t.truth);
        maxFlt = std::max(maxFlt, t.flt);
        maxQuad = std::max(maxQuad, t.quad);
        maxQb = std::max(maxQb, t.quadBound);
        if (t.truth > t.claim) ++bad;
        if (t.truth > 0) {
          ratios.push_back(t.claim / t.truth);
          minRatio = std::min(minRatio, t.claim / t.truth);
        }
      }
      over += bad;
      auto part = [](double v) {
        char b[16];
        if (v < 0)
          std::snprintf(b, sizeof b, "-");
        else
          std::snprintf(b, sizeof b, "%.2e", v);
        return std::string(b);
      };
      std::printf("| %s | %s | %.2e | %.2e | %.1f | %.2f | %.1f | %d | %s | %s | %s |\n", row.pair.c_str(),
                  row.table.c_str(), row.claimed, worst, row.claimed / std::max(worst, 1e-300), minRatio,
                  median(ratios), bad, part(maxFlt).c_str(), part(maxQuad).c_str(), part(maxQb).c_str());
      std::fflush(stdout);
      rows.push_back(std::move(row));
    }
  }
  std::printf(
      "ratio: brdf.error / largest true error; tx min, tx med: per-texel claim / true error (smallest, "
      "median); over: texels whose true error exceeds their claim; max flt: |device - same rule in "
      "double|; max quad: |rule in double - reference|; max qbnd: the rule's own bound in double\n");
  std::printf("%d texels over their claimed bound\n", over);
  if (!csv.empty()) {
    FILE* f = std::fopen(csv.c_str(), "w");
    if (!f) throw Error(kExitCantCreat, "cannot write " + csv);
    std::fprintf(f, "pair,table,brdf_error,i,j,mu,r,value,claim,true,float,quad,quad_bound\n");
    for (const TableRow& row : rows)
      for (const TexelRow& t : row.texels)
        std::fprintf(f, "%s,%s,%.9g,%d,%d,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", row.pair.c_str(),
                     row.table.c_str(), row.claimed, t.i, t.j, t.mu, t.r, t.value, t.claim, t.truth, t.flt, t.quad,
                     t.quadBound);
    std::fclose(f);
    std::printf("per-texel rows: %s\n", csv.c_str());
  }
  return over == 0 ? 0 : 1;
}

}  // namespace brdfbake
