// Independent high-precision reference for the baked quantities: host-side adaptive
// Gauss-Kronrod quadrature (Boost.Math) in double, in the plain angles (theta_h, phi_h) of the
// half vector, sharing only the model formulas (kernels/brdf) with the device. Slow; for tests,
// the benchmark and `brdfbake verify`-style checks.
#pragma once

namespace brdfbake::reference {

struct Moments {
  double a = 0, b = 0;  // split-sum A, B; E = a + b
  double e() const { return a + b; }
};

// k_p of the NDF's raw shape at perceptual roughness r (alpha = r^2).
double kp(int ndf, double r);
// Split-sum moments and directional albedo at (mu, r).
Moments albedo(int ndf, int gaf, double r, double mu);
// Average albedo E_avg(r) = 2 int_0^1 E(mu) mu dmu.
double albedoAvg(int ndf, int gaf, double r);
// Weak white furnace: int G1(o) max(0, o.h) D(h) dw_h, which is mu for a Smith G1 matching D.
double weakFurnace(int ndf, double r, double mu);

}  // namespace brdfbake::reference
