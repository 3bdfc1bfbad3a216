/* quadrature.h: fixed rules shared by the estimators.
 * Gauss-Kronrod 7/15 on [-1, 1], the QUADPACK qk15 pair (Piessens et al. 1983): the 15-point
 * Kronrod value is the estimate. |K15 - G7| estimates the error of G7, not of K15: on smooth
 * integrands K15's is orders of magnitude smaller. gk_error below turns the pair into an estimate
 * of K15's own error. */
/* Once per pass (compat.h "Passes"). */
#if defined(BRDF_SECOND_PASS) ? !defined(BRDF_QUADRATURE_H_2) : !defined(BRDF_QUADRATURE_H)
#ifdef BRDF_SECOND_PASS
#define BRDF_QUADRATURE_H_2
#else
#define BRDF_QUADRATURE_H
#endif
#include "brdf/compat.h"

/* GK15 nodes on [-1, 1] in ascending order, Kronrod weights, and Kronrod minus Gauss weights (the
 * error estimate is |sum WD f|; the 7 Gauss nodes are the odd ones), padded to 16 with a
 * zero-weight node so that one float16 lane vector holds
 * a whole panel on the device; the host stops at 15 (HEMI_GK_N). The pad is a real node (x = 0,
 * inside the panel), so that 0 * f stays finite. */
#define HEMI_GK_N (BRDF_LANES > 1 ? 16 : 15)
BRDF_CONST real GK15_XL[16] = {RC(-0.991455371120812639206854697526329), RC(-0.949107912342758524526189684047851),
                               RC(-0.864864423359769072789712788640926), RC(-0.741531185599394439863864773280788),
                               RC(-0.586087235467691130294144845693013), RC(-0.405845151377397166906606412076961),
                               RC(-0.207784955007898467600689403773245), RC(0.0),
                               RC(0.207784955007898467600689403773245),  RC(0.405845151377397166906606412076961),
                               RC(0.586087235467691130294144845693013),  RC(0.741531185599394439863864773280788),
                               RC(0.864864423359769072789712788640926),  RC(0.949107912342758524526189684047851),
                               RC(0.991455371120812639206854697526329),  RC(0.0)};
BRDF_CONST real GK15_WKL[16] = {RC(0.022935322010529224963732008058970), RC(0.063092092629978553290700663189204),
                                RC(0.104790010322250183839876322541518), RC(0.140653259715525918745189590510238),
                                RC(0.169004726639267902826583426598550), RC(0.190350578064785409913256402421014),
                                RC(0.204432940075298892414161999234649), RC(0.209482141084727828012999174891714),
                                RC(0.204432940075298892414161999234649), RC(0.190350578064785409913256402421014),
                                RC(0.169004726639267902826583426598550), RC(0.140653259715525918745189590510238),
                                RC(0.104790010322250183839876322541518), RC(0.063092092629978553290700663189204),
                                RC(0.022935322010529224963732008058970), RC(0.0)};
BRDF_CONST real GK15_WDL[16] = {RC(0.0229353220105292249637320080589700), RC(-0.0663928735388911399799107694898780),
                                RC(0.104790010322250183839876322541518),  RC(-0.139052131773750749156278180913542),
                                RC(0.169004726639267902826583426598550),  RC(-0.191479472440333535037113373067961),
                                RC(0.204432940075298892414161999234649),  RC(-0.208477042588741559742102865924613),
                                RC(0.204432940075298892414161999234649),  RC(-0.191479472440333535037113373067961),
                                RC(0.169004726639267902826583426598550),  RC(-0.139052131773750749156278180913542),
                                RC(0.104790010322250183839876322541518),  RC(-0.0663928735388911399799107694898780),
                                RC(0.0229353220105292249637320080589700), RC(0.0)};

