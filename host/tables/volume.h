// 3D isotropic BRDF tables (--table brdf3d): the header that describes them, the writer that bakes
// them slab by slab into an EXR atlas (never the whole table in memory), and the way back from a
// file to the table and the material it holds (brdfbake sample, tests).
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "formats/format_outputs.h"
#include "formats/output_set.h"
#include "tables/job.h"

namespace brdfbake {

class KernelRunner;

// The header attributes of a 3D table's file (its planes empty): every parameter of the material,
// the axes and grid, the atlas, the grazing policy, the value stored and its error figures.
TableImage volumeHeader(const VolumeJob& job);

// The OutputFile that bakes `job` on `runner` when the output set writes it: one slab (a row of
// atlas slices) at a time, EXR or MERL. *seconds (optional) accumulates kernel time; *peakSlab
// (optional) records the largest slab in bytes.
OutputFile volumeOutput(KernelRunner& runner, const VolumeJob& job, const TableImage& header, double* seconds = nullptr,
                        uint64_t* peakSlab = nullptr);

// Writes a 3D table of n = (nx, ny, nz) texels as an EXR atlas of its z-slices (`cols` per row,
// left to right, then top to bottom; unused slots 0) to the temporary `tmp` for `path`, one atlas
// row at a time: slab(z0, zn) returns slices z0 .. z0 + zn - 1 as one plane per channel (1: the
// same in R, G, B; 3: R, G, B), [((z - z0) * ny + y) * nx + x]. Throws Error(kExitSoftware) naming
// `what` when a value is not finite.
void writeAtlasTemporary(const std::string& tmp, const std::string& path, const TableImage& header, bool half,
                         std::array<int, 3> n, int cols,
                         const std::function<std::vector<std::vector<float>>(int z0, int zn)>& slab,
                         const std::string& what);

// The most bytes the file can take (uncompressed data, header and offsets): checked against the
// free space before anything is written.
uint64_t volumeBytesBound(const VolumeJob& job);
// Throws Error(kExitCantCreat) when the volumes cannot fit in the free space under `dir` (its
// nearest existing ancestor), naming the need and what is free.
void checkVolumeSpace(const std::string& dir, const std::vector<VolumeJob>& volumes);

// The spec a brdf3d file's header describes (material, axes, grid, size), and its atlas grid.
// Throws Error(kExitDataErr) naming the attribute that is missing or unreadable.
Brdf3dSpec specFromHeader(const std::string& path, const TableImage& img, int* cols, int* rows);
// The table's planes in slab order, [(z * ny + y) * nx + x], out of the atlas.
std::vector<std::vector<float>> volumeFromAtlas(const TableImage& img, const Brdf3dSpec& s, int cols);

// `brdfbake sample FILE --at A,B,C` (degrees): the trilinear lookup of each channel next to the
// exact value, as text.
std::string sampleReport(const std::string& path, const std::array<double, 3>& atDegrees);

// The files of a 3D table in the non-EXR formats of `job` (KTX2, DDS: 3D textures; header): each
// bakes the table slab by slab on `runner` while it writes (never whole in memory). `atlasHeader`
// is volumeHeader(job). *seconds accumulates kernel time.
std::vector<PlannedFile> volumeFormatOutputs(KernelRunner& runner, const VolumeJob& job, const TableImage& atlasHeader,
                                             double* seconds);

}  // namespace brdfbake
