// A BRDF lookup table as it is handed to, and read back from, a file format.
//
// A table is a 2D grid of float texels with up to four channels (R, G, B, A) plus
// string / V2f / float attributes that describe how it was baked.  Nothing here knows
// about any one file format: the EXR reader and writer (exr/table_file.h), and the
// writers for other formats, share this model and the checks every table must pass.
#pragma once
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace brdfbake {

struct TableImage {
  int width = 0, height = 0;                           // x = first axis (width), y = second axis (height)
  std::vector<std::string> channels;                   // subset of "R","G","B","A", in that order
  std::vector<std::vector<float>> planes;              // planes[c][y * width + x], one per channel
  std::map<std::string, std::string> strings;          // string header attributes
  std::map<std::string, std::pair<float, float>> v2f;  // Imath::V2f header attributes
  std::map<std::string, float> floats;                 // float header attributes
};

// `img` without its texels: size, channels and attributes (a header to amend for a file).
inline TableImage headerOf(const TableImage& img) {
  TableImage h;
  h.width = img.width;
  h.height = img.height;
  h.channels = img.channels;
  h.strings = img.strings;
  h.v2f = img.v2f;
  h.floats = img.floats;
  return h;
}

// The channels a table may have, in the order they must appear.
inline constexpr const char* kTableChannels[] = {"R", "G", "B", "A"};
// Position of `name` in kTableChannels, or -1 when it is not a table channel.
int tableChannelRank(const std::string& name);

// What a file format adds to the checks every table gets.
struct TableFormatRules {
  // Values must fit an IEEE half (|v| <= 65504), for formats storing HALF channels.
  bool halfRange = false;
  // Attribute names the format keeps for its own structure, and the format's name for
  // the message that rejects one.  Null when the format reserves none.
  bool (*isReservedAttribute)(const std::string& name) = nullptr;
  const char* formatName = "";
};

// Checks `img` before it is written to `path` (named in the message only) and throws
// Error(kExitDataErr, "cannot write <path>: ...") naming the channel and texel if:
// width or height < 1, channels empty / not a subset of R,G,B,A in that order /
// planes.size() != channels.size(), a plane does not hold width*height values, a value
// is NaN or infinite, or (rules.halfRange) |value| > 65504.  Attribute names must be
// non-empty, unique across the three maps and not reserved by the format.
void validateTableImage(const std::string& path, const TableImage& img, const TableFormatRules& rules);
// The two halves of validateTableImage, for tables written in blocks of rows: the size, channels
// and attribute names of `img` (its planes unused); then the values of rows y0 .. y0 + rows - 1,
// planes[c] holding rows * width values (texels named by their row in the whole table).
void validateTableHeader(const std::string& path, const TableImage& img, const TableFormatRules& rules);
void validateTableRows(const std::string& path, const TableImage& img, const std::vector<std::vector<float>>& planes,
                       int y0, int rows, const TableFormatRules& rules);

}  // namespace brdfbake
