// OpenEXR reading of BRDF lookup tables, and the reading helpers exr_describe.cpp
// shares (exr_internal.h).  See table_file.h for the contract.
#include <ImfAttribute.h>
#include <ImfChannelList.h>
#include <ImfCompression.h>
#include <ImfFloatAttribute.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfPixelType.h>
#include <ImfStringAttribute.h>
#include <ImfVecAttribute.h>
#include <sys/stat.h>

#include <cerrno>
#include <algorithm>
#include <cstdint>

#include "common/errors.h"
#include "common/input_file.h"
#include "formats/exr/exr_internal.h"
#include "formats/exr/table_file.h"

namespace brdfbake {
namespace {

using exr::errnoText;

// The file is there and regular (openExr checked it first, 66 otherwise): what fails now is its
// content, a data error as in every other format's reader.
[[noreturn]] void readError(const std::string& path, const std::string& reason) {
  throw Error(kExitDataErr, "cannot read " + path + ": OpenEXR " + reason);
}

// Runs f(); OpenEXR / standard exceptions become Error(kExitDataErr).
template <class F>
auto guardRead(const std::string& path, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    readError(path, e.what());
  }
}

uint32_t le32(const std::string& b, size_t at) {
  return uint32_t(uint8_t(b[at])) | uint32_t(uint8_t(b[at + 1])) << 8 | uint32_t(uint8_t(b[at + 2])) << 16 |
         uint32_t(uint8_t(b[at + 3])) << 24;
}

// OpenEXR allocates an attribute's declared size before it reads the value: a size of 0x7fffffff
// in a 1 KB file had it take 2 GB. So the header is walked here first (OpenEXR file layout: magic,
// version, then per part attributes "name\0type\0" int32 size, value, ended by an empty name; a
// multi-part file's list of headers ends with an empty one), and every size must fit in the bytes
// the file has left. The walk reads the first 64 KiB (brdfbake's headers are under 4 KiB), and
// the first 1 MiB only for a header that runs past them; a longer header is refused.
void checkHeaderSizes(const std::string& path, uint64_t fileBytes) {
  constexpr uint64_t kFirstRead = 64 << 10, kMaxHeader = 1 << 20;
  struct NeedMore {};
  auto fail = [&](const std::string& why) { readError(path, "header: " + why); };
  // walks b, the file's first bytes; throws NeedMore where the header runs past them and more may be read
  auto walk = [&](const std::string& b, bool last) {
    auto short_ = [&](const std::string& why) {
      if (!last && b.size() < fileBytes) throw NeedMore{};
      fail(b.size() == fileBytes ? why : "longer than 1 MiB");
    };
    if (b.size() < 8) fail("the file is shorter than its magic number and version");
    const bool multipart = (le32(b, 4) & 0x1000) != 0;
    size_t p = 8;
    auto cString = [&](const char* what) {
      const size_t end = b.find('\0', p);
      if (end == std::string::npos && b.size() - p <= 255) short_("the file ends inside it");
      if (end == std::string::npos || end - p > 255)
        fail(std::string(what) + " at byte " + std::to_string(p) + " is not ended within 255 bytes of the header");
      std::string text = b.substr(p, end - p);
      p = end + 1;
      return text;
    };
    while (true) {
      while (true) {
        if (p >= b.size()) short_("the file ends inside it");
        const std::string name = cString("an attribute name");
        if (name.empty()) break;  // the part's header ends
        cString("an attribute type");
        if (p + 4 > b.size()) short_("the file ends inside attribute '" + name + "'");
        const int32_t size = static_cast<int32_t>(le32(b, p));
        p += 4;
        if (size < 0 || static_cast<uint64_t>(size) > fileBytes - p)
          fail("attribute '" + name + "' declares " + std::to_string(size) + " bytes; the file has " +
               std::to_string(fileBytes - p) + " left");
        p += static_cast<size_t>(size);
      }
      if (!multipart) return;
      if (p >= b.size()) short_("the file ends inside the list of headers");
      if (b[p] == '\0') return;  // the empty header ends the list
    }
  };
  try {
    walk(readInputPrefix(path, "", std::min(fileBytes, kFirstRead)), fileBytes <= kFirstRead);
  } catch (const NeedMore&) {
    walk(readInputPrefix(path, "", std::min(fileBytes, kMaxHeader)), true);
  }
}

}  // namespace

