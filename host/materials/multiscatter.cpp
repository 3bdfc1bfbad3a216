#include "materials/multiscatter.h"

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <vector>

namespace brdfbake::materials {

glm::vec2 Texture::sample(float u, float v) const {
  // GL's linear filter (OpenGL 4.6 section 8.14.2): i0 = floor(u n - 1/2), weight frac(u n - 1/2),
  // both taps clamped to the edge.
  auto taps = [this](float c, int n, int& i0, int& i1, float& w) {
    if (nodeGrid) c = (0.5f + static_cast<float>(n - 1) * c) / static_cast<float>(n);
    float x = c * static_cast<float>(n) - 0.5f;
    float f = std::floor(x);
    w = x - f;
    i0 = std::clamp(static_cast<int>(f), 0, n - 1);
    i1 = std::clamp(static_cast<int>(f) + 1, 0, n - 1);
  };
  int x0, x1, y0, y1;
  float wx, wy;
  taps(u, width, x0, x1, wx);
  taps(v, height, y0, y1, wy);
  auto at = [&](int x, int y) { return texels[static_cast<size_t>(y) * width + x]; };
  return glm::mix(glm::mix(at(x0, y0), at(x1, y0), wx), glm::mix(at(x0, y1), at(x1, y1), wx), wy);
}

Texture textureFrom(const KernelTable& t, bool nodeGrid, int planeX, int planeY) {
  Texture tex;
  tex.nodeGrid = nodeGrid;
  tex.width = t.width;
  tex.height = t.height;
  tex.texels.resize(static_cast<size_t>(t.width) * t.height);
  for (size_t k = 0; k < tex.texels.size(); ++k)
    tex.texels[k] = glm::vec2(t.planes[planeX][k], planeY < 0 ? 0.0f : t.planes[planeY][k]);
  return tex;
}

// ---- the shader, compiled here -------------------------------------------------------------
// The lookups read the bound tables, as a GLSL shader's read its bound sampler uniforms.
namespace glsl {
using namespace glm;
thread_local const MsTables* bound = nullptr;

#include "../../shaders/multiscatter.glsl"

float lookupE(float mu, float r) { return bound->e.sample(mu, r).x; }
float lookupEavg(float r) { return bound->eavg.sample(r, 0.5f).x; }
vec2 lookupAB(float mu, float r) { return bound->ab.sample(mu, r); }

struct Bind {
  explicit Bind(const MsTables& t) { bound = &t; }
  ~Bind() { bound = nullptr; }
};
}  // namespace glsl

double kullaContyLobe(const MsTables& tables, double muO, double muI, double r) {
  glsl::Bind bind(tables);
  return glsl::kullaContyLobe(static_cast<float>(muO), static_cast<float>(muI), static_cast<float>(r));
}

MsEnergy evaluate(const MsTables& tables, double mu, double r, double f0) {
  glsl::Bind bind(tables);
  const float m = static_cast<float>(mu), rr = static_cast<float>(r);
  const glm::vec3 f(static_cast<float>(f0));
  MsEnergy out;
  // int f_ms (n.i) dw_i = 2 pi int_0^1 f_ms(mu, mu_i) mu_i dmu_i (f_ms does not depend on the
  // azimuth). Between two texel centres of the E table the lookup is linear in mu_i (below the
  // first and above the last it is constant), so the integrand is a quadratic there: 3-point
  // Gauss-Legendre on each of those intervals is exact up to rounding.
  static const double x3[3] = {-0.7745966692414834, 0.0, 0.7745966692414834};
  static const double w3[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  // Breakpoints: the texel centres in mu (node grid: the nodes), and the ends.
  const int n = tables.e.width;
  std::vector<double> knots{0.0};
  for (int k = 0; k < n; ++k) knots.push_back(tables.e.nodeGrid ? k / (n - 1.0) : (k + 0.5) / n);
  knots.push_back(1.0);
  double sum = 0;
  for (size_t k = 0; k + 1 < knots.size(); ++k) {
    const double a = knots[k], b = knots[k + 1];
    if (b <= a) continue;
    for (int j = 0; j < 3; ++j) {
      double mi = 0.5 * (a + b) + 0.5 * (b - a) * x3[j];
      sum += 0.5 * (b - a) * w3[j] * mi * glsl::kullaContyLobe(m, static_cast<float>(mi), rr);
    }
  }
  const double fresnel = glsl::kullaContyFresnel(glsl::msFavgSchlick(f), rr).x;
  out.kullaConty = 2 * M_PI * sum * fresnel;
  out.fdezSingle = glsl::fdezAgueraSingle(m, rr, f).x;
  out.fdezMultiple = glsl::fdezAgueraMultiple(m, rr, f).x;
  out.filament = glsl::filamentEnergyCompensation(m, rr, f).x;
  return out;
}

}  // namespace brdfbake::materials