/* cos(k pi/32), k = 0..32: the trapezoid nodes of a full azimuth half-circle (exact to 30 digits). */
BRDF_CONST real COS_PI32[33] = {RC(1.00000000000000000000000000000),
                                RC(0.995184726672196886244836953109),
                                RC(0.980785280403230449126182236134),
                                RC(0.956940335732208864935797886980),
                                RC(0.923879532511286756128183189397),
                                RC(0.881921264348355029712756863660),
                                RC(0.831469612302545237078788377618),
                                RC(0.773010453362736960810906609758),
                                RC(0.707106781186547524400844362105),
                                RC(0.634393284163645498215171613225),
                                RC(0.555570233019602224742830813949),
                                RC(0.471396736825997648556387625905),
                                RC(0.382683432365089771728459984030),
                                RC(0.290284677254462367636192375817),
                                RC(0.195090322016128267848284868477),
                                RC(0.0980171403295606019941955638886),
                                RC(0.0),
                                RC(-0.0980171403295606019941955638886),
                                RC(-0.195090322016128267848284868477),
                                RC(-0.290284677254462367636192375817),
                                RC(-0.382683432365089771728459984030),
                                RC(-0.471396736825997648556387625905),
                                RC(-0.555570233019602224742830813949),
                                RC(-0.634393284163645498215171613225),
                                RC(-0.707106781186547524400844362105),
                                RC(-0.773010453362736960810906609758),
                                RC(-0.831469612302545237078788377618),
                                RC(-0.881921264348355029712756863660),
                                RC(-0.923879532511286756128183189397),
                                RC(-0.956940335732208864935797886980),
                                RC(-0.980785280403230449126182236134),
                                RC(-0.995184726672196886244836953109),
                                RC(-1.00000000000000000000000000000)};

/* Trapezoid rules on the azimuth half-circle [0, pi] with n = 16 and 32 intervals (cos(k pi/32) is
 * COS_PI32): the weights (1/2 at the ends), and the weights minus those of the n/2-interval rule on
 * the even nodes, (-1/2, 1, -1, ..., 1, -1/2), whose sum against f is the error estimate. */
BRDF_CONST real COS_PI16[17] = {
    RC(1.00000000000000000000000000000),   RC(0.980785280403230449126182236134),  RC(0.923879532511286756128183189397),
    RC(0.831469612302545237078788377618),  RC(0.707106781186547524400844362105),  RC(0.555570233019602224742830813949),
    RC(0.382683432365089771728459984030),  RC(0.195090322016128267848284868477),  RC(0.0),
    RC(-0.195090322016128267848284868477), RC(-0.382683432365089771728459984030), RC(-0.555570233019602224742830813949),
    RC(-0.707106781186547524400844362105), RC(-0.831469612302545237078788377618), RC(-0.923879532511286756128183189397),
    RC(-0.980785280403230449126182236134), RC(-1.00000000000000000000000000000)};
BRDF_CONST real TRAP16_W[17] = {RC(0.5), RC(1.0), RC(1.0), RC(1.0), RC(1.0), RC(1.0), RC(1.0), RC(1.0), RC(1.0),
                                RC(1.0), RC(1.0), RC(1.0), RC(1.0), RC(1.0), RC(1.0), RC(1.0), RC(0.5)};
BRDF_CONST real TRAP16_D[17] = {RC(-0.5), RC(1.0),  RC(-1.0), RC(1.0),  RC(-1.0), RC(1.0),  RC(-1.0), RC(1.0), RC(-1.0),
                                RC(1.0),  RC(-1.0), RC(1.0),  RC(-1.0), RC(1.0),  RC(-1.0), RC(1.0),  RC(-0.5)};
BRDF_CONST real TRAP32_W[33] = {RC(0.5), RC(1.0), RC(1.0), RC(1.0), RC(1.0), RC(1.0), RC(1.0), RC(1.0), RC(1.0),
                                RC(1.0), RC(1.0), RC(1.0), RC(1.0), RC(1.0), RC(1.0), RC(1.0), RC(1.0), RC(1.0),
                                RC(1.0), RC(1.0), RC(1.0), RC(1.0), RC(1.0), RC(1.0), RC(1.0), RC(1.0), RC(1.0),
                                RC(1.0), RC(1.0), RC(1.0), RC(1.0), RC(1.0), RC(0.5)};
