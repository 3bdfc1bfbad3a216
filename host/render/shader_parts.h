// The parts of `brdfbake render`'s shaders and pictures that are not GL calls: the sphere grid's
// geometry, GLSL literals, Gauss-Legendre rules, shaders/multiscatter.glsl as the shader needs it,
// and the lobe picture's host side (single scattering from kernels/brdf compiled as C++).
#pragma once
#include <string>
#include <vector>

namespace brdfbake {

constexpr float kSphere = 0.9f;  // a sphere's radius, a fraction of half its cell

// The lobe picture: one sphere per roughness, lit by a directional light of irradiance 1 from
// upper left (normalised (-0.5, 0.5, 0.7)), seen along +z; top row single scattering, bottom row
// with the Kulla-Conty lobe added.
constexpr double kLobeRoughness[3] = {0.4, 0.7, 1.0};
constexpr double kLight[3] = {-0.5, 0.5, 0.7};

// Gauss-Legendre nodes and weights on [0, 1].
void gaussLegendre(int n, std::vector<double>* x, std::vector<double>* w);
// A GLSL float literal ("1" is an int there, which a float constant cannot take), and a list of them.
std::string lit(double d);
std::string floats(const std::vector<double>& v);
// shaders/multiscatter.glsl without its prototypes of the lookups (the generated glue defines them first).
std::string multiscatterBody();

struct LobeInput {
  std::vector<float> geometry;  // per pixel: mu_o, mu_i, r, 1 (sphere) or 0 (background)
  std::vector<float> single;    // f_ss(o, i) mu_i from kernels/brdf (host, double), per pixel
};
// The lobe picture's inputs for 3 x 2 cells of `cell` pixels: the pair's BRDF, F = 1.
LobeInput lobeInput(int cell, int ndf, int gaf);

}  // namespace brdfbake
