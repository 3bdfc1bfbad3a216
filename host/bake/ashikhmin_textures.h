// The three factorised textures of the anisotropic Ashikhmin-Shirley BRDF (seed 001; formulas in
// kernels/brdf/anisotropic.h, conventions in docs/MODELS.md "Ashikhmin-Shirley: factorised
// textures", the recombining shader in shaders/ashikhmin_shirley.glsl). Closed forms, computed on
// the host in double (brdf64): `brdfbake bake --table ashikhmin-shirley` needs no OpenCL program.
#pragma once
#include <string>

#include "formats/table_image.h"

namespace brdfbake {

// Tex2's second coordinate: t = sqrt(n_u) (h.x)/kAsTex2Scale + kAsTex2Offset, so the texture spans
// sqrt(n_u) h.x in [-scale/2, scale/2] = [-5, 5], where Tex2 <= exp(-12.5) = 3.7e-6 (the seed's
// scale 5 stops at [-2.5, 2.5], where Tex2 is still 0.044, and clamping keeps that floor).
constexpr double kAsTex2Scale = 10.0;
constexpr double kAsTex2Offset = 0.5;
constexpr int kAsTextures = 3;

// "as_tex0.exr", "as_tex1.exr", "as_tex2.exr".
std::string ashikhminFileName(int texture);

// Throws Error(kExitUsage) naming the flag and the accepted range when the textures cannot be
// baked as asked: size below 2, HALF with size above 127 (Tex1 = F/(u v) reaches 4 n^2 at the
// corner texel, above half's 65504), the node grid (Tex1 is infinite at u = 0 and v = 0).
void checkAshikhminRequest(int size, bool half, bool nodeGrid);

// Texture 0, 1 or 2 on an n x n texel-centre grid, with its metadata; brdf.error is the largest
// error of any stored value (after rounding to FLOAT or HALF) against the exact value evaluated
// in long double from the seed's formula, relative to max(1, |value|). Throws Error(kExitSoftware)
// if a texel is not finite.
TableImage ashikhminTexture(int texture, int n, bool half);

}  // namespace brdfbake