namespace exr {

std::unique_ptr<Imf::InputFile> openExr(const std::string& path) {
  // a regular file (OpenEXR would block on a FIFO), its header's sizes within it
  checkHeaderSizes(path, checkInputFile(path, "", kCapTable));
  // OpenEXR refuses a header whose data window is larger than this before it allocates for it (a
  // damaged dataWindow had it allocate 3.1 GB): no table brdfbake writes is wider or taller
  Imf::Header::setMaxImageSize(1 << 16, 1 << 16);
  auto file = guardRead(path, [&] { return std::make_unique<Imf::InputFile>(path.c_str(), 0); });
  if (!file->isComplete()) readError(path, "file is incomplete (truncated?)");
  return file;
}

Window dataWindowOf(const std::string& path, const Imf::Header& h) {
  Window w;
  w.box = h.dataWindow();
  const int64_t width = int64_t{w.box.max.x} - w.box.min.x + 1;
  const int64_t height = int64_t{w.box.max.y} - w.box.min.y + 1;
  if (width < 1 || height < 1 || width > (1 << 16) || height > (1 << 16))
    readError(path, "data window " + std::to_string(width) + " x " + std::to_string(height) +
                        " is outside [1, 65536] on an axis");
  // the texels the window declares must fit in the file's bytes: whole when uncompressed, and at
  // most deflate's 1032:1 (with room) when compressed; checked before a byte is allocated for them
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) {
    uint64_t sample = 0;
    for (auto c = h.channels().begin(); c != h.channels().end(); ++c) sample += c.channel().type == Imf::HALF ? 2 : 4;
    const uint64_t raw = static_cast<uint64_t>(width) * static_cast<uint64_t>(height) * sample;
    const uint64_t most = h.compression() == Imf::NO_COMPRESSION ? static_cast<uint64_t>(st.st_size)
                                                                 : static_cast<uint64_t>(st.st_size) * 1100 + 65536;
    if (raw > most)
      readError(path, "data window " + std::to_string(width) + " x " + std::to_string(height) + " declares " +
                          std::to_string(raw) + " bytes of texels, more than the file's " + std::to_string(st.st_size) +
                          " bytes can hold (damaged header?)");
  }
  w.width = static_cast<int>(width);
  w.height = static_cast<int>(height);
  return w;
}

std::vector<std::vector<float>> readPlanes(const std::string& path, Imf::InputFile& file, const Window& win,
                                           const std::vector<std::string>& names) {
  const size_t count = static_cast<size_t>(win.width) * static_cast<size_t>(win.height);
  std::vector<std::vector<float>> planes(names.size());
  Imf::FrameBuffer fb;
  for (size_t i = 0; i < names.size(); ++i) {
    const Imf::Channel* ch = file.header().channels().findChannel(names[i]);
    if (ch->xSampling != 1 || ch->ySampling != 1) readError(path, "channel " + names[i] + " is subsampled");
    planes[i].assign(count, 0.0f);
    fb.insert(names[i], Imf::Slice::Make(Imf::FLOAT, planes[i].data(), win.box, sizeof(float),
                                         sizeof(float) * static_cast<size_t>(win.width)));
  }
  guardRead(path, [&] {
    file.setFrameBuffer(fb);
    file.readPixels(win.box.min.y, win.box.max.y);
  });
  return planes;
}

}  // namespace exr

namespace {

using exr::as;
using exr::dataWindowOf;
using exr::isStructuralAttribute;
using exr::openExr;
using exr::readPlanes;
using exr::Window;

// Names of the R/G/B/A channels present, in that order.
std::vector<std::string> tableChannels(const std::string& path, const Imf::Header& h) {
  std::vector<std::string> names;
  for (const char* c : kTableChannels)
    if (h.channels().findChannel(c)) names.emplace_back(c);
  if (names.empty()) readError(path, "none of the channels R, G, B, A is present");
  return names;
}

}  // namespace

namespace {
// Size, channels and every table attribute of an open file; planes only when `pixels`.
TableImage readTable(const std::string& path, bool pixels) {
  std::unique_ptr<Imf::InputFile> file = openExr(path);
  const Imf::Header& h = file->header();
  const Window win = dataWindowOf(path, h);

  TableImage img;
  img.width = win.width;
  img.height = win.height;
  img.channels = tableChannels(path, h);
  if (pixels) img.planes = readPlanes(path, *file, win, img.channels);

  for (Imf::Header::ConstIterator it = h.begin(); it != h.end(); ++it) {
    const std::string name = it.name();
    if (isStructuralAttribute(name)) continue;
    const Imf::Attribute& a = it.attribute();
    if (auto s = as<Imf::StringAttribute>(a)) {
      img.strings[name] = s->value();
    } else if (auto v = as<Imf::V2fAttribute>(a)) {
      img.v2f[name] = {v->value().x, v->value().y};
    } else if (auto f = as<Imf::FloatAttribute>(a)) {
      img.floats[name] = f->value();
    }
  }
  return img;
}
}  // namespace

TableImage readTableExr(const std::string& path) { return readTable(path, true); }
TableImage readTableExrHeader(const std::string& path) { return readTable(path, false); }

bool tableExrIsHalf(const std::string& path) {
  std::unique_ptr<Imf::InputFile> file = openExr(path);
  const Imf::Header& h = file->header();
  for (const std::string& c : tableChannels(path, h))
    if (h.channels().findChannel(c)->type != Imf::HALF) return false;
  return true;
}

}  // namespace brdfbake

namespace brdfbake {

std::optional<std::string> readExrStringAttribute(const std::string& path, const std::string& name) {
  try {
    std::unique_ptr<Imf::InputFile> file = openExr(path);
    const Imf::StringAttribute* a = file->header().findTypedAttribute<Imf::StringAttribute>(name);
    if (!a) return std::nullopt;
    return a->value();
  } catch (const std::exception&) {
    return std::nullopt;  // not an EXR we can read: no attribute
  }
}

}  // namespace brdfbake
