#include "common/brdf3d_grid.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include "common/brdf_host.h"

namespace brdfbake {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kHalfPi = 0.5 * kPi;
}  // namespace

int Brdf3dSpec::channels() const { return fresnel.channels() == 3 || rho.size() == 3 ? 3 : 1; }

int Brdf3dSpec::kernelParam() const {
  if (param == Brdf3dParam::Angles) return 0;
  return thetaHSqrt ? 2 : 1;
}

int Brdf3dSpec::kernelGrid() const { return grid == Brdf3dGrid::TexelCenter ? 0 : grid == Brdf3dGrid::Node ? 1 : 2; }

std::array<Brdf3dSpec::Axis, 3> Brdf3dSpec::axes() const {
  if (param == Brdf3dParam::Angles) return {{{"theta_i", 0, kHalfPi}, {"theta_o", 0, kHalfPi}, {"phi", 0, kPi}}};
  return {{{"theta_h", 0, kHalfPi}, {"theta_d", 0, kHalfPi}, {"phi_d", 0, kPi}}};
}

double gridFraction(Brdf3dGrid grid, int i, int n) {
  switch (grid) {
    case Brdf3dGrid::TexelCenter:
      return (i + 0.5) / n;
    case Brdf3dGrid::Node:
      return n > 1 ? static_cast<double>(i) / (n - 1) : 0.0;
    default:
      return static_cast<double>(i) / n;
  }
}

std::vector<double> axisTrig(const Brdf3dSpec& s) {
  std::vector<double> out;
  int n[3] = {s.nx, s.ny, s.nz};
  for (int a = 0; a < 3; ++a) {
    for (int i = 0; i < n[a]; ++i) {
      // t = num/den and 1 - t = (den - num)/den, from integers
      double num, den;
      switch (s.grid) {
        case Brdf3dGrid::TexelCenter:
          num = 2.0 * i + 1;
          den = 2.0 * n[a];
          break;
        case Brdf3dGrid::Node:
          num = i;
          den = n[a] > 1 ? n[a] - 1.0 : 1.0;
          break;
        default:
          num = i;
          den = n[a];
      }
      double u = num / den, uc = (den - num) / den;
      if (a == 0 && s.param == Brdf3dParam::Rusinkiewicz && s.thetaHSqrt) {
        u = (num * num) / (den * den);
        uc = ((den - num) * (den + num)) / (den * den);  // 1 - t^2, exact in integers
      }
      if (a == 2) {  // the azimuth, pi t
        out.push_back(std::cos(kPi * u));
        out.push_back(std::sin(kPi * u));
      } else {
        out.push_back(std::sin(kHalfPi * uc));
        out.push_back(std::sin(kHalfPi * u));
      }
    }
  }
  return out;
}

glm::dvec3 texelAngles(const Brdf3dSpec& s, int x, int y, int z) {
  auto ax = s.axes();
  double t[3] = {gridFraction(s.grid, x, s.nx), gridFraction(s.grid, y, s.ny), gridFraction(s.grid, z, s.nz)};
  if (s.param == Brdf3dParam::Rusinkiewicz && s.thetaHSqrt) t[0] = t[0] * t[0];
  return {ax[0].hi * t[0], ax[1].hi * t[1], ax[2].hi * t[2]};
}

double texelIndex(const Brdf3dSpec& s, int axis, double angle) {
  int n = axis == 0 ? s.nx : axis == 1 ? s.ny : s.nz;
  double t = angle / s.axes()[axis].hi;
  if (axis == 0 && s.param == Brdf3dParam::Rusinkiewicz && s.thetaHSqrt) t = std::sqrt(std::max(t, 0.0));
  switch (s.grid) {
    case Brdf3dGrid::TexelCenter:
      return t * n - 0.5;
    case Brdf3dGrid::Node:
      return t * (n - 1);
    default:
      return t * n;
  }
}

Directions fromAngles(double thetaI, double thetaO, double phi) {
  Directions d;
  d.i = {std::sin(thetaI) * std::cos(phi), std::sin(thetaI) * std::sin(phi), std::cos(thetaI)};
  d.o = {std::sin(thetaO), 0.0, std::cos(thetaO)};
  return d;
}

