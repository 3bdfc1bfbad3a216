// What a furnace pixel's lookups read and how far that can be from the functions the tables sample,
// near the pixel: the bound each measured row of `brdfbake render` holds its pixels to.
//
// A texel-centre table looked up by GL's bilinear, clamped-to-edge texture() reads the 2 x 2
// texels around (u, v) (one texel or two beyond the outer centres). Its error there is at most the
// texels' claims (brdf.error) plus what the interpolation adds over that cell: the leading term of
// linear interpolation's error, h^2/8 (|f_xx| + |f_yy|), from the texels' second differences, and in
// the clamp region beyond an edge texel's centre up to half a texel of the slope there, each counted
// twice (the margin tables/interp_estimate.h measured). Local, where the table's brdf.interp-error is
// the largest over the whole table (one corner's value, 0.16 for ggx's albedo at 32^2).
#pragma once
#include <vector>

#include "brdfbake/brdfbake.h"

namespace brdfbake {

class LocalTable {
 public:
  // The sum of `channels` of a texel-centre table whose x texels are spaced linearly (brdf.mu.index
  // linear); Error(kExitSoftware) for a node grid or a sqrt(mu) axis, which the furnace never bakes.
  LocalTable(const Table& t, const std::vector<int>& channels);
  // GL's bilinear, clamped-to-edge lookup at (u, v) in [0, 1]^2, in double.
  double value(double u, double v) const;
  // The bound on |value(u, v) - f(u, v)|: the claims of the texels read plus the local interpolation
  // terms of the cell on both axes (the clamp term where the lookup clamps).
  double error(double u, double v) const { return claim_ + local(u, v, true, true); }
  // The bound on |value(u, v) - l(u, v)|, l the linear interpolation in v of f on the two rows the
  // lookup reads: the claims plus the x axis' interpolation term only. What matters where two tables
  // share the v grid and their v interpolations cancel (the Kulla-Conty row's albedo and albedo-avg).
  double errorAlongX(double u, double v) const { return claim_ + local(u, v, true, false); }
  double claim() const { return claim_; }
  int width() const { return w_; }
  int height() const { return h_; }

 private:
  int w_ = 0, h_ = 0;
  double claim_ = 0;
  std::vector<double> f_, localX_, localY_;
  double local(double u, double v, bool x, bool y) const;
  double at(int x, int y) const { return f_[static_cast<size_t>(y) * w_ + x]; }
};

}  // namespace brdfbake
