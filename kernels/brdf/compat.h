/* compat.h: the few differences between OpenCL C and C++ that the shared BRDF code needs.
 *
 * Everything under kernels/brdf/ and kernels/integrate/ is written in the subset of C that both
 * OpenCL C 1.2 and C++17 compile, plus one Clang extension on the device: functions are
 * __attribute__((overloadable)) (PoCL and the other Clang-based OpenCL compilers accept it). The
 * device compiles it with `real` = float (a macro there); the host includes it inside a namespace
 * that defines `real` (double for tests, float to mirror the device).
 *   RC(x)      a floating literal of type real (0.5f on the device, (real)0.5 on the host)
 *   BRDF_FN    storage class of shared functions (overloadable on the device, see lanes)
 *   acc_t      accumulator type: double where the device has fp64, else float
 *
 * Lanes. PoCL does not vectorise across work-items when a kernel has loops, so the integrators
 * evaluate BRDF_LANES quadrature nodes of one texel at once: lane_t is float16 on the device and
 * plain `real` on the host (BRDF_LANES = 1). The pointwise functions (models in brdf/, the integrand
 * in integrate/integrand.h) are branch-free in their lane arguments (selects, never `if` on a
 * value) and the device compiles them twice, with `real` = float and `real` = lane_t
 * (BRDF_LANE_PASS defined), overloaded by argument type. Parts that only exist once (ids, structs,
 * grid maps) sit in `#ifndef BRDF_LANE_PASS` blocks.
 *   lane_load(tab, k)  tab[k .. k + BRDF_LANES) as a lane_t;  lane_store(x, arr, k) the reverse
 *   lane_sum(x)        the sum of x's lanes
 *   param_t            a value derived from the per-texel parameters: one value in both passes
 *   tab_at(tab, i)     tab[i] of a BRDF_CONST float table, i an integer held in a real (per lane)
 *
 * Passes. Each header includes the headers it uses (paths relative to kernels/) and is read at
 * most once per pass: a first pass, and a second with BRDF_SECOND_PASS defined, which is the
 * device's lane pass (integrate/lanes.h) and the host's float namespace (host/common/brdf_host.h).
 * The guard at the top of each header says so; this file's own guard is single-pass (its macros
 * are the same in both), except the host's per-namespace part below. On the device the host joins
 * a program's files by following the #include lines from its .cl file (host/cl/programs.cpp).
 */
#ifndef BRDF_COMPAT_H
#define BRDF_COMPAT_H

#ifdef __OPENCL_C_VERSION__
#define BRDF_FN static inline __attribute__((overloadable))
/* A shared function kept out of line (integrand.h hemi_fresnel_weight says why) */
#define BRDF_FN_OUTLINE static __attribute__((overloadable, noinline))
#if defined(BRDF_DEVICE_DOUBLE) && defined(cl_khr_fp64)
/* Programs that evaluate the models at points rather than integrate them (kernels/brdf3d.cl) ask
 * for `real` = double where the device has it: one pass, no lanes. */
#pragma OPENCL EXTENSION cl_khr_fp64 : enable
#define RC(x) x
#define real double
typedef double param_t;
#define BRDF_REAL_IS_DOUBLE 1
#else
#define RC(x) x##f
#define real float
typedef float param_t;
#define BRDF_REAL_IS_DOUBLE 0
#endif
#define BRDF_LANES 16
typedef float16 lane_t;
#define lane_load(tab, k) vload16(0, (tab) + (k))
#define lane_store(x, arr, k) vstore16((x), 0, (arr) + (k))
static inline float lane_sum(float16 x) {
  float8 a = x.lo + x.hi;
  float4 b = a.lo + a.hi;
  float2 c = b.lo + b.hi;
  return c.x + c.y;
}
/* lane_sum of four (two) lane vectors at once, (lane_sum(a), lane_sum(b), ...): one reduction tree,
 * each step halving a vector that holds all of them, instead of one tree each. A GK15 panel reduces
 * six vectors (azimuth.h), a trapezoid six too; these measured faster than six lane_sum each
 * (docs/performance.md, "Kernel choices"). */
