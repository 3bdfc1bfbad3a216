// The isotropic BRDF as a 3D table: what is tabulated (material, parameterisation, grid, stored
// value) and, on the host in double with GLM vectors, the directions of each sample and the BRDF
// there. The host side is the independent check of kernels/brdf3d.cl: same models
// (kernels/brdf/brdf.h), but its own geometry (vectors and rotations instead of the kernel's
// closed-form cosines) and double instead of float.
#pragma once
#include <array>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "common/material.h"

namespace brdfbake {

enum class Brdf3dParam { Angles, Rusinkiewicz };
enum class Brdf3dGrid { TexelCenter, Node, CellStart };  // (i+0.5)/n, i/(n-1), i/n (MERL's bins)

struct Brdf3dSpec {
  int ndf = 0, gaf = 0;     // NDF_*, GAF_*
  double roughness = 0.5;   // perceptual r of the specular lobe
  FresnelChoice fresnel;    // validated; model one = F = 1
  int diffuse = -1;         // DIFFUSE_* or -1 (no diffuse lobe)
  double diffuseParam = 0;  // F0 (shirley forms), sigma (oren-nayar) or r (burley)
  std::vector<double> rho;  // diffuse albedo: one value or three (R, G, B)
  Brdf3dParam param = Brdf3dParam::Angles;
  bool thetaHSqrt = false;  // rusinkiewicz: x = sqrt(theta_h/(pi/2)) (MERL), else theta_h/(pi/2)
  Brdf3dGrid grid = Brdf3dGrid::TexelCenter;
  bool timesCos = false;          // store f (n.i) instead of f
  int nx = 32, ny = 32, nz = 32;  // x, y, z resolution

  int channels() const;  // 3 when the Fresnel parameters or rho have three values, else 1
  // The kernel's parameterisation id (B3_PARAM_* in kernels/brdf3d.cl) and grid id.
  int kernelParam() const;
  int kernelGrid() const;
  // Axis names and ranges in radians: {"theta_i", 0, pi/2}, ...
  struct Axis {
    std::string name;
    double lo, hi;
  };
  std::array<Axis, 3> axes() const;
};

// The kernel's input: each axis's samples as (cos, sin) pairs, x then y then z, in double. Angles
// pi/2 u for the theta axes (u = t, or t^2 for MERL's theta_h index), pi t for the azimuth. The
// cosine of pi/2 u is the sine of pi/2 (1 - u), with 1 - u formed from the grid's integers, so
// that it keeps its relative precision near grazing.
std::vector<double> axisTrig(const Brdf3dSpec& s);
// Fraction t in [0, 1] of sample i of n on the spec's grid.
double gridFraction(Brdf3dGrid grid, int i, int n);
// The spec's three coordinates (radians) of texel (x, y, z).
glm::dvec3 texelAngles(const Brdf3dSpec& s, int x, int y, int z);
// The table coordinate (fractional texel index, 0 = the first sample) of an angle on axis a, the
// inverse of texelAngles per axis.
double texelIndex(const Brdf3dSpec& s, int axis, double angle);

struct Directions {
  glm::dvec3 i, o;  // unit vectors, normal = +z
};
// (theta_i, theta_o, phi): i at azimuth phi, o at azimuth 0.
Directions fromAngles(double thetaI, double thetaO, double phi);
// (theta_h, theta_d, phi_d) by Rusinkiewicz 1998: h at azimuth 0, i = d rotated by theta_h about y.
Directions fromRusinkiewicz(double thetaH, double thetaD, double phiD);
// Inverse: (theta_h, theta_d, phi_d in [0, 2 pi)) of a pair of directions.
glm::dvec3 toRusinkiewicz(const Directions& d);
Directions texelDirections(const Brdf3dSpec& s, int x, int y, int z);

// f(i, o) (times n.i when s.timesCos) of channel c in double (brdf64::brdf_f).
double hostBrdf(const Brdf3dSpec& s, const Directions& d, int c);

// Trilinear lookup in a table of the spec's shape, planes[c][(z*ny + y)*nx + x], at fractional
// texel indices (clamped to the table; z wraps on nothing: phi ends at pi).
double trilinear(const Brdf3dSpec& s, const std::vector<float>& plane, glm::dvec3 index);

// Interpolation error of the spec's resolution: at `samples` points spread over each axis' whole
// range (a fixed low-discrepancy set, so the figure is reproducible; on texel-center grids the half
// texel at each end, where a lookup clamps, included), the trilinear lookup of the exact grid
// values against the exact BRDF, relative to max(1, |f|). Host-side, in double.
struct InterpError {
  double max = 0, rms = 0;
  glm::dvec3 worstAt{0.0};  // angles (radians) of the worst point
  // the same over the points with both directions at most kInteriorTheta from the normal: away
  // from grazing, where f itself grows without bound for most GAFs and no resolution helps
  double maxInterior = 0, rmsInterior = 0;
};
constexpr double kInteriorThetaDeg = 80.0;
InterpError interpolationError(const Brdf3dSpec& s, int samples = 4096);

}  // namespace brdfbake
