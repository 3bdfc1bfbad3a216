// A baked table -> one output file per requested format (--format), each with its own metadata:
// brdf.format, brdf.precision and brdf.error with that file's storage rounding. The files join the
// bake's output set (formats/output_set.h), so they land together with the others or not at all.
// Every format's metadata is assembled here, next to the writers.
#pragma once
#include <deque>
#include <string>
#include <vector>

#include "formats/layout.h"
#include "formats/output_set.h"
#include "formats/storage.h"
#include "formats/writers.h"

namespace brdfbake {

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

// Where and how a 2D table is written: its path (the EXR's; the other formats replace the
// extension), the formats, the precision they store, whether the EXR is half, the engine layout.
struct FileSpec {
  std::string path;
  std::vector<FileFormat> formats = {FileFormat::Exr};
  Precision precision = Precision::Float32;
  bool half = false;
  TableLayout layout = {};
  std::string layoutName;  // recorded as brdf.layout (with the preset's sampling recipe)
};

// The files of a 2D table `img` as its family made it, whose brdf.error includes the storage
// rounding of the EXR's precision (float32 or float16). Checks every format first: a unorm
// precision with values outside [0, 1] throws Error(kExitUsage) naming the table, its range and the
// formats that can hold it. `img` must outlive the files; per-format metadata is kept in `keep`.
std::vector<PlannedFile> tableOutputs(const FileSpec& spec, const TableImage& img, std::deque<TableImage>& keep);

// The metadata of the file of format `f` for table `src`: the table's own, plus brdf.format,
// brdf.precision and brdf.error = `computeError` (the table's error without storage) + `storage`.
TableImage formatMetadata(const TableImage& src, FileFormat f, Precision p, double computeError, double storage,
                          int channels);
// The OutputFile that writes `src` in the binary or header format `f` (KTX2, DDS, header; `js`:
// the header's .mjs twin) with metadata `meta`.
OutputFile formatWriter(const std::string& path, FileFormat f, Precision p, const TableImage& meta,
                        const SliceSource& src, const std::string& stem, bool js);

}  // namespace brdfbake
