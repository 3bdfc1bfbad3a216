// The reference's mirror limits (r = 0), derived by hand; checked against the reference's own
// integral approached from inside in tests/models_test.cpp.
#include <cmath>

#include "common/brdf_host.h"
#include "reference/reference.h"

namespace brdfbake::reference {

// Derived by hand: with alpha -> 0 at mu > 0, E = int D (G/no) F (o.h) dw_h concentrates at h = n,
// where i = (-s, 0, mu): n.i = n.o = o.h = i.h = mu, n.h = 1, so E = (G/mu) mu = G there:
//   none, cook-torrance (min(1, 2, 2)), kelemen (mu^2/mu^2): 1; implicit: mu^2; neumann: mu;
//   ashikhmin-premoze: mu^2/(2 mu - mu^2) = mu/(2 - mu); Schlick with k -> 0: 1, and
//   schlick-ggx-direct, whose k = (r + 1)^2/8 -> 1/8: (mu/(mu (1 - k) + k))^2;
//   smith, smith-correlated: Lambda -> 0 for every direction above the horizon, so 1.
Moments mirrorAlbedo(int gaf, double mu, const Weight& w) {
  double e = 1;
  switch (gaf) {
    case GAF_IMPLICIT:
      e = mu * mu;
      break;
    case GAF_NEUMANN:
      e = mu;
      break;
    case GAF_ASHIKHMIN_PREMOZE:
      e = mu / (2 - mu);
      break;
    case GAF_SCHLICK_GGX_DIRECT: {
      double g = mu / (mu * 7 / 8 + 1.0 / 8);
      e = g * g;
      break;
    }
    default:
      break;
  }
  if (mu <= 0 && gaf != GAF_NONE) e = 0;
  Moments m;
  m.b = e * weightAt(w, mu);  // o.h = mu at the mirror configuration
  m.a = e - m.b;
  return m;
}

}  // namespace brdfbake::reference
