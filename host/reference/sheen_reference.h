// Independent double-precision reference for the sheen (charlie) quantities: the directional
// albedo by adaptive Gauss-Kronrod over the INCIDENT direction (n.i, phi_i), not the half vector
// the kernels integrate over, with its own Charlie D, its own fitted Lambda and its own visibility
// terms written from the papers (docs/MODELS.md "Sheen"); nothing from kernels/.
#pragma once

namespace brdfbake::reference {

// Charlie D(h) at perceptual roughness r (alpha = r^2) for sin^2(theta_h) = s2 (Estevez and Kulla 2017).
double charlieD(double r, double s2);
// Estevez and Kulla 2017's fitted Smith Lambda at cosine c.
double charlieLambda(double r, double c);
// int D (n.h) dw_h over theta_h in plain angles, adaptively (1 for a normalised D).
double charlieNormalisation(double r);
// The sheen BRDF's directional albedo E(mu) with F = 1 for gaf = GAF_CHARLIE_SMITH, GAF_NEUBELT,
// GAF_IMPLICIT or GAF_NONE; r = 0 gives 0 (mu > 0: the lobe lies on the horizon, below every i);
// mu = 0 is approached from inside (mu = 1e-9); the corner (0, 0) from r = 3e-5 (implicit only is
// finite there).
double sheenAlbedo(int gaf, double r, double mu);
// A (the F0 part, weight 1 - (1 - o.h)^5) and B of the same albedo, for the split-sum kernel's planes.
void sheenMoments(int gaf, double r, double mu, double* a, double* b);
// E_avg(r) = 2 int_0^1 E(mu) mu dmu.
double sheenAlbedoAvg(int gaf, double r);

}  // namespace brdfbake::reference