BRDF_CONST real TRAP32_D[33] = {
    RC(-0.5), RC(1.0),  RC(-1.0), RC(1.0),  RC(-1.0), RC(1.0),  RC(-1.0), RC(1.0),  RC(-1.0), RC(1.0),  RC(-1.0),
    RC(1.0),  RC(-1.0), RC(1.0),  RC(-1.0), RC(1.0),  RC(-1.0), RC(1.0),  RC(-1.0), RC(1.0),  RC(-1.0), RC(1.0),
    RC(-1.0), RC(1.0),  RC(-1.0), RC(1.0),  RC(-1.0), RC(1.0),  RC(-1.0), RC(1.0),  RC(-1.0), RC(1.0),  RC(-0.5)};

/* The same weights for the n/2-interval rule minus the n/4-interval one (on the nodes k = 0 mod 2:
 * 2 (-1/2, 1, -1, ..., 1, -1/2) on the even nodes, 0 on the odd ones): the trapezoid ladder's
 * second difference (trap_error). */
BRDF_CONST real TRAP16_D2[17] = {RC(-1.0), RC(0.0), RC(2.0), RC(0.0),  RC(-2.0), RC(0.0), RC(2.0), RC(0.0), RC(-2.0),
                                 RC(0.0),  RC(2.0), RC(0.0), RC(-2.0), RC(0.0),  RC(2.0), RC(0.0), RC(-1.0)};
BRDF_CONST real TRAP32_D2[33] = {
    RC(-1.0), RC(0.0),  RC(2.0),  RC(0.0), RC(-2.0), RC(0.0),  RC(2.0),  RC(0.0), RC(-2.0), RC(0.0),  RC(2.0),
    RC(0.0),  RC(-2.0), RC(0.0),  RC(2.0), RC(0.0),  RC(-2.0), RC(0.0),  RC(2.0), RC(0.0),  RC(-2.0), RC(0.0),
    RC(2.0),  RC(0.0),  RC(-2.0), RC(0.0), RC(2.0),  RC(0.0),  RC(-2.0), RC(0.0), RC(2.0),  RC(0.0),  RC(-1.0)};

/* A square root of the integrand at cos(phi) = cphi (Fresnel's critical angle) close to an azimuth
 * arc's end phi = pi without a break there: beyond the arc (cphi < -1), singular at pi -+ i a with
 * a = acosh(-cphi), or on it at fk = acos(cphi) near pi, mirrored at 2 pi - fk beyond the break at
 * fk. Panels graded 4-fold towards *g (pi, or fk) from the returned distance resolve it, where that
 * distance is under 1 (cphi > -SQRT_NEAR_CK = -cosh(1)), resp. under fk/4; 0: no grading. Never
 * closer than SQRT_NEAR_MIN. */
#define SQRT_NEAR_CK RC(1.5430806348152437)
#define SQRT_NEAR_MIN RC(1e-6)
BRDF_FN real sqrt_near_pi(real cphi, real* g) {
  if (cphi <= RC(-1.0) && cphi > -SQRT_NEAR_CK) {
    *g = BRDF_PI;
    return fmax(acosh(-cphi), SQRT_NEAR_MIN);
  }
  if (cphi > RC(-1.0) && cphi < RC(1.0)) {
    real fk = acos(cphi);
    if (BRDF_PI - fk < RC(0.25) * fk) {
      *g = fk;
      return fmax(BRDF_PI - fk, SQRT_NEAR_MIN);
    }
  }
  return RC(0.0);
}

