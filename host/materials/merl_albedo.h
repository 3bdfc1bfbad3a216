// Directional and average albedo of a tabulated isotropic BRDF (a MERL file), on the host in
// double, by a quadrature that follows the table's piecewise structure (docs/MODELS.md, "MERL
// files"): E(mu) = int f(i, o) (n.i) dw_i over the hemisphere of i, o at n.o = mu, integrated over
// the half vector h (dw_i = 4 (o.h) dw_h):
//   theta_h: one Gauss-Legendre panel per sqrt-spaced bin (u = sqrt(theta_h/(pi/2)) 90 in [k, k+1]),
//            cut where the horizon's curve turns in theta_h (theta_h = pi/4 +- theta_o/2),
//   phi_h:   at each theta_h node, the circle cut where theta_d or phi_d crosses a bin edge and where
//            i crosses the horizon (all closed forms), Gauss-Legendre on every piece;
// so every kink of the trilinear interpolant (and every step of MERL's nearest-bin lookup) is a
// panel edge. The rules (n, n - 1) (n nodes per theta_h panel, n - 1 per phi_h piece) climb a
// ladder from n = 4; a rule's estimate is its largest difference from the two rules below it.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <string>

#include "formats/exr/table_file.h"
#include "formats/merl.h"
#include "common/models.h"

namespace brdfbake {

// f at (theta_h, theta_d, phi_d) for R, G, B; false where it has no value (f is then 0 there).
using RusinkiewiczFn = std::function<bool(double thetaH, double thetaD, double phiD, double f[3])>;
// Progress of a long computation: done of total units, seconds since it started.
using ProgressFn = std::function<void(double done, double total, double seconds)>;
RusinkiewiczFn merlFunction(const MerlData& d, bool nearestBin = false);  // trilinear, or MERL's lookup
RusinkiewiczFn analyticFunction(const Brdf3dSpec& s);                     // hostBrdf (for checks)

struct HSpaceRule {
  int thetaNodes = 4;  // Gauss-Legendre nodes per theta_h bin
  int phiNodes = 3;    // Gauss-Legendre nodes per phi_h piece
};

struct AlbedoEstimate {
  std::array<double, 3> e{}, err{};  // per channel: value and its estimate
  double unsupported = 0;            // share of the integral's weight (of E = 1 for f = 1/pi) where f had no value
  int nodes = 0;                     // nodes per theta_h bin of the rule returned
};

// The rules hSpaceAlbedo climbs, (n, n - 1) for n in kMerlLadder, and where it stops: at the first
// rule from the third on whose estimate is within merlTexelTarget in every channel (else the
// last). The target follows what storing the value costs anyway: 2^-25 |E| is half a float ulp
// at the bottom of E's binade, so the claim (estimate + rounding) stays within a few times the
// stored values' error for dark materials too; 1e-9 below that.
inline constexpr std::array<int, 10> kMerlLadder{4, 5, 6, 7, 8, 10, 12, 15, 20, 25};
inline double merlLargest(const std::array<double, 3>& e) {
  return std::max({std::fabs(e[0]), std::fabs(e[1]), std::fabs(e[2])});
}
inline double merlTexelTarget(const std::array<double, 3>& e) {
  return std::max(1e-9, std::ldexp(merlLargest(e), -25));
}
inline constexpr double kMerlArithmetic = 1e-11;  // the double sums' rounding, added to brdf.error

// One rule's E(mu) per channel; *unsupported (optional) as in AlbedoEstimate.
std::array<double, 3> hSpaceIntegral(const RusinkiewiczFn& f, double mu, HSpaceRule rule,
                                     double* unsupported = nullptr);
// E(mu) by the ladder's rule R_k, err = max(|R_k - R_k-1|, |R_k - R_k-2|) per channel.
AlbedoEstimate hSpaceAlbedo(const RusinkiewiczFn& f, double mu);
// E_avg = 2 int E(mu) mu dmu over the table's own coordinates (theta_h, theta_d, phi_d), where its
// kinks are coordinate planes (merl_albedo_avg.cpp): rules of n nodes per bin and piece, n climbing
// kMerlAvgLadder as hSpaceAlbedo's texels climb theirs; `threads` workers (0 = hardware). Not the
// mu average of hSpaceAlbedo, whose estimate cannot be tight (E(mu) kinks wherever a cut meets a bin
// edge; docs/merl.md).
inline constexpr std::array<int, 7> kMerlAvgLadder{2, 3, 4, 5, 6, 7, 8};
// E_avg is one value per channel, so its claim is tight only if its estimate sits well below the
// storage rounding it is added to (else a value that happens to round almost exactly makes the
// claim many times its error): an eighth of merlTexelTarget, 1e-10 below that.
inline double merlAvgTarget(const std::array<double, 3>& e) { return std::max(1e-10, std::ldexp(merlLargest(e), -28)); }
AlbedoEstimate directAlbedoAvg(const RusinkiewiczFn& f, int threads = 0, const ProgressFn& progress = {});
// One rule of directAlbedoAvg's, n nodes per bin and piece (n <= 31), for checks above its ladder.
std::array<double, 3> directAlbedoAvgRule(const RusinkiewiczFn& f, int n, int threads = 0);

// What a measured material's table holds, as the measured family (tables/measured/measured.cpp)
// names it: the table's name (brdf.table, and messages), and E(mu) with its channels' description,
// or E_avg.
struct MerlTableSpec {
  std::string table;     // brdf.table
  bool average = false;  // E_avg (1 x 1) instead of E(mu)
  std::string channels;  // brdf.channels of an E(mu) table
};

// The table of a measured material, RGB, no roughness axis, with its metadata:
//   E(mu) per channel over `width` mu texels (height 1; mu at texel centres or, nodeGrid, at
//     i/(width-1)): the measured family's albedo, and its splitsum, the same numbers labelled as the
//     split sum's whole second factor (README, "MERL in and out");
//   average: 1 x 1, E_avg per channel.
// `name` is the material's name (brdf.material = "merl:<name>"); progress lines go to stderr when
// a table takes more than two seconds.
TableImage merlTable(const MerlData& d, const std::string& name, const MerlTableSpec& spec, int width, bool nodeGrid,
                     bool half, const ProgressFn& progress = {});

}  // namespace brdfbake
