// A material's Fresnel (and, with the whole-materials work, its diffuse) choice as the command
// line and the tables' metadata spell it: the model, its parameters as given (one value, or three
// for an RGB table), validated once here.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace brdfbake {

const std::vector<std::string>& fresnelNames();  // index = FRESNEL_* id
int fresnelId(const std::string& name, const std::string& field = "--fresnel");

struct FresnelChoice {
  int model = 0;                        // FRESNEL_ONE
  std::vector<double> f0, eta, k, f82;  // as given: empty, one value, or three (R, G, B)

  bool isOne() const { return model == 0; }
  // 3 when any parameter has three values (an RGB table), else 1.
  int channels() const;
  // The model's parameters (x, y) for channel c, as reference::FresnelSpec takes them: F0 or eta;
  // k (conductor) or the tint (f82-tint).
  std::pair<double, double> modelParams(int c) const;
  // The kernel's parameters (fr_x, fr_y) for channel c: the same, but the F82 model's b for y.
  std::pair<double, double> kernelParams(int c) const;
  // "dielectric eta=1.5", "conductor eta=0.2,0.92,1.1 k=3.9,2.45,2.14", "one".
  std::string describe() const;
  // The parameters as metadata: {"f0", "0.04"}, ...
  std::vector<std::pair<std::string, std::string>> parameters() const;
};

// F_avg = 2 int_0^1 F(mu) mu dmu of channel c (Kulla and Conty 2017), in double: closed forms for
// one (1), schlick ((20 F0 + 1)/21), f82-tint ((20 F0 + 1)/21 - b/126) and schlick-tir
// (eta < 1: (1 - eta^2) + eta^2 (20 F0 + 1)/21); adaptive Gauss-Kronrod otherwise (dielectric,
// conductor), split at the critical angle. *err (optional): the bound (0 for closed forms);
// *how (optional): "closed form" or "GK31 adaptive".
double fresnelAverage(int model, double x, double y, double* err = nullptr, std::string* how = nullptr);
double fresnelAverage(const FresnelChoice& f, int c, double* err = nullptr, std::string* how = nullptr);

// Fills the model's defaults (schlick F0 0.04; dielectric and schlick-tir eta 1.5; f82-tint F0
// 0.04, tint 1) and checks every parameter: its range, that the model takes it, that a conductor
// has eta and k. Throws Error(kExitUsage) naming the flag and its valid range.
void validateFresnel(FresnelChoice& f);

const std::vector<std::string>& diffuseNames();  // index = DIFFUSE_* id
int diffuseId(const std::string& name, const std::string& field = "--diffuse");

// The parameter a diffuse model's albedo table runs over (its second axis): F0 for the Shirley
// forms (the specular's reflectance at normal incidence), sigma in radians for Oren-Nayar,
// roughness r for Burley (and for Lambert, which has none: a constant table).
struct DiffuseAxis {
  std::string name;  // "f0", "sigma", "r"
  double lo, hi;
};
DiffuseAxis diffuseAxis(int model);

// "0.2,0.92,1.1" -> {0.2, 0.92, 1.1}: one or three finite numbers, else Error(kExitUsage).
std::vector<double> parseValues(const std::string& flag, const std::string& text);

}  // namespace brdfbake
