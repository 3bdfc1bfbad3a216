// Shared by the EXR writer, reader and describer (exr_*.cpp); not part of the public
// interface, which is table_file.h.
#pragma once
#include <ImfAttribute.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <Imath/ImathBox.h>

#include <cstring>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace brdfbake {
namespace exr {

// The eight attributes every EXR header has; `info` does not list them.
inline bool isStandardAttribute(const std::string& name) {
  static const std::set<std::string> kStandard = {"channels",           "compression",      "dataWindow",
                                                  "displayWindow",      "lineOrder",        "pixelAspectRatio",
                                                  "screenWindowCenter", "screenWindowWidth"};
  return kStandard.count(name) != 0;
}
// Attributes that describe the file's structure rather than the table; they are
// never written from, nor read into, TableImage's attribute maps.
inline bool isStructuralAttribute(const std::string& name) {
  static const std::set<std::string> kStructural = {"tiles",   "type",       "name",
                                                    "version", "chunkCount", "maxSamplesPerPixel"};
  return isStandardAttribute(name) || kStructural.count(name) != 0;
}

inline std::string errnoText(int err) { return std::strerror(err); }

// The attribute as type A, or null when it is of another type.
template <class A>
const A* as(const Imf::Attribute& a) {
  return dynamic_cast<const A*>(&a);
}

// Reading helpers, defined in exr_reader.cpp.  Every failure throws
// Error(kExitNoInput, "cannot read <path>: <reason>").

// The file's data window and its size.
struct Window {
  Imath::Box2i box;
  int width = 0, height = 0;
};

// Opens `path` for reading; rejects a missing file, a directory and an incomplete file.
std::unique_ptr<Imf::InputFile> openExr(const std::string& path);
// The data window of `h`, checked to be non-empty and to fit int sizes.
Window dataWindowOf(const std::string& path, const Imf::Header& h);
// Reads the named (unsubsampled) channels as float planes.
std::vector<std::vector<float>> readPlanes(const std::string& path, Imf::InputFile& file, const Window& win,
                                           const std::vector<std::string>& names);

}  // namespace exr
}  // namespace brdfbake
