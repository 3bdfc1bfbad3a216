#include "render/furnace_bounds.h"

#include <algorithm>
#include <cmath>

#include "common/errors.h"

namespace brdfbake {

namespace {
// The texels a clamped bilinear lookup at texture coordinate t reads along an axis of n texels.
void span(double t, int n, int* lo, int* hi) {
  const double x = t * n - 0.5;
  const int i = static_cast<int>(std::floor(x));
  *lo = std::clamp(i, 0, n - 1);
  *hi = std::clamp(i + 1, 0, n - 1);
}
}  // namespace

LocalTable::LocalTable(const Table& t, const std::vector<int>& channels) : w_(t.width), h_(t.height) {
  auto meta = [&](const char* k) { return t.metadata.count(k) ? t.metadata.at(k) : std::string(); };
  if (meta("brdf.grid") != "texel-center" || meta("brdf.mu.index").rfind("sqrt", 0) == 0)
    throw Error(kExitSoftware, "internal: furnace bounds need a texel-centre table with a linear x axis");
  const std::string claim = meta("brdf.error");
  claim_ = (claim.empty() ? 0.0 : std::stod(claim)) * static_cast<double>(channels.size());
  f_.assign(static_cast<size_t>(w_) * h_, 0.0);
  for (int c : channels)
    for (size_t i = 0; i < f_.size(); ++i) f_[i] += t.planes.at(static_cast<size_t>(c))[i];
  // per texel: |second difference|/4 on each axis (h^2/8 |f''| twice over; an edge texel takes its
  // neighbour's), plus on an edge the whole first difference to the next texel (half a texel of
  // slope, twice over) for the lookups that clamp there
  localX_.assign(f_.size(), 0.0);
  localY_.assign(f_.size(), 0.0);
  auto second = [&](int x, int y, int dx, int dy, int n, int k) {
    if (n < 3) return 0.0;
    const int c = std::clamp(k, 1, n - 2), x0 = dx ? c : x, y0 = dy ? c : y;
    return std::fabs(at(x0 - dx, y0 - dy) - 2 * at(x0, y0) + at(x0 + dx, y0 + dy)) / 4;
  };
  for (int y = 0; y < h_; ++y)
    for (int x = 0; x < w_; ++x) {
      double ex = second(x, y, 1, 0, w_, x), ey = second(x, y, 0, 1, h_, y);
      if (w_ > 1 && (x == 0 || x == w_ - 1)) ex += std::fabs(at(x == 0 ? 1 : w_ - 2, y) - at(x, y));
      if (h_ > 1 && (y == 0 || y == h_ - 1)) ey += std::fabs(at(x, y == 0 ? 1 : h_ - 2) - at(x, y));
      localX_[static_cast<size_t>(y) * w_ + x] = ex;
      localY_[static_cast<size_t>(y) * w_ + x] = ey;
    }
}

double LocalTable::value(double u, double v) const {
  const double x = std::clamp(u * w_ - 0.5, 0.0, w_ - 1.0), y = std::clamp(v * h_ - 0.5, 0.0, h_ - 1.0);
  const int x0 = std::min(static_cast<int>(x), w_ - 1), y0 = std::min(static_cast<int>(y), h_ - 1);
  const int x1 = std::min(x0 + 1, w_ - 1), y1 = std::min(y0 + 1, h_ - 1);
  const double fx = x - x0, fy = y - y0;
  return (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x1, y0)) + fy * ((1 - fx) * at(x0, y1) + fx * at(x1, y1));
}

double LocalTable::local(double u, double v, bool alongX, bool alongY) const {
  int x0, x1, y0, y1;
  span(u, w_, &x0, &x1);
  span(v, h_, &y0, &y1);
  double e = 0;
  for (int y : {y0, y1})
    for (int x : {x0, x1}) {
      const size_t i = static_cast<size_t>(y) * w_ + x;
      e = std::max(e, (alongX ? localX_[i] : 0.0) + (alongY ? localY_[i] : 0.0));
    }
  return e;
}

}  // namespace brdfbake
