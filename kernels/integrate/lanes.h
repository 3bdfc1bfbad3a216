/* lanes.h: the pointwise functions (the models of brdf/ and the integrand) compiled a second time
 * on the device, with `real` = lane_t (compat.h "Lanes"), after their one-value pass. The
 * integrators that evaluate BRDF_LANES nodes at once (azimuth.h, diffuse_albedo.h) include this.
 * The host has one lane (lane_t = real): the one-value pass is all it needs. */
/* Once per pass (compat.h "Passes"). */
#if defined(BRDF_SECOND_PASS) ? !defined(BRDF_LANES_H_2) : !defined(BRDF_LANES_H)
#ifdef BRDF_SECOND_PASS
#define BRDF_LANES_H_2
#else
#define BRDF_LANES_H
#endif
#include "integrate/integrand.h"
#include "brdf/diffuse.h"
#ifdef __OPENCL_C_VERSION__
#if BRDF_REAL_IS_DOUBLE
#error "the lane pass needs real = float (a program without BRDF_DEVICE_DOUBLE)"
#endif
#define BRDF_LANE_PASS 1
#define BRDF_SECOND_PASS 1
#undef real
#define real lane_t
#include "integrate/integrand.h"
#include "brdf/diffuse.h"
#undef real
#define real float
#undef BRDF_SECOND_PASS
#undef BRDF_LANE_PASS
#endif
#endif /* BRDF_LANES_H */
