#include "tables/interp_estimate.h"

#include <algorithm>
#include <cmath>

namespace brdfbake {

InterpEstimate estimateInterpolation(const TableImage& img, bool nodeGrid) {
  InterpEstimate e;
  const int w = img.width, h = img.height;
  for (const auto& p : img.planes) {
    auto at = [&](int x, int y) { return static_cast<double>(p[static_cast<size_t>(y) * w + x]); };
    auto rel = [&](double d, double v) { return std::fabs(d) / std::max(1.0, std::fabs(v)); };
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        double v = at(x, y);
        // h^2/8 |f''| with h = one texel, |f(x-1) - 2 f(x) + f(x+1)|/8, per axis, twice over: a
        // margin for curvature that changes within the cell (measured against the reference:
        // tests/gl_test.cpp, GlPipeline.*)
        if (x > 0 && x + 1 < w) e.interior = std::max(e.interior, rel((at(x - 1, y) - 2 * v + at(x + 1, y)) / 4, v));
        if (y > 0 && y + 1 < h) e.interior = std::max(e.interior, rel((at(x, y - 1) - 2 * v + at(x, y + 1)) / 4, v));
        if (!nodeGrid) {
          // clamped over the half texel beyond the edge texel's centre: about half the slope there,
          // counted whole (the same margin)
          if ((x == 0 || x == w - 1) && w > 1) e.edge = std::max(e.edge, rel(at(x == 0 ? 1 : w - 2, y) - v, v));
          if ((y == 0 || y == h - 1) && h > 1) e.edge = std::max(e.edge, rel(at(x, y == 0 ? 1 : h - 2) - v, v));
        }
      }
  }
  return e;
}

}  // namespace brdfbake
