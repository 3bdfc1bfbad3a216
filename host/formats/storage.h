// What every table file format shares: the formats and per-channel precisions the baker writes,
// the conversion of float texels to the stored bytes (and back, for the error), the storage
// rounding each precision adds, and a temporary file written in one pass and synced.
//
// The writers (ktx2_writer, dds_writer, png_writer, header_writer) take their texels from a
// SliceSource: depth slices of width x height texels, z-major, delivered a block of slices at a
// time, so a 3D table streams into the file without being held whole in memory.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "formats/table_image.h"

namespace brdfbake {

enum class FileFormat { Exr, Ktx2, Dds, Png16, Header };
enum class Precision { Float32, Float16, Unorm16, Unorm8 };

// "exr", "ktx2", "dds", "png16", "header"; "float32", "float16", "unorm16", "unorm8".
const std::string& formatName(FileFormat f);
const std::string& precisionName(Precision p);
// Throws Error(kExitUsage) naming `opt` and the accepted names.
FileFormat parseFormat(const std::string& opt, const std::string& name);
Precision parsePrecision(const std::string& opt, const std::string& name);
// File name extensions: ".exr", ".ktx2", ".dds", ".png", ".h" (the header format also writes ".mjs").
std::string formatExtension(FileFormat f);
// Whether `f` can store `p` (exr: float32, float16; png16: unorm16 only, through its mapping;
// ktx2, dds, header: all four).
bool formatHolds(FileFormat f, Precision p);
bool isUnorm(Precision p);
// How far past [0, 1] a unorm value may lie and be clamped: a few float ulps at 1 (2^-20), the
// rounding of quantities that are exactly 1 (A + B at mu = 1, r = 0 on a node grid, 1.00000012).
// The clamp is storage rounding: storageError counts it.
inline constexpr float kUnormSlack = 1.0f / 1048576.0f;
int bytesPerChannel(Precision p);  // 4, 2, 2, 1

// The value a texel `v` reads back as after storing it with precision `p` (round to nearest;
// unorm clamps to [0, 1]; float16 through Imath::half).
double storedValue(float v, Precision p);
// The largest storage rounding of the values, relative to max(1, |v|): what brdf.error adds for
// storage (0 for float32, which holds the computed floats exactly; the rounding of a computation
// to float is in the computation's own claim, tables/error_model.h).
double storageError(const std::vector<float>& values, Precision p);
// The a priori bound of the same, for values streamed before they are known (3D tables):
// 2^-24, 2^-11 (float16's half ulp relative), 1/(2*65535) and 1/(2*255) plus 2^-24 for unorm.
double storageErrorBound(Precision p);

// Texels a block at a time: fill(z0, zn, planes) puts slices z0 .. z0 + zn - 1 of every channel
// in planes[c] (zn * width * height values, [(z - z0) * height + y] * width + x), one plane per
// channel.
struct SliceSource {
  int width = 0, height = 0, depth = 1;
  int channels = 0;        // channels of the table (1..4); the file may pad (alpha = 1)
  int slicesPerBlock = 1;  // how many slices fill delivers at once
  std::function<void(int z0, int zn, std::vector<std::vector<float>>& planes)> fill;
};

// Appends `count` texels of `planes` (starting at texel `first`) as little-endian values of
// precision p with `outChannels` channels per texel, interleaved; channels past planes.size() are
// 1 (alpha). Throws Error naming `path`, the channel and texel (index counted from texel0) when a
// value is NaN or infinite (kExitDataErr), exceeds float16's range (kExitDataErr) or leaves
// [0, 1] for a unorm precision (kExitUsage: the table needs another format or precision).
void packTexels(const std::string& path, const std::vector<std::vector<float>>& planes, int outChannels, Precision p,
                size_t count, uint64_t texel0, int width, int height, std::string& out);
// Bits of the stored value: float32/float16 bit patterns, unorm codes.
uint32_t storedBits(float v, Precision p);

// A temporary file written front to back: created (O_EXCL-free, like the EXR writer), appended
// to, synced and closed by finish(); removed on destruction unless finish() succeeded. Errors:
// kExitCantCreat (cannot create) and kExitIoErr (write, fsync, close), naming `path`.
class TempFileWriter {
 public:
  TempFileWriter(const std::string& tmp, const std::string& path);
  ~TempFileWriter();
  TempFileWriter(const TempFileWriter&) = delete;
  TempFileWriter& operator=(const TempFileWriter&) = delete;
  void write(const void* data, size_t n);
  void write(const std::string& s) { write(s.data(), s.size()); }
  uint64_t offset() const { return offset_; }
  void finish();

 private:
  std::string tmp_, path_;
  int fd_ = -1;
  uint64_t offset_ = 0;
  bool done_ = false;
};

// The texels of `src`, slab after slab (its slicesPerBlock slices at a time), packed as packTexels
// does and appended to `out`: the level data of the formats that store slices one after another
// (KTX2, DDS). Throws like packTexels and the writer.
void writeSlices(TempFileWriter& out, const SliceSource& src, const std::string& path, int outChannels, Precision p);

// Little-endian appends, for the binary headers.
void putU8(std::string& s, uint32_t v);
void putU16(std::string& s, uint32_t v);
void putU32(std::string& s, uint32_t v);
void putU64(std::string& s, uint64_t v);

// An attribute of the table as text (strings as they are, v2f "a,b", floats %.9g), every
// attribute sorted by name: the metadata of the formats that store text (KTX2, PNG, header).
std::vector<std::pair<std::string, std::string>> attributesAsText(const TableImage& meta);

}  // namespace brdfbake
