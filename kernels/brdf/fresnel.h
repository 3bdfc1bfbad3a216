/* fresnel.h: Fresnel reflectance, MODELS.md "Fresnel". c is the cosine of the angle to the normal
 * of the reflecting facet (o.h for microfacets). */
#ifndef BRDF_LANE_PASS
#define FRESNEL_ONE 0
#define FRESNEL_SCHLICK 1
#define FRESNEL_DIELECTRIC 2
#define FRESNEL_SCHLICK_TIR 3
#endif

/* (1 - c)^5, Schlick's weight, with two multiplications instead of pow. */
BRDF_FN real fresnel_schlick_weight(real c) {
  real m = RC(1.0) - c;
  real m2 = m * m;
  return m2 * m2 * m;
}

/* Schlick 1994: F0 + (1 - F0)(1 - c)^5 */
BRDF_FN real fresnel_schlick(real f0, real c) { return f0 + (RC(1.0) - f0) * fresnel_schlick_weight(c); }

/* Exact unpolarised dielectric (Cook and Torrance 1982, with MODELS.md errata):
 * g^2 = eta^2 + c^2 - 1, F = 1/2 (g-c)^2/(g+c)^2 (1 + (c(g+c) - 1)^2/(c(g-c) + 1)^2); F = 1 when g^2 < 0. */
BRDF_FN real fresnel_dielectric(real eta, real c) {
  c = fabs(c);
  real g2 = eta * eta + c * c - RC(1.0);
  real g = sqrt(fmax(g2, RC(0.0)));
  real a = (g - c) / (g + c);
  real b = (c * (g + c) - RC(1.0)) / (c * (g - c) + RC(1.0));
  real f = RC(0.5) * a * a * (RC(1.0) + b * b);
  return g2 < RC(0.0) ? RC(1.0) : f;
}

/* Schlick on the transmitted angle where eta < 1 (Burley 2015, MODELS.md errata):
 * cos^2 t = 1 - (1 - c^2)/eta^2; F = 1 when that is negative. F0 = ((eta-1)/(eta+1))^2. */
BRDF_FN real fresnel_schlick_tir(real eta, real c) {
  real f0 = (eta - RC(1.0)) / (eta + RC(1.0));
  f0 *= f0;
  real ct2 = RC(1.0) - (RC(1.0) - c * c) / (eta * eta);
  real f = fresnel_schlick(f0, eta >= RC(1.0) ? c : sqrt(fmax(ct2, RC(0.0))));
  return (eta < RC(1.0) && ct2 < RC(0.0)) ? RC(1.0) : f;
}
