// Every model and estimator the host uses from kernels/, included into a namespace that defines
// `real` (host/common/brdf_host.h, once per precision: no guard of its own). Each header brings
// the headers it uses.
#include "brdf/anisotropic.h"
#include "brdf/brdf.h"
#include "integrate/dielectric.h"
#include "integrate/diffuse_albedo.h"
#include "integrate/hemisphere_texel.h"
#include "integrate/ltc_fit.h"
