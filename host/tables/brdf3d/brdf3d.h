// The brdf3d family's names (tables/brdf3d/brdf3d.cpp) and its kernel's launch
// (tables/brdf3d/brdf3d_slab.cpp).
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "cl/runner.h"
#include "tables/job.h"

namespace brdfbake {

// The 3D table's kernel (kernels/brdf3d.cl bake_brdf3d) for the pair, to prepare.
KernelNeed brdf3dKernel(int ndf, int gaf);
// One slab of a 3D BRDF table: slices z0 .. z0 + zn - 1 of the spec's table, one plane per
// channel, [((z - z0) * ny + y) * nx + x].
std::vector<std::vector<float>> brdf3dSlab(KernelRunner& runner, const Brdf3dSpec& spec, int z0, int zn);

// brdf3d_<ndf>_<gaf>[_<fresnel>][_<diffuse>]_angles.exr (or _rusinkiewicz.exr, or .binary for MERL's layout).
std::string volumeFileName(const VolumeJob& job);
// The atlas grid for `depth` slices: an exact columns x rows split no wider than 4:1 when there is
// one (180 -> 15x12, 512 -> 32x16), else ceil(sqrt(depth)) columns and as many rows as needed.
std::pair<int, int> atlasGrid(int depth);

}  // namespace brdfbake
