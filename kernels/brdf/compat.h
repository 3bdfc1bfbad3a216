/* compat.h: the few differences between OpenCL C and C++ that the shared BRDF code needs.
 *
 * Everything under kernels/brdf/ and kernels/integrate/ is written in the subset of C that both
 * OpenCL C 1.2 and C++17 compile. The device compiles it with `real` = float; the host includes it
 * inside a namespace that defines `real` (double for tests, float to mirror the device).
 *   RC(x)      a floating literal of type real (0.5f on the device, (real)0.5 on the host)
 *   BRDF_FN    storage class of shared functions
 *   acc_t      accumulator type: double where the device has fp64, else float (Kahan-compensated)
 */
#ifndef BRDF_COMPAT_H
#define BRDF_COMPAT_H

#ifdef __OPENCL_C_VERSION__
#define BRDF_FN static inline
#define RC(x) x##f
typedef float real;
#if defined(cl_khr_fp64) && !defined(BRDF_NO_FP64)
#pragma OPENCL EXTENSION cl_khr_fp64 : enable
typedef double acc_t;
#define BRDF_ACC_IS_DOUBLE 1
#else
typedef float acc_t;
#define BRDF_ACC_IS_DOUBLE 0
#endif
#define BRDF_CONST constant
#else /* C++ host */
#include <cmath>
#define BRDF_FN static inline
#define RC(x) ((real)(x))
#define BRDF_CONST static const
#define BRDF_ACC_IS_DOUBLE 1
#endif

#define BRDF_PI RC(3.14159265358979323846)
#define BRDF_INV_PI RC(0.31830988618379067154)
#define BRDF_SQRT_PI RC(1.77245385090551602730)

#endif /* BRDF_COMPAT_H */

/* Per-namespace part for the host: pull the overloaded math functions into scope. This block is
 * outside the include guard on purpose: the host includes the models once per precision. */
#ifndef __OPENCL_C_VERSION__
using std::acos;
using std::atan;
using std::atan2;
using std::cos;
using std::erf;
using std::erfc;
using std::exp;
using std::expm1;
using std::fabs;
using std::fmax;
using std::fmin;
using std::log;
using std::log1p;
using std::sin;
using std::sqrt;
using std::tan;
typedef double acc_t;
#endif