static inline float4 lane_sum4(float16 a, float16 b, float16 c, float16 d) {
  float16 ab = (float16)(a.lo + a.hi, b.lo + b.hi);
  float16 cd = (float16)(c.lo + c.hi, d.lo + d.hi);
  float16 x = (float16)(ab.even + ab.odd, cd.even + cd.odd); /* four partial sums of each */
  float8 y = x.even + x.odd;                                 /* two of each */
  return y.even + y.odd;
}
static inline float2 lane_sum2(float16 a, float16 b) {
  float16 ab = (float16)(a.lo + a.hi, b.lo + b.hi);
  float8 x = ab.even + ab.odd;
  float4 y = x.even + x.odd;
  return y.even + y.odd;
}
#if defined(cl_khr_fp64) && !defined(BRDF_NO_FP64)
#pragma OPENCL EXTENSION cl_khr_fp64 : enable
typedef double acc_t;
#define BRDF_ACC_IS_DOUBLE 1
#else
typedef float acc_t;
#define BRDF_ACC_IS_DOUBLE 0
#endif
#define BRDF_CONST constant
#define BRDF_TABLE constant /* a parameter pointing into a BRDF_CONST table */
/* tab_at(tab, i): tab[i] for an index held in a real (an integer value), gathered lane by lane;
 * for tables in constant memory and for private arrays (ndf.h smith_column), one definition per
 * address space */
#if BRDF_REAL_IS_DOUBLE
#define BRDF_TAB_AT_DOUBLE(PTR) \
  static inline __attribute__((overloadable)) double tab_at(PTR t, double i) { return (double)t[(int)i]; }
#else
#define BRDF_TAB_AT_DOUBLE(PTR)
#endif
#define BRDF_TAB_AT(PTR)                                                                                       \
  static inline __attribute__((overloadable)) float tab_at(PTR t, float i) { return t[(int)i]; }               \
  BRDF_TAB_AT_DOUBLE(PTR)                                                                                      \
  static inline __attribute__((overloadable)) float16 tab_at(PTR t, float16 i) {                               \
    int16 k = convert_int16(i);                                                                                \
    return (float16)(t[k.s0], t[k.s1], t[k.s2], t[k.s3], t[k.s4], t[k.s5], t[k.s6], t[k.s7], t[k.s8], t[k.s9], \
                     t[k.sa], t[k.sb], t[k.sc], t[k.sd], t[k.se], t[k.sf]);                                    \
  }
BRDF_TAB_AT(constant float*)
BRDF_TAB_AT(const float*)
#else /* C++ host */
#include <cmath>
#define BRDF_FN static inline
#define BRDF_FN_OUTLINE static inline
#define RC(x) ((real)(x))
#define BRDF_CONST static const
#define BRDF_TABLE const
#define BRDF_ACC_IS_DOUBLE 1
#define BRDF_LANES 1
#endif

#define BRDF_PI RC(3.14159265358979323846)
#define BRDF_INV_PI RC(0.31830988618379067154)
#define BRDF_SQRT_PI RC(1.77245385090551602730)

#endif /* BRDF_COMPAT_H */

/* Per-namespace part for the host: pull the overloaded math functions into scope and define the
 * one-lane helpers for this namespace's `real`. Once per pass, not under the guard above: the host
 * includes the models once per precision (host/common/brdf_host.h defines BRDF_HOST_NAMESPACE). */
#if !defined(__OPENCL_C_VERSION__) && defined(BRDF_HOST_NAMESPACE) && \
    (defined(BRDF_SECOND_PASS) ? !defined(BRDF_COMPAT_NS_2) : !defined(BRDF_COMPAT_NS))
#ifdef BRDF_SECOND_PASS
#define BRDF_COMPAT_NS_2
#else
#define BRDF_COMPAT_NS
#endif
using std::acos;
using std::atan;
using std::atan2;
using std::cos;
using std::erf;
using std::erfc;
using std::exp;
using std::expm1;
using std::fabs;
using std::floor;
using std::fma;
using std::fmax;
using std::fmin;
using std::log;
using std::lgamma;
using std::log1p;
using std::sin;
using std::sqrt;
using std::tan;
typedef double acc_t;
typedef real lane_t;
typedef real param_t;
BRDF_FN real lane_load(const real* tab, int k) { return tab[k]; }
BRDF_FN real lane_sum(real x) { return x; }
BRDF_FN void lane_store(real x, real* arr, int k) { arr[k] = x; }
BRDF_FN real tab_at(const float* t, real i) { return (real)t[(int)i]; }
#endif
