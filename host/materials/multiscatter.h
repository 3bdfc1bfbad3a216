// The host side of shaders/multiscatter.glsl: that shader code itself, compiled as C++ with GLM,
// its lookups sampling brdfbake's tables as a GL sampler does, and the hemisphere integral of the
// Kulla-Conty lobe. tests/multiscatter_test.cpp checks the compensation with it; a CLI check of a
// baked set could reuse it. docs/multiple-scattering.md has the formulas and the measured figures.
#pragma once
#include <glm/vec2.hpp>
#include <vector>

#include "cl/runner.h"

namespace brdfbake::materials {

// A table as a texture sampled with GL_LINEAR and GL_CLAMP_TO_EDGE: texel i at u = (i+0.5)/n,
// bilinear between centres, the edge texel's value beyond them. Exact arithmetic (in float), i.e.
// without the 8-bit fixed-point filter weights some GPUs use. A node-grid table (`--grid node`,
// texel i at q = i/(n-1)) is read through the remap README.md gives, u = (0.5 + (n-1) q)/n, as
// the including shader code must do for such a table; then q = 0 and q = 1 are texel centres.
struct Texture {
  int width = 0, height = 0;
  std::vector<glm::vec2> texels;  // [y * width + x]: two channels (E in x; or A in x, B in y)
  bool nodeGrid = false;
  glm::vec2 sample(float u, float v) const;
};

// Channels planeX (and planeY, or 0) of a KernelTable (x = mu or r, y = r) as a texture.
Texture textureFrom(const KernelTable& t, bool nodeGrid, int planeX, int planeY = -1);

// The three tables shaders/multiscatter.glsl reads: albedo (E(mu, r), F = 1), albedo-avg
// (E_avg(r)) and splitsum ((A, B)), texel-centre grids.
struct MsTables {
  Texture e, eavg, ab;
};

// What the shader adds for one view direction mu = n.o at roughness r, Schlick reflectance f0
// (grey: one channel of the shader's vec3), all from the tables:
struct MsEnergy {
  double kullaConty;    // int f_ms,F(o, i) (n.i) dw_i: the Kulla-Conty lobe's albedo, Fresnel factor included
  double fdezSingle;    // Fdez-Aguera's F_ss E_ss = F0 A + B
  double fdezMultiple;  // Fdez-Aguera's F_ms E_ms
  double filament;      // Filament's scale 1 + F0 (1/E_ss - 1)
};
MsEnergy evaluate(const MsTables& tables, double mu, double r, double f0);

// The shader's kullaContyLobe(muO, muI, r) (F = 1) with these tables bound.
double kullaContyLobe(const MsTables& tables, double muO, double muI, double r);

}  // namespace brdfbake::materials
