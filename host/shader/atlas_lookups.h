// The generated lookups of the tables stored as atlases of 2D slices: brdf3d (the BRDF over three
// angles, with the angles from unit vectors) and the rough-dielectric cube (E_R, E_T over mu, r and
// eta). shader/shader_gen.h describes the two paths every lookup has.
#pragma once
#include <string>

#include "formats/table_image.h"
#include "formats/shader_lang.h"

namespace brdfbake::shadergen {

// P_index, P_slice, P_lookup[Exact], P_texel, P_f[Exact] and P_angles of a brdf3d table.
std::string lookups3d(const Lang& L, const std::string& P, const std::string& path, const TableImage& h);
// P_index (mu, r, eta), the atlas lookups and P_albedos[Exact] of a dielectric table.
std::string lookupsDielectric(const Lang& L, const std::string& P, const std::string& path, const TableImage& h);

}  // namespace brdfbake::shadergen
