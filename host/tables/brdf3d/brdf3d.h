// The brdf3d family's names (tables/brdf3d/brdf3d.cpp).
#pragma once
#include <string>
#include <utility>

#include "tables/job.h"

namespace brdfbake {

// brdf3d_<ndf>_<gaf>[_<fresnel>][_<diffuse>]_angles.exr (or _rusinkiewicz.exr, or .binary for MERL's layout).
std::string volumeFileName(const VolumeJob& job);
// The atlas grid for `depth` slices: an exact columns x rows split no wider than 4:1 when there is
// one (180 -> 15x12, 512 -> 32x16), else ceil(sqrt(depth)) columns and as many rows as needed.
std::pair<int, int> atlasGrid(int depth);

}  // namespace brdfbake
