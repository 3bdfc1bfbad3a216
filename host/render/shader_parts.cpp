// The non-GL parts of `brdfbake render` (render/shader_parts.h).
#include "render/shader_parts.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "common/brdf3d_grid.h"
#include "common/format.h"
#include "common/models.h"

namespace brdfbake {

namespace {
// shaders/multiscatter.glsl, embedded at configure time (generated/multiscatter_glsl.h)
#include "multiscatter_glsl.h"
}  // namespace

// Gauss-Legendre nodes and weights on [0, 1] (Newton on P_n from Chebyshev's first guesses; Golub
// and Welsch give the same): the shader integrates the Kulla-Conty lobe over mu_i with them.
void gaussLegendre(int n, std::vector<double>* x, std::vector<double>* w) {
  x->assign(n, 0);
  w->assign(n, 0);
  for (int i = 0; i < n; ++i) {
    double z = std::cos(M_PI * (i + 0.75) / (n + 0.5)), dp = 0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = z;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (z * p1 - p0) / (z * z - 1);
      const double dz = p1 / dp;
      z -= dz;
      if (std::fabs(dz) < 1e-16) break;
    }
    (*x)[i] = 0.5 * (1 - z);
    (*w)[i] = 1 / ((1 - z * z) * dp * dp);  // 2/((1 - z^2) P'^2) on [-1, 1], halved on [0, 1]
  }
}

// A GLSL float literal: "1" is an int there, which a float constant cannot take.
std::string lit(double d) {
  std::string s = fmtG9(d);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

std::string floats(const std::vector<double>& v) {
  std::string s;
  for (double d : v) s += (s.empty() ? "" : ", ") + lit(d);
  return s;
}

std::string multiscatterBody() {
  std::string in = kMultiscatterGlsl, out;
  size_t at = 0;
  while (at < in.size()) {
    size_t end = in.find('\n', at);
    if (end == std::string::npos) end = in.size();
    const std::string line = in.substr(at, end - at);
    const bool prototype = line.rfind("float lookup", 0) == 0 || line.rfind("vec2 lookup", 0) == 0;
    if (!(prototype && line.back() == ';')) out += line + "\n";
    at = end + 1;
  }
  return out;
}

// The single-scattering term from the BRDF code in kernels/brdf compiled for the host
// (common/brdf3d_grid.h hostBrdf: the pair, F = 1, times n.i), and each pixel's
// cosines for the shader's Kulla-Conty lobe.
LobeInput lobeInput(int cell, int ndf, int gaf) {
  const int W = 3 * cell, H = 2 * cell;
  LobeInput in;
  in.geometry.assign(static_cast<size_t>(W) * H * 4, 0.0f);
  in.single.assign(static_cast<size_t>(W) * H, 0.0f);
  const double ll = std::sqrt(kLight[0] * kLight[0] + kLight[1] * kLight[1] + kLight[2] * kLight[2]);
  const glm::dvec3 l(kLight[0] / ll, kLight[1] / ll, kLight[2] / ll), v(0, 0, 1);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const double cx = ((x % cell) + 0.5) / cell * 2 - 1, cy = -(((y % cell) + 0.5) / cell * 2 - 1);
      const double d2 = (cx * cx + cy * cy) / (kSphere * kSphere);
      if (d2 >= 1) continue;
      const glm::dvec3 n(cx / kSphere, cy / kSphere, std::sqrt(1 - d2));
      const double r = kLobeRoughness[x / cell], muO = glm::dot(n, v), muI = glm::dot(n, l);
      const size_t k = static_cast<size_t>(y) * W + x;
      in.geometry[k * 4 + 0] = static_cast<float>(muO);
      in.geometry[k * 4 + 1] = static_cast<float>(std::max(muI, 0.0));
      in.geometry[k * 4 + 2] = static_cast<float>(r);
      in.geometry[k * 4 + 3] = 1.0f;
      if (muI <= 0) continue;
      // the local frame: n = z, its tangents from any vector not along n
      const glm::dvec3 a = std::fabs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
      const glm::dvec3 t = glm::normalize(glm::cross(a, n)), b = glm::cross(n, t);
      Brdf3dSpec s;
      s.ndf = ndf;
      s.gaf = gaf;
      s.roughness = r;
      s.timesCos = true;
      const Directions dir{{glm::dot(l, t), glm::dot(l, b), muI}, {glm::dot(v, t), glm::dot(v, b), muO}};
      in.single[k] = static_cast<float>(hostBrdf(s, dir, 0));
    }
  return in;
}

}  // namespace brdfbake
