// The shared BRDF code (kernels/brdf, kernels/integrate) compiled for the host, twice:
// brdf64 in double (model tests, the reference's integrand) and brdf32 in float (the device's
// arithmetic, one lane: same formulas and rules, but lane sums in a different order, so results
// agree with the device's to float rounding, not bit for bit).
#pragma once
#include "brdf/compat.h"
#define BRDF_HOST_NAMESPACE 1

namespace brdf64 {
typedef double real;
#include "brdf/compat.h"
#include "brdf/smith_tables.h"
#include "brdf/ndf.h"
#include "brdf/gaf.h"
#include "brdf/fresnel.h"
#include "brdf/diffuse.h"
#include "brdf/brdf.h"
#include "brdf/anisotropic.h"
#include "integrate/integrand.h"
#include "integrate/quadrature.h"
#include "integrate/azimuth.h"
#include "integrate/hemisphere.h"
#include "integrate/hemisphere_texel.h"
#include "integrate/sheen.h"
#include "integrate/albedo_avg.h"
#include "integrate/diffuse_albedo.h"
#include "brdf/btdf.h"
#include "integrate/dielectric.h"
}  // namespace brdf64

namespace brdf32 {
typedef float real;
#include "brdf/compat.h"
#include "brdf/smith_tables.h"
#include "brdf/ndf.h"
#include "brdf/gaf.h"
#include "brdf/fresnel.h"
#include "brdf/diffuse.h"
#include "brdf/brdf.h"
#include "brdf/anisotropic.h"
#include "integrate/integrand.h"
#include "integrate/quadrature.h"
#include "integrate/azimuth.h"
#include "integrate/hemisphere.h"
#include "integrate/hemisphere_texel.h"
#include "integrate/sheen.h"
#include "integrate/albedo_avg.h"
#include "integrate/diffuse_albedo.h"
#include "brdf/btdf.h"
#include "integrate/dielectric.h"
}  // namespace brdf32
