// brdfbake energy: does a whole material (specular lobe with its Fresnel, plus a diffuse lobe,
// coupled) conserve energy? The worst total directional albedo over a (mu, r, parameter) grid,
// where it occurs, and a verdict a build can gate on.
#pragma once
#include <string>
#include <vector>

#include "brdfbake/request.h"

namespace brdfbake {

struct EnergyPoint {
  double mu, r, param;  // param: the diffuse model's swept parameter (sigma, F0), or NaN
  int channel;          // colour channel of the Fresnel parameters (0 for one value)
  double spec, diffuse, total, bound;
};

struct EnergyResult {
  std::string material;            // "ggx+smith-correlated, fresnel dielectric eta=1.5, diffuse lambert, coupling sum"
  bool violates = false;           // worst total exceeds 1 by more than its bound
  std::vector<EnergyPoint> worst;  // the largest totals, worst first
  std::string paramName;           // of EnergyPoint::param ("" when none is swept)
  int channels = 1;                // colour channels of the Fresnel parameters
  std::vector<double> fresnelAvg;  // F_avg per channel
  std::string fresnelAvgHow;       // "closed form" or the quadrature
  std::string diffuseAlone;        // the diffuse lobe's own largest albedo, and where ("" without one)
  std::string secondLobe = "diffuse";  // the column of EnergyPoint::diffuse: "E_T" for rough glass
};

// How the material's lobes combine (brdfbake energy --coupling, --transmission).
struct EnergyOptions {
  std::string coupling = "sum";  // sum | albedo-scaling (the diffuse lobe scaled by 1 - E_spec)
  bool transmission = false;     // rough glass: E_R + E_T, --fresnel dielectric
};

// One result per NDF/GAF pair of the request (size = grid nodes per axis, default 33). With
// transmission (rough glass: --fresnel dielectric) the total is E_R + E_T of the microfacet BSDF
// (Walter et al. 2007) at the material's eta.
std::vector<EnergyResult> checkEnergy(const BakeRequest& req, const EnergyOptions& opts = {});
// The verdict lines and the table of worst points.
std::string formatEnergy(const std::vector<EnergyResult>& results);
// The page <outDir>/energy/index.html: the verdicts, energy.csv (the worst points) and the white
// furnace of each pair (report/furnace_figure.h). Returns the line saying where it is. `brdfbake
// energy` writes it only with -o: the gate alone takes 0.07 to 0.09 s, with the page 1.1 to 1.7 s
// (the render's bakes and GL), for the default pair on 2 cores.
std::string writeEnergyPage(const BakeRequest& req, const std::vector<EnergyResult>& results);

}  // namespace brdfbake
