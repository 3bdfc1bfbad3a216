// MERL's measured-BRDF binary layout (Matusik, Pfister, Brand and McMillan 2003, "A data-driven
// reflectance model"): writing an isotropic BRDF table in it, reading one back, and looking values
// up. docs/MODELS.md, "MERL files", has the layout and where each fact comes from.
//
// File: three little-endian int32 (90, 90, 180: theta_h, theta_d, phi_d bins), then the R, G and B
// planes of 90*90*180 little-endian doubles each. Bin (th, td, pd) is at pd + 180 (td + 90 th);
// th = sqrt(theta_h/(pi/2)) 90, td = theta_d/(pi/2) 90, pd = phi_d/pi 180 (phi_d folded mod pi:
// f(phi_d) = f(phi_d + pi) by reciprocity). A reader multiplies the stored R, G, B by 1/1500,
// 1.15/1500 and 1.66/1500; negative values mark bins that were not measured.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "common/brdf3d_grid.h"

namespace brdfbake {

constexpr int kMerlThetaH = 90, kMerlThetaD = 90, kMerlPhiD = 180;
constexpr size_t kMerlBins = size_t(kMerlThetaH) * kMerlThetaD * kMerlPhiD;  // 1458000
constexpr size_t kMerlFileBytes = 12 + 3 * kMerlBins * sizeof(double);       // 34992012
// What a reader multiplies the stored R, G, B by (a writer divides by it).
constexpr double kMerlScale[3] = {1.0 / 1500.0, 1.15 / 1500.0, 1.66 / 1500.0};

// MERL's bin of (theta_h bin, theta_d bin, phi_d bin).
inline size_t merlIndex(int th, int td, int pd) { return pd + size_t(kMerlPhiD) * (td + size_t(kMerlThetaD) * th); }

// The brdf3d table shape a MERL file holds: Rusinkiewicz coordinates, sqrt theta_h axis, samples
// at the bins' lower edges (CellStart), 90 x 90 x 180, f itself (not times n.i). Keeps s's material.
Brdf3dSpec merlSpec(Brdf3dSpec s);

// Writes `planes` (1 or 3 channels; one = the same value in R, G and B) of a table of merlSpec's
// shape, planes[c][(z * 90 + y) * 90 + x] (x = theta_h bin, y = theta_d bin, z = phi_d bin), as a
// MERL file at `tmp` (the temporary of `path`, which messages name): reordered to MERL's bin order,
// divided by kMerlScale, little-endian, fsynced; no rename. Negative values pass through (they
// mark unmeasured bins). Throws Error and removes `tmp`: kExitDataErr for a wrong plane count or
// size or a NaN/Inf value (nothing is created), kExitCantCreat when `tmp` cannot be created,
// kExitIoErr when writing, syncing or closing fails (e.g. disk full).
void writeMerlTemporary(const std::string& tmp, const std::string& path, const std::vector<std::vector<float>>& planes);
// writeMerlTemporary to temporaryPathFor(path), then rename onto path (kExitCantCreat if that fails).
void writeMerl(const std::string& path, const std::vector<std::vector<float>>& planes);

// The analytic material of `s` (ndf, gaf, roughness, fresnel, diffuse) at every bin of merlSpec(s),
// by hostBrdf at texelDirections, in double rounded to float: s.channels() planes in the layout
// writeMerlTemporary takes. For tests and checks (the bake fills them on the device).
std::vector<std::vector<float>> merlPlanesFromSpec(const Brdf3dSpec& s);

// The least share of the lit bins (both directions above the horizon) a MERL file must measure,
// per channel: below a half, the albedo would integrate more of the interpolation's guesses than
// of the measurement. The tables record the share (brdf.merl.measured).
constexpr double kMerlMinMeasured = 0.5;

// A MERL file in memory: the BRDF (stored values times kMerlScale) in MERL's bin order.
struct MerlData {
  std::string path;
  std::array<std::vector<double>, 3> f;  // f[c][merlIndex(th, td, pd)]
  // Bins an interpolation may use, per channel: value >= 0 (measured) and the bin's sample
  // configuration (its lower edges) has both directions above the horizon.
  std::array<std::vector<uint8_t>, 3> usable;
  std::array<size_t, 3> negative{};  // bins holding a negative value (not measured)
  size_t belowHorizon = 0;           // bins whose sample configuration is below the horizon
  // The share of the bins above the horizon that are measured, per channel (readMerl refuses a
  // file where it is below kMerlMinMeasured in any channel).
  std::array<double, 3> measuredShare{};

  // Fractional bin coordinates of an angle triple: u = sqrt(theta_h/(pi/2)) 90, v = theta_d/(pi/2)
  // 90, w = (phi_d mod pi)/pi 180, so that bin k's sample is at coordinate k.
  static std::array<double, 3> coordinates(double thetaH, double thetaD, double phiD);

  // MERL's own lookup: the bin holding (theta_h, theta_d, phi_d), indices floored and clamped to
  // the table, phi_d folded mod pi; the raw value (negative where not measured).
  double nearest(int c, double thetaH, double thetaD, double phiD) const;
  // The interpolation the integrals use: trilinear in (u, v, w) between bin samples; w periodic
  // (bin 179 neighbours bin 0 = phi_d pi), u and v clamped at the last bin (u > 89: theta_h above
  // 88.0 deg; v > 89: theta_d above 89 deg). Corners that are not usable are left out and the
  // others' weights renormalised; with no usable corner, returns false and sets f[c] = 0.
  // Returns true when every channel had a usable corner.
  bool trilinear(double u, double v, double w, double f[3]) const;
  bool lookup(double thetaH, double thetaD, double phiD, double f[3]) const;
};

// Reads and checks a MERL file: Error(kExitNoInput) when it cannot be opened or read,
// Error(kExitDataErr) when its size is not kMerlFileBytes, its header not 90 90 180, or a value is
// NaN or infinite; each message names the file, what was expected and what was found.
MerlData readMerl(const std::string& path);

}  // namespace brdfbake
