// The interpolation error a 2D (or 1D) table's resolution costs a bilinear lookup, estimated from
// the table itself: inside, the leading term of linear interpolation's error, h^2/8 |f''| per axis,
// from second differences (the error is largest at cell centres); at the edges of a texel-center
// table the lookup clamps within half a texel of the edge, which costs about half the first
// difference there. Both counted twice, a margin. Relative to max(1, |value|), every channel. An
// estimate, not a bound: the tests compare it with lookups against the reference (tests/gl_test.cpp).
// Differences are taken texel to texel, in whatever coordinate the texels are spaced: on a
// --mu-axis sqrt table (brdf.mu.index sqrt) that is u = sqrt(mu), the coordinate the lookup
// interpolates in (u = sqrt(mu), then bilinear), so the estimate is of that lookup. Its limit, on
// every axis: what no texel holds it cannot see, as the dip of E where mu ~ alpha = r^2 towards the
// corner (0, 0), up to 0.11 off at 64^2 (tests/mu_axis_test.cpp measures it; docs/layouts.md "The sqrt(mu) axis").
#pragma once
#include "formats/table_image.h"

namespace brdfbake {

struct InterpEstimate {
  double interior = 0;  // second-difference term
  double edge = 0;      // texel-center clamp term (0 on node grids)
  double total() const { return interior > edge ? interior : edge; }
};

InterpEstimate estimateInterpolation(const TableImage& img, bool nodeGrid);

}  // namespace brdfbake
