// `brdfbake render --light quad`: spheres over roughness under a rectangle light, shaded on GL with
// the LTC tables and the generated lookup and polygon code (shader/shader_gen.h shaderForFiles; the polygon
// integral from tables/ltc/ltc_shader.cpp), each
// pixel against the exact integral of the BRDF over the light (host quadrature with kernels/brdf).
#pragma once
#include "render/render.h"

namespace brdfbake {

// Writes DIR/ltc_quad.{exr,png} and the tables under DIR/tables; prints the largest deviation and
// its bound. Returns 1 when a pixel is past its bound.
int runLtcRender(const RenderOptions& o);

}  // namespace brdfbake