/* Insertion sort of a few breakpoints (a few dozen at most), ascending. */
BRDF_FN void sort_ascending(real* v, int n) {
  for (int i = 1; i < n; ++i)
    for (int j = i; j > 0 && v[j - 1] > v[j]; --j) {
      real t = v[j];
      v[j] = v[j - 1];
      v[j - 1] = t;
    }
}

/* The error of a GK15 value from kg = |K15 - G7| and resasc = int |f - mean f| (by the Kronrod rule):
 * QUADPACK's qk15 rescaling (Piessens et al. 1983, QUADPACK, sec. 3.2.1, qk15.f):
 *   err = resasc min(1, (C kg/resasc)^(3/2)),
 * which assumes K15 converges faster than G7 by the power 3/2, as on integrands analytic around
 * the panel. QUADPACK's C = 200 is a margin for double precision; the estimators here use
 * C = GK_SHARP_C = 3, measured: on every NDF/GAF pair the largest miss of the texel's estimate
 * against its true error is 5.5e-8
 * of the value (edges and node grids included; hemisphere_texel.h HEMI_ERR_FLOOR_SHARP covers it),
 * and a
 * 128x128 ggx + smith-correlated table refines 0.3% of its texels at HEMI_BAKE_TARGET (C = 10:
 * 15%). sharp = 0 keeps kg, a bound of K15's error wherever G7's error exceeds K15's. */
#define GK_SHARP_C RC(3.0)
BRDF_FN real gk_error(real kg, real resasc, int sharp) {
  if (!sharp || !(resasc > RC(0.0))) return kg;
  real q = fmin(RC(1.0), GK_SHARP_C * kg / resasc);
  return resasc * q * sqrt(q);
}
#if defined(__OPENCL_C_VERSION__) && !defined(BRDF_LANE_PASS)
/* gk_error(kg, resasc, 1) lane by lane, with its operations, so each lane's bits: gk_error4 for two
 * panels' two moments (azimuth.h hemi_phi_gk_pair), or one panel's in .xy (hemi_phi_gk);
 * gk_error16 for one panel of each of 16 outer nodes (azimuth_lanes.h hemi_arcs_lanes). */
#define BRDF_GK_ERROR_LANES(T, NAME)                                       \
  BRDF_FN T NAME(T kg, T resasc) {                                         \
    T q = fmin((T)(1.0f), (float)GK_SHARP_C * kg / resasc);                \
    return select(kg, resasc * q * sqrt(q), isgreater(resasc, (T)(0.0f))); \
  }
BRDF_GK_ERROR_LANES(float4, gk_error4)
BRDF_GK_ERROR_LANES(float16, gk_error16)
#undef BRDF_GK_ERROR_LANES
#endif

/* The error of the trapezoid rule T_n on a smooth periodic integrand from d1 = |T_n - T_{n/2}| and
 * d2 = |T_{n/2} - T_{n/4}|: its error decays geometrically in n, e_n ~ C q^n (Trefethen and
 * Weideman 2014, The exponentially convergent trapezoidal rule, SIAM Review 56(3), Thm. 3.2), so
 * with d1 ~ e_{n/2} and d2 ~ e_{n/4}: e_n ~ e_{n/2}^2/e_{n/4} = d1 (d1/d2)^2. Where the ladder is
 * not converging geometrically (d1 >= d2) it keeps d1, the error of T_{n/2}. */
BRDF_FN real trap_error(real d1, real d2) {
  if (!(d2 > d1)) return d1;
  real q = d1 / d2;
  return d1 * q * q;
}
#if defined(__OPENCL_C_VERSION__) && !defined(BRDF_LANE_PASS)
/* trap_error lane by lane, with its operations (azimuth_lanes.h hemi_trap_lanes: one trapezoid of
 * each of 16 outer nodes). */
BRDF_FN float16 trap_error16(float16 d1, float16 d2) {
  float16 q = d1 / d2;
  return select(d1, d1 * q * q, isgreater(d2, d1));
}
#endif
#endif /* BRDF_QUADRATURE_H */
