// Independent high-precision reference for the baked quantities: host-side adaptive
// Gauss-Kronrod quadrature (Boost.Math GK31/G15) in double, in the plain angles (theta_h, phi_h)
// of the half vector, with directions as GLM vectors.
//
// What it shares with the kernels: the normalised NDF D(h) (kernels/brdf/ndf.h, as a formula) and
// nothing else. Its own, written from the papers (see docs/MODELS.md): the GAFs G(i, o, h) on
// vectors, the Smith Lambdas, Schlick's k conventions, Schlick's weight (pow), the gaussian's k_p
// (adaptive in theta), the visible domain, the kinks of min/max GAFs (located by root finding on
// the GAFs' own branch differences, not taken from the kernel), and the limits:
//   r = 0 (mirror):      closed forms derived by hand (mirrorAlbedo), checked against the integral
//                        at small alpha in tests/models_test.cpp;
//   mu = 0 (grazing):    the integral evaluated from inside, at mu = 1e-9 min(1, alpha) (E changes
//                        on the scale mu ~ alpha, so this is the limit to ~1e-9);
//   mu = 0 and r = 0:    the limit along the mu = 0 edge, from inside at r = 3e-5 (alpha ~ 1e-9).
// Slow (seconds per value at grazing); for tests, the benchmark and checks.
#pragma once

namespace brdfbake::reference {

// A Fresnel model and its parameters (kernels/brdf/fresnel.h ids; x: F0 or eta, y: k or the
// f82-tint's tint). The reference evaluates dielectric and conductor reflectance from the complex
// Fresnel amplitudes (std::complex), not from the kernels' real closed forms.
struct FresnelSpec {
  int model = 0;  // FRESNEL_ONE
  double x = 0, y = 0;
};
double fresnel(const FresnelSpec& f, double c);
// F_avg = 2 int_0^1 F(mu) mu dmu, adaptively (split at the critical angle where eta < 1).
double fresnelAvg(const FresnelSpec& f);

// The weight w(o.h) that splits the albedo into Moments: b = int H w, a = int H (1 - w).
struct Weight {
  enum Kind { Split, Fresnel, F82C } kind = Split;  // (1 - o.h)^5, F(o.h), o.h (1 - o.h)^6
  FresnelSpec f;
};
double weightAt(const Weight& w, double c);
// Where the weight has a kink: o.h = sqrt(1 - eta^2) for a Fresnel with total internal reflection
// (dielectric, schlick-tir with eta < 1); -1 where it has none.
double weightKink(const Weight& w);
// The weight at o.h = c next to that kink, with delta = c - oc computed by the caller to full
// relative precision (from its distance to the kink, not by subtraction).
double weightNearKink(const Weight& w, double c, double delta);

struct Moments {
  double a = 0, b = 0;  // split-sum A, B; E = a + b
  double e() const { return a + b; }
};

// k_p of the NDF's raw shape at perceptual roughness r (alpha = r^2).
double kp(int ndf, double r);
// int D(h) (n.h) dw_h of the normalised NDF with the given 1/k_p (used by the gaussian only; the
// kernels' own, from brdf_params), adaptively: 1 for a correctly normalised D.
double normalisation(int ndf, double r, double invKp);
// Split-sum moments and directional albedo at (mu, r), limits included as above.
// With a weight: b is the albedo with that Fresnel (Weight::Fresnel), a + b the F = 1 albedo.
Moments albedo(int ndf, int gaf, double r, double mu, const Weight& w = {});
// Average albedo E_avg(r) = 2 int_0^1 E(mu) mu dmu; with a Fresnel weight, of that albedo (b).
double albedoAvg(int ndf, int gaf, double r, const Weight& w = {});
// Weak white furnace: int G1(o) max(0, o.h) D(h) dw_h, which is mu for a Smith G1 matching D.
double weakFurnace(int ndf, double r, double mu);
// The same with the Smith G1 of a GAF: GAF_SMITH (Beckmann's Lambda for Blinn-Phong and the
// gaussian) or GAF_SMITH_EXACT / GAF_SMITH_CORRELATED_EXACT (the exact Lambda, smithLambdaExact).
double weakFurnace(int ndf, int gaf, double r, double mu);
// The exact Smith Lambda of the NDF at r for the direction with cosine mu, by adaptive quadrature
// of the back-facing projected area (Heitz 2014 eq. 17-18), independent of kernels/brdf/smith_tables.h.
double smithLambdaExact(int ndf, double r, double mu);

// The mirror limit (alpha -> 0 at mu > 0): D becomes a delta at h = n, i = o mirrored, and
// E(mu, 0) = G at that configuration (hand-derived per GAF); A and B split it by (1 - mu)^5.
Moments mirrorAlbedo(int gaf, double mu, const Weight& w = {});
// The GAF G(i, o, h) for directions in the frame n = (0, 0, 1), chi+ included, in double.
// (Public so tests can compare the kernel's grazing form G/(n.o) with it away from grazing.)
double gaf(int ndf, int gaf, double r, const double i[3], const double o[3], const double h[3]);

}  // namespace brdfbake::reference
