// brdfbake-bench --all-pairs [--pair NDF+GAF]...: every pair's split-sum table (or the given
// pairs') against the reference on the sampled texels, with the bake's own per-texel claims: each
// table is baked through the library (brdfbake::bake), as `brdfbake bake --table splitsum` makes it.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include "bench/bench_util.h"
#include "brdfbake/brdfbake.h"
#include "brdfbake/table_kind.h"
#include "common/models.h"
#include "reference/reference.h"

namespace brdfbake {
using namespace bench;

// Every pair's n x n texel-centre split-sum table against the reference on the sampled texels
// (only the --pair ones where any are given). Returns 0 if every error is within its bound.
int allPairs(const std::string& device, int n, int stride, const std::vector<std::pair<int, int>>& only) {
  std::vector<std::pair<int, int>> texels = sampledTexels(n, stride);
  std::printf("split-sum %dx%d, %s, errors on %zu texels (stride %d + edges)\n", n, n,
              only.empty() ? "every NDF/GAF pair" : "the given pairs", texels.size(), stride);
  std::printf("%-12s %-20s %12s %12s %10s\n", "ndf", "gaf", "max error", "max claim", "over claim");
  double all = 0;
  int over = 0;
  for (int ndf = 0; ndf < static_cast<int>(ndfNames().size()); ++ndf)
    for (int gaf = 0; gaf < static_cast<int>(gafNames().size()); ++gaf) {
      // (the sheen pairs' reference is reference/sheen_reference.h: tests/tables/microfacet/sheen_test.cpp)
      if (!pairSupported(ndf, gaf) || isSheenNdf(ndf)) continue;
      if (!only.empty() && std::find(only.begin(), only.end(), std::pair{ndf, gaf}) == only.end()) continue;
      BakeRequest req;
      req.ndfs = {ndf};
      req.gafs = {gaf};
      req.tables = {TableKind::SplitSum};
      req.size = n;
      req.device = device;
      Table t = std::move(bake(req).at(0));  // R = A, G = B, B = A + B = E
      std::vector<double> err(texels.size());
      onTwoThreads(texels.size(), [&](size_t k) {
        auto [i, j] = texels[k];
        size_t x = static_cast<size_t>(j) * n + i;
        reference::Moments ref = reference::albedo(ndf, gaf, (j + 0.5) / n, (i + 0.5) / n);
        err[k] = std::max({rel(t.planes[0][x], ref.a), rel(t.planes[1][x], ref.b), rel(t.planes[2][x], ref.e())});
      });
      double worst = 0, bound = 0;
      int bad = 0;
      for (size_t k = 0; k < texels.size(); ++k) {
        size_t x = static_cast<size_t>(texels[k].second) * n + texels[k].first;
        double b = t.texelBounds[x];
        worst = std::max(worst, err[k]);
        bound = std::max(bound, b);
        if (err[k] > b) ++bad;
      }
      all = std::max(all, worst);
      over += bad;
      std::printf("%-12s %-20s %12.2e %12.2e %10d\n", ndfNames()[ndf].c_str(), gafNames()[gaf].c_str(), worst, bound,
                  bad);
    }
  std::printf("%s: largest error %.2e, %d texels over their bound\n", only.empty() ? "all pairs" : "these pairs", all,
              over);
  return over == 0 ? 0 : 1;
}

}  // namespace brdfbake
