// Independent reference for the diffuse models' directional albedo E(mu) = int f_d (n.i) dw_i:
// nested adaptive Gauss-Kronrod quadrature (Boost.Math, GK31) in double over the direction of i,
// the models evaluated from GLM vectors by their own code here (not kernels/brdf/diffuse.h), with
// breakpoints at the kinks (theta_i = theta_o, phi = pi/2, 3 pi/2). Plus closed forms derived by
// hand (docs/MODELS.md "Diffuse models"). Model ids and parameters as in kernels/brdf/diffuse.h.
#pragma once
#include <string>

namespace brdfbake::reference {

// f_d(i, o) (rho = 1) for unit directions i, o in the frame n = (0, 0, 1).
double diffuseBrdf(int model, double param, const double i[3], const double o[3]);
// E(mu) by quadrature. At mu = 0 the integral at o exactly grazing (the limit from inside for every
// model but oren-nayar-as-printed, whose albedo is +inf there where sigma > 0: returned as +inf).
double diffuseAlbedo(int model, double param, double mu);
// Closed-form E(mu) where there is one (lambert, shirley, ashikhmin-shirley, shirley-as-printed,
// oren-nayar and oren-nayar-as-printed; burley only at mu = 0); NaN otherwise.
double diffuseAlbedoClosedForm(int model, double param, double mu);
// The model's name (MODELS.md spelling) for messages.
std::string diffuseName(int model);

}  // namespace brdfbake::reference
