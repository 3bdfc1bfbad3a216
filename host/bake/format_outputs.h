// A baked table -> one output file per requested format (--format), each with its own metadata:
// brdf.format, brdf.precision and brdf.error with that file's storage rounding. The files join the
// bake's output set (bake/output_set.h), so they land together with the others or not at all.
#pragma once
#include <deque>
#include <string>
#include <vector>

#include "bake/bake.h"
#include "bake/output_set.h"
#include "formats/storage.h"
#include "tables/job.h"

namespace brdfbake {

class KernelRunner;

// A file of the set and the error bound its metadata states (the bake's report lists each).
struct PlannedFile {
  OutputFile file;
  double errorBound = 0;
};

// The precision format `f` stores when the bake asked for `p`: png16 is always unorm16 (its own
// mapping); the others store p.
Precision effectivePrecision(FileFormat f, Precision p);
// `stem` + the format's extension(s): the header format gives two files, .h and .mjs.
std::vector<std::string> formatPaths(const std::string& stem, FileFormat f);
// The path without its extension (".exr", ".binary").
std::string pathStem(const std::string& path);

// The files of a 2D table `img` as computeTable (or merlTable, ashikhminTexture) made it, whose
// brdf.error includes the storage rounding of `exrPrecision` (float32 or float16). Checks every
// format first: a unorm precision with values outside [0, 1] throws Error(kExitUsage) naming the
// table, its range and the formats that can hold it. `img` must outlive the files; per-format
// metadata is kept in `keep`.
std::vector<PlannedFile> tableOutputs(const TableJob& job, const TableImage& img, std::deque<TableImage>& keep);

// tableOutputs for the bake: appends the files to `files` and one report per file (`base` with the
// file's path and error bound) to `reports`.
void addTableFiles(const TableJob& job, const TableImage& img, const TableReport& base, std::deque<TableImage>& keep,
                   std::vector<OutputFile>& files, std::vector<TableReport>& reports);

// The files of a 3D table in the non-EXR formats of `job` (KTX2, DDS: 3D textures; header): each
// bakes the table slab by slab on `runner` while it writes (never whole in memory). `atlasHeader`
// is volumeHeader(job). *seconds accumulates kernel time.
std::vector<PlannedFile> volumeFormatOutputs(KernelRunner& runner, const VolumeJob& job, const TableImage& atlasHeader,
                                             double* seconds);

}  // namespace brdfbake
