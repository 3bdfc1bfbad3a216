// The reference's exact Smith Lambda of the blinn-phong and gaussian NDFs (Heitz 2014 eq. 17-18),
// independent of kernels/brdf/smith_tables.h; shared by reference.cpp's GAFs.
#pragma once
#include "common/brdf_host.h"

namespace brdfbake::reference::detail {

// cos(theta) Lambda_exact of the NDF (its parameters dp) for the direction with cosine c, by
// adaptive quadrature to 1e-11 relative.
double cLambdaQuad(int ndf, const brdf64::BrdfParams& dp, double c);
// The same from a table per (NDF, alpha), shared by every thread, 8-point Lagrange in between.
double cLambdaTabled(int ndf, const brdf64::BrdfParams& dp, double c);

}  // namespace brdfbake::reference::detail
