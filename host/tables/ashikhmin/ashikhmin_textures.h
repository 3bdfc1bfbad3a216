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

// Grids (brdf.grid). Tex0 and Tex2 `node`: texel i at i/(n-1), so u = 1 holds Tex2's limit exactly
// and a shader's n.h -> 1 reads it rather than a clamped last texel centre (whose error is first
// order in 1/n); sample at (0.5 + (n-1) q)/n. Tex1 `upper-node`: texel i at (i+1)/n, so u = 1 and
// v = 1 (the highlight of a view along n) are texels while u = 0 and v = 0, where Tex1 is
// infinite, are not; sample at q - 0.5/n (GL clamps below 1/n to the first texel).
bool ashikhminNodeGrid(int texture);
double ashikhminCoord(int texture, int i, int n);  // the value of texel i's axis coordinate

// "as_tex0.exr", "as_tex1.exr", "as_tex2.exr".
std::string ashikhminFileName(int texture);

// The exact value of texture `t`'s channel `c` at its coordinates (u, y), from the formulas as
// printed in long double (Tex2's y is t, its argument v = scale (t - offset)): the reference.
double ashikhminExact(int t, int c, double u, double y);

// Throws Error(kExitUsage) naming the flag and the accepted range when the textures cannot be
// baked as asked: size below 2, HALF with size above 255 (Tex1 = F/(u v) reaches n^2 at the
// corner texel, above half's 65504), --grid node (the textures' grids are fixed, see below).
void checkAshikhminRequest(int size, bool half, bool nodeGrid);

// Texture 0, 1 or 2 on its n x n grid, with its metadata; brdf.error is the largest
// error of any stored value (after rounding to FLOAT or HALF) against the exact value evaluated
// in long double from the seed's formula, relative to max(1, |value|). Throws Error(kExitSoftware)
// if a texel is not finite.
TableImage ashikhminTexture(int texture, int n, bool half);

}  // namespace brdfbake