Directions fromRusinkiewicz(double thetaH, double thetaD, double phiD) {
  // d about the half-vector frame's z, then that frame tilted by theta_h about y (h ends at
  // azimuth 0); o is i reflected about h.
  glm::dvec3 d(std::sin(thetaD) * std::cos(phiD), std::sin(thetaD) * std::sin(phiD), std::cos(thetaD));
  glm::dmat3 tilt(glm::rotate(glm::dmat4(1.0), thetaH, glm::dvec3(0, 1, 0)));
  glm::dvec3 h = tilt * glm::dvec3(0, 0, 1);
  Directions r;
  r.i = tilt * d;
  r.o = 2.0 * glm::dot(r.i, h) * h - r.i;
  return r;
}

glm::dvec3 toRusinkiewicz(const Directions& dirs) {
  glm::dvec3 h = glm::normalize(dirs.i + dirs.o);
  double thetaH = std::acos(std::clamp(h.z, -1.0, 1.0)), phiH = std::atan2(h.y, h.x);
  // undo the half-vector's azimuth, then its tilt: i in the half-vector frame
  glm::dmat3 unspin(glm::rotate(glm::dmat4(1.0), -phiH, glm::dvec3(0, 0, 1)));
  glm::dmat3 untilt(glm::rotate(glm::dmat4(1.0), -thetaH, glm::dvec3(0, 1, 0)));
  glm::dvec3 d = untilt * (unspin * dirs.i);
  double thetaD = std::acos(std::clamp(d.z, -1.0, 1.0)), phiD = std::atan2(d.y, d.x);
  if (phiD < 0) phiD += 2 * kPi;
  return {thetaH, thetaD, phiD};
}

Directions texelDirections(const Brdf3dSpec& s, int x, int y, int z) {
  glm::dvec3 a = texelAngles(s, x, y, z);
  return s.param == Brdf3dParam::Angles ? fromAngles(a.x, a.y, a.z) : fromRusinkiewicz(a.x, a.y, a.z);
}

double hostBrdf(const Brdf3dSpec& s, const Directions& d, int c) {
  using namespace brdf64;
  BrdfGeometry g;
  g.ni = d.i.z;
  g.no = d.o.z;
  g.s2i = d.i.x * d.i.x + d.i.y * d.i.y;
  g.s2o = d.o.x * d.o.x + d.o.y * d.o.y;
  glm::dvec3 sum = d.i + d.o;
  double len2 = glm::dot(sum, sum);
  if (len2 > 1e-24) {  // else i = -o, both on the horizon: no half-vector (kernels/brdf3d.cl)
    glm::dvec3 h = sum / std::sqrt(len2);
    g.nh = h.z;
    g.s2h = h.x * h.x + h.y * h.y;
    g.oh = glm::dot(d.o, h);
  } else {
    g.nh = 1;
    g.s2h = 0;
    g.oh = 0;
  }
  double sio = std::sqrt(g.s2i * g.s2o);
  g.cphi = sio > 0 ? (d.i.x * d.o.x + d.i.y * d.o.y) / sio : 1.0;
  BrdfMaterial m;
  m.ndf = s.ndf;
  m.gaf = s.gaf;
  // the material's parameters as the device receives them (float), so that both evaluate the
  // BRDF of the same material
  auto fl = [](double v) { return static_cast<double>(static_cast<float>(v)); };
  m.p = brdf_params(s.ndf, s.gaf, fl(s.roughness));
  m.fresnel = s.fresnel.model;
  m.diffuse = s.diffuse;
  m.dparam = fl(s.diffuseParam);
  auto [fx, fy] = s.fresnel.kernelParams(s.fresnel.channels() == 3 ? c : 0);
  double rho = s.rho.empty() ? 1.0 : s.rho[s.rho.size() == 3 ? c : 0];
  double f = brdf_f(m, g, fl(fx), fl(fy), fl(rho));
  return s.timesCos ? f * std::max(g.ni, BRDF_MIN_COS) : f;
}

