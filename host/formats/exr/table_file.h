// Reading and writing BRDF lookup tables as OpenEXR files.
//
// The table model, TableImage, and the checks every table passes live in
// formats/table_image.h (included here, so this header alone is enough for callers).
// Files are single-part scanline EXRs (FLOAT uncompressed, HALF ZIP), written atomically and
// deterministically (the same TableImage always gives byte-identical files).
//
// Implemented in exr_writer.cpp (writeTableExr, writeTableExrTemporary,
// temporaryPathFor), exr_reader.cpp (readTableExr, tableExrIsHalf) and
// exr_describe.cpp (describeTableExr).
#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "formats/table_image.h"

namespace brdfbake {

// Writes a single-part scanline EXR, channels FLOAT with NO_COMPRESSION (or HALF with
// ZIP_COMPRESSION when half == true), INCREASING_Y line order, with every attribute of `img` in
// the header.
//
// Validates first (validateTableImage, with the HALF range when half == true and
// OpenEXR's structural names reserved) and throws Error(kExitDataErr) naming the
// channel and texel if:
// width or height < 1, channels empty / not a subset of R,G,B,A in that order /
// planes.size() != channels.size(), a plane does not hold width*height values, a value
// is NaN or infinite, or (half == true) |value| > 65504.  Attribute names must be
// non-empty, unique across the three maps and not one of OpenEXR's structural names
// (channels, compression, dataWindow, displayWindow, lineOrder, pixelAspectRatio,
// screenWindowCenter, screenWindowWidth, tiles, type, name, version, chunkCount,
// maxSamplesPerPixel); otherwise kExitDataErr too.
//
// Atomic: writes a unique `<dir>/.<name>.brdfbake-tmp-XXXXXX` next to `path`, fsyncs it, then renames it
// onto `path`.  On failure the temp file is removed and Error is thrown whose message
// names `path`: kExitCantCreat if the temp file cannot be created or the rename fails,
// kExitIoErr for errors while writing.
//
// Deterministic: no timestamps or other varying attributes, fixed zip level, and
// OpenEXR is called with numThreads = 0 (the global thread count is not touched).
void writeTableExr(const std::string& path, const TableImage& img, bool half);

// The most bytes such a file of width x height texels and `channels` channels takes: the raw
// texels (ZIP stores a block raw when it does not shrink), 16 bytes of offset and block header a
// line at most (an uncompressed file's blocks are single lines) and 64 KiB for the header. The
// output set checks it against the free space before anything is written.
uint64_t tableExrBytesBound(uint64_t width, uint64_t height, uint64_t channels, bool half);

// The first half of writeTableExr, for sets of files that land together (formats/output_set.h):
// validates, writes `tmp` (the temporary for `path`, named in messages) and fsyncs it; no rename.
// On failure `tmp` is removed and Error is thrown as above.
void writeTableExrTemporary(const std::string& tmp, const std::string& path, const TableImage& img, bool half);
// The same for several files, on two threads where the machine has two cores: each file is encoded
// and synced on its own, so the bytes do not depend on the order. Measured on every pair's bake
// (160 files, 2 cores): 0.21 s against 0.42 s on one thread (`brdfbake bake --timings`, write).
// The first Error is rethrown after both threads finish; the caller removes the temporaries.
struct ExrTemporary {
  std::string tmp, path;
  const TableImage* image;
  bool half;
};
void writeTableExrTemporaries(const std::vector<ExrTemporary>& files);
// The same for a table written in blocks of rows, never whole in memory (3D tables): `meta` has
// the size, channels and attributes (its planes unused); fill(y0, rows, planes) puts rows
// y0 .. y0 + rows - 1 of every channel in planes[c] (rows * width values), block after block.
// Each block is validated as it comes (values, HALF range); an Error the fill throws passes
// through with its code. Same bytes as writeTableExrTemporary for the same values.
using TableRowFill = std::function<void(int y0, int rows, std::vector<std::vector<float>>& planes)>;
void writeTableExrRowsTemporary(const std::string& tmp, const std::string& path, const TableImage& meta, bool half,
                                int rowsPerBlock, const TableRowFill& fill);
// A unique temporary next to `path` (formats/commit_record.h makeTemporaryFor: created, empty);
// throws kExitCantCreat when path names no file, kExitIoErr when the file system is full.
std::string temporaryPathFor(const std::string& path);

// Reads a file written by writeTableExr (or any single-part scanline EXR with R/G/B/A
// channels; other channels are ignored), converting HALF (or UINT) to float.  The
// returned channels are the R/G/B/A channels present, in that order; a data window not
// starting at (0,0) is shifted so texel (0,0) is its corner.  Fills every string, v2f
// and float attribute of the header except the structural ones listed above.
// Throws Error(kExitNoInput, "cannot read <path>: <reason>") on a missing or
// unreadable file, or one that has none of the channels R, G, B, A.
TableImage readTableExr(const std::string& path);

// readTableExr without the pixels: size, channels and attributes (planes empty). Throws likewise.
TableImage readTableExrHeader(const std::string& path);

// One string attribute of an EXR's header, read without its pixels; nullopt when the file is
// missing, not a readable EXR, or has no such string attribute. (Incremental bakes read brdf.hash.)
std::optional<std::string> readExrStringAttribute(const std::string& path, const std::string& name);

// The attribute a scene's 2D table carries (tables written with brdf.scene set): FNV-1a 64 of its
// texels exactly as stored (each channel in order, each texel's HALF or FLOAT bits, little-endian),
// in hex. A scene bake reads the file back and compares before it calls it up to date.
inline const char* const kTexelsHashAttribute = "brdf.texels.fnv1a64";
std::string texelsHash(const std::vector<std::vector<float>>& planes, bool half);

// True when the R/G/B/A channels of the file are stored as HALF (all of them); false
// when any is FLOAT or UINT.  Throws like readTableExr.
bool tableExrIsHalf(const std::string& path);

// Human-readable description for `brdfbake info FILE`:
//   <path>
//     size: WxH
//     channels: R (FLOAT), G (FLOAT)
//     compression: NONE (ZIP, ...)
//     <name> (<type>): <value>        one line per non-standard attribute, sorted by name;
//                                     v2f as "(a, b)", floats with %.9g
//     channel R: min <v> max <v>      one line per channel (%.9g)
// Channels are listed R, G, B, A first, then any others; attributes skip only the eight
// standard ones (channels ... screenWindowWidth).
// Throws like readTableExr.
std::string describeTableExr(const std::string& path);

}  // namespace brdfbake
