// Independent reference for the rough dielectric's albedos (kernels/integrate/dielectric.h): the
// BSDF of Walter et al. 2007 evaluated directly at pairs of directions, integrated over the
// scattered direction o (not over h, as the kernel does) by nested adaptive Gauss-Kronrod 31/15
// (reference/adaptive.h) in double, in polar coordinates around each lobe's centre (the mirror
// direction; the direction refracted by the mean surface), with breaks graded on the lobe's width.
// Shared with the kernels: the NDF D(h) only (as reference.cpp). Own: the Fresnel (complex
// amplitudes, fresnel_reference.cpp), the Smith Lambdas, G, Boost.Math's beta for the
// height-correlated transmission, the half-vectors, the Jacobian, the domains.
#pragma once

namespace brdfbake::reference {

struct DielectricAlbedo {
  double r = 0, t = 0;  // E_R, E_T
};

// E_R and E_T at (mu, r, eta) for ggx/beckmann with smith/smith-correlated, mu in (0, 1], r > 0,
// eta > 0 and eta != 1 (at eta = 1 the transmitted lobe is a delta: dielectricAlbedoEta1).
DielectricAlbedo dielectricAlbedo(int ndf, int gaf, double mu, double r, double eta);
// The eta = 1 limit, derived by hand (docs/MODELS.md): E_R = 0, E_T = (1 + Lambda) G_T(Lambda, Lambda)
// with Lambda = Lambda(mu): 1/(1 + Lambda) (smith), (1 + Lambda) B(1 + Lambda, 1 + Lambda) (smith-correlated).
DielectricAlbedo dielectricAlbedoEta1(int ndf, int gaf, double mu, double r);

}  // namespace brdfbake::reference