double trilinear(const Brdf3dSpec& s, const std::vector<float>& plane, glm::dvec3 index) {
  int n[3] = {s.nx, s.ny, s.nz};
  int lo[3];
  double w[3];
  for (int a = 0; a < 3; ++a) {
    double u = std::clamp(index[a], 0.0, static_cast<double>(n[a] - 1));
    lo[a] = std::min(static_cast<int>(std::floor(u)), std::max(n[a] - 2, 0));
    w[a] = n[a] > 1 ? u - lo[a] : 0.0;
  }
  auto at = [&](int x, int y, int z) {
    x = std::min(x, n[0] - 1);
    y = std::min(y, n[1] - 1);
    z = std::min(z, n[2] - 1);
    return static_cast<double>(plane[(static_cast<size_t>(z) * n[1] + y) * n[0] + x]);
  };
  double v = 0;
  for (int k = 0; k < 8; ++k) {
    int dx = k & 1, dy = (k >> 1) & 1, dz = (k >> 2) & 1;
    double wk = (dx ? w[0] : 1 - w[0]) * (dy ? w[1] : 1 - w[1]) * (dz ? w[2] : 1 - w[2]);
    if (wk != 0) v += wk * at(lo[0] + dx, lo[1] + dy, lo[2] + dz);
  }
  return v;
}

InterpError interpolationError(const Brdf3dSpec& s, int samples) {
  // Points of the (2, 3, 5) Halton sequence spread over each axis' whole range (in the table's own
  // coordinate: sqrt(theta_h) for MERL's index), where a shader may look up: on texel-center grids
  // that includes the half texel at each end, where the lookup clamps. The trilinear lookup uses
  // the exact BRDF at the grid points, which the table holds to float precision.
  auto radical = [](int i, int b) {
    double f = 1, r = 0;
    for (; i > 0; i /= b) {
      f /= b;
      r += f * (i % b);
    }
    return r;
  };
  int n[3] = {s.nx, s.ny, s.nz};
  auto ax = s.axes();
  InterpError e;
  double sum2 = 0, sum2Interior = 0;
  int interior = 0;
  const double cosInterior = std::cos(kInteriorThetaDeg * kPi / 180);
  for (int k = 1; k <= samples; ++k) {
    double t[3] = {radical(k, 2), radical(k, 3), radical(k, 5)};
    glm::dvec3 ang;
    for (int a = 0; a < 3; ++a)
      ang[a] = ax[a].hi * (a == 0 && s.param == Brdf3dParam::Rusinkiewicz && s.thetaHSqrt ? t[a] * t[a] : t[a]);
    double lookup = 0;
    int lo[3];
    double w[3];
    for (int a = 0; a < 3; ++a) {
      double idx = std::clamp(texelIndex(s, a, ang[a]), 0.0, n[a] - 1.0);
      lo[a] = std::min(static_cast<int>(std::floor(idx)), std::max(n[a] - 2, 0));
      w[a] = n[a] > 1 ? idx - lo[a] : 0.0;
    }
    for (int c = 0; c < 8; ++c) {
      int dx = c & 1, dy = (c >> 1) & 1, dz = (c >> 2) & 1;
      double wc = (dx ? w[0] : 1 - w[0]) * (dy ? w[1] : 1 - w[1]) * (dz ? w[2] : 1 - w[2]);
      if (wc != 0)
        lookup += wc * hostBrdf(s,
                                texelDirections(s, std::min(lo[0] + dx, n[0] - 1), std::min(lo[1] + dy, n[1] - 1),
                                                std::min(lo[2] + dz, n[2] - 1)),
                                0);
    }
    Directions d =
        s.param == Brdf3dParam::Angles ? fromAngles(ang.x, ang.y, ang.z) : fromRusinkiewicz(ang.x, ang.y, ang.z);
    double exact = hostBrdf(s, d, 0);
    double err = std::fabs(lookup - exact) / std::max(1.0, std::fabs(exact));
    sum2 += err * err;
    if (err > e.max) {
      e.max = err;
      e.worstAt = ang;
    }
    if (std::min(d.i.z, d.o.z) >= cosInterior) {
      ++interior;
      sum2Interior += err * err;
      e.maxInterior = std::max(e.maxInterior, err);
    }
  }
  e.rms = std::sqrt(sum2 / samples);
  e.rmsInterior = interior ? std::sqrt(sum2Interior / interior) : 0.0;
  return e;
}

}  // namespace brdfbake
