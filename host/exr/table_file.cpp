// OpenEXR I/O for BRDF lookup tables.  See table_file.h for the contract.
#include "exr/table_file.h"

#include <Iex.h>
#include <ImfAttribute.h>
#include <ImfBoxAttribute.h>
#include <ImfChannelList.h>
#include <ImfCompression.h>
#include <ImfDoubleAttribute.h>
#include <ImfFloatAttribute.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfIntAttribute.h>
#include <ImfLineOrder.h>
#include <ImfOutputFile.h>
#include <ImfPixelType.h>
#include <ImfStringAttribute.h>
#include <ImfStringVectorAttribute.h>
#include <ImfVecAttribute.h>
#include <Imath/half.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <set>
#include <sstream>

#include "common/errors.h"

namespace brdfbake {
namespace {

constexpr const char* kChannelOrder[] = {"R", "G", "B", "A"};
constexpr float kHalfMax = 65504.0f;
// Fixed so the output does not depend on Imf::setDefaultZipCompressionLevel().
constexpr int kZipLevel = 6;

// Attributes that describe the file's structure rather than the table; they are
// never written from, nor read into, TableImage's attribute maps.
bool isStandardAttribute(const std::string& name) {
  static const std::set<std::string> kStandard = {
      "channels",         "compression",        "dataWindow",        "displayWindow",
      "lineOrder",        "pixelAspectRatio",   "screenWindowCenter", "screenWindowWidth"};
  return kStandard.count(name) != 0;
}
bool isStructuralAttribute(const std::string& name) {
  static const std::set<std::string> kStructural = {"tiles",   "type",       "name",
                                                    "version", "chunkCount", "maxSamplesPerPixel"};
  return isStandardAttribute(name) || kStructural.count(name) != 0;
}

int channelRank(const std::string& name) {
  for (int i = 0; i < 4; ++i)
    if (name == kChannelOrder[i]) return i;
  return -1;
}

std::string fmtG(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

std::string errnoText(int err) { return std::strerror(err); }

// ---------------------------------------------------------------------------
// Writing
// ---------------------------------------------------------------------------

[[noreturn]] void dataError(const std::string& path, const std::string& what) {
  throw Error(kExitDataErr, "cannot write " + path + ": " + what);
}

void validate(const std::string& path, const TableImage& img, bool half) {
  if (img.width < 1 || img.height < 1)
    dataError(path, "invalid table size " + std::to_string(img.width) + "x" +
                        std::to_string(img.height));
  if (img.channels.empty()) dataError(path, "no channels");
  if (img.planes.size() != img.channels.size())
    dataError(path, std::to_string(img.channels.size()) + " channels but " +
                        std::to_string(img.planes.size()) + " planes");
  int lastRank = -1;
  for (const std::string& c : img.channels) {
    const int rank = channelRank(c);
    if (rank < 0) dataError(path, "channel \"" + c + "\" is not one of R, G, B, A");
    if (rank <= lastRank)
      dataError(path, "channel " + c + " is duplicated or out of R, G, B, A order");
    lastRank = rank;
  }

  const size_t w = static_cast<size_t>(img.width);
  const size_t count = w * static_cast<size_t>(img.height);
  for (size_t ci = 0; ci < img.channels.size(); ++ci) {
    const std::string& c = img.channels[ci];
    const std::vector<float>& plane = img.planes[ci];
    if (plane.size() != count)
      dataError(path, "channel " + c + " has " + std::to_string(plane.size()) +
                          " values, expected " + std::to_string(img.width) + "*" +
                          std::to_string(img.height) + " = " + std::to_string(count));
    for (size_t i = 0; i < count; ++i) {
      const float v = plane[i];
      const char* problem = nullptr;
      if (std::isnan(v))
        problem = "is NaN";
      else if (std::isinf(v))
        problem = "is infinite";
      else if (half && std::fabs(v) > kHalfMax)
        problem = "exceeds the HALF range (|v| <= 65504)";
      if (problem)
        dataError(path, "channel " + c + " texel (x=" + std::to_string(i % w) +
                            ", y=" + std::to_string(i / w) + ") value " + fmtG(v) + " " +
                            problem);
    }
  }

  std::set<std::string> seen;
  auto checkName = [&](const std::string& name) {
    if (name.empty()) dataError(path, "empty attribute name");
    if (isStructuralAttribute(name))
      dataError(path, "attribute name \"" + name + "\" is reserved by OpenEXR");
    if (!seen.insert(name).second)
      dataError(path, "attribute \"" + name + "\" is given with two different types");
  };
  for (const auto& kv : img.strings) checkName(kv.first);
  for (const auto& kv : img.v2f) checkName(kv.first);
  for (const auto& kv : img.floats) checkName(kv.first);
}

// An Imf::OStream over a POSIX file descriptor.  Remembers the first write error so it
// can be detected even when OpenEXR swallows the exception (its OutputFile destructor
// writes the line offset table and ignores failures).
class FdOStream final : public Imf::OStream {
 public:
  FdOStream(int fd, const std::string& name) : Imf::OStream(name.c_str()), fd_(fd) {}

  void write(const char c[], int n) override {
    if (err_ != 0) throw Iex::IoExc("earlier write failed: " + errnoText(err_));
    size_t left = n > 0 ? static_cast<size_t>(n) : 0;
    while (left > 0) {
      const ssize_t r = ::pwrite(fd_, c, left, static_cast<off_t>(pos_));
      if (r < 0) {
        if (errno == EINTR) continue;
        err_ = errno;
        throw Iex::IoExc(errnoText(err_));
      }
      if (r == 0) {
        err_ = EIO;
        throw Iex::IoExc(errnoText(err_));
      }
      c += r;
      left -= static_cast<size_t>(r);
      pos_ += static_cast<uint64_t>(r);
    }
  }
  uint64_t tellp() override { return pos_; }
  void seekp(uint64_t pos) override { pos_ = pos; }
  int error() const { return err_; }

 private:
  int fd_;
  uint64_t pos_ = 0;
  int err_ = 0;
};

// Closes the descriptor and removes the temp file unless released.
class TempFileGuard {
 public:
  TempFileGuard(std::string path, int fd) : path_(std::move(path)), fd_(fd) {}
  ~TempFileGuard() {
    if (fd_ >= 0) ::close(fd_);
    if (!released_) ::unlink(path_.c_str());
  }
  TempFileGuard(const TempFileGuard&) = delete;
  TempFileGuard& operator=(const TempFileGuard&) = delete;
  int fd() const { return fd_; }
  // Closes the descriptor; returns 0 or an errno value.
  int close() {
    const int r = ::close(fd_);
    fd_ = -1;
    return r == 0 ? 0 : errno;
  }
  void release() { released_ = true; }

 private:
  std::string path_;
  int fd_;
  bool released_ = false;
};

}  // namespace

std::string temporaryPathFor(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  const std::string dir = slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
  const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  if (name.empty() || name == "." || name == "..")
    throw Error(kExitCantCreat, "cannot create " + path + ": not a file name");
  return dir + "." + name + ".tmp-" + std::to_string(::getpid());
}

void writeTableExr(const std::string& path, const TableImage& img, bool half) {
  const std::string tmp = temporaryPathFor(path);
  writeTableExrTemporary(tmp, path, img, half);
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    throw Error(kExitCantCreat, "cannot create " + path + ": " + errnoText(err));
  }
}

void writeTableExrTemporary(const std::string& tmp, const std::string& path, const TableImage& img, bool half) {
  validate(path, img, half);

  // Everything that can fail for reasons other than the file system is prepared first.
  Imf::Header header(img.width, img.height);
  std::vector<std::vector<Imath::half>> halfPlanes;
  Imf::FrameBuffer fb;
  try {
    header.compression() = Imf::ZIP_COMPRESSION;
    header.zipCompressionLevel() = kZipLevel;
    header.lineOrder() = Imf::INCREASING_Y;
    for (const auto& kv : img.strings) header.insert(kv.first, Imf::StringAttribute(kv.second));
    for (const auto& kv : img.v2f)
      header.insert(kv.first, Imf::V2fAttribute(Imath::V2f(kv.second.first, kv.second.second)));
    for (const auto& kv : img.floats) header.insert(kv.first, Imf::FloatAttribute(kv.second));

    const Imf::PixelType type = half ? Imf::HALF : Imf::FLOAT;
    const size_t w = static_cast<size_t>(img.width);
    if (half) halfPlanes.resize(img.channels.size());
    for (size_t ci = 0; ci < img.channels.size(); ++ci) {
      const std::string& c = img.channels[ci];
      header.channels().insert(c, Imf::Channel(type));
      if (half) {
        std::vector<Imath::half>& hp = halfPlanes[ci];
        hp.reserve(img.planes[ci].size());
        for (float v : img.planes[ci]) hp.emplace_back(v);
        fb.insert(c, Imf::Slice(Imf::HALF, reinterpret_cast<char*>(hp.data()),
                                sizeof(Imath::half), sizeof(Imath::half) * w));
      } else {
        // OpenEXR only reads through the pointer when writing.
        char* base = reinterpret_cast<char*>(const_cast<float*>(img.planes[ci].data()));
        fb.insert(c, Imf::Slice(Imf::FLOAT, base, sizeof(float), sizeof(float) * w));
      }
    }
  } catch (const std::exception& e) {
    throw Error(kExitIoErr, "cannot write " + path + ": " + e.what());
  }

  int fd;
  do {
    fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW, 0666);
  } while (fd < 0 && errno == EINTR);
  if (fd < 0) {
    const int err = errno;
    throw Error(kExitCantCreat,
                "cannot create " + path + ": " + errnoText(err) + " (temporary file " + tmp + ")");
  }
  TempFileGuard guard(tmp, fd);

  try {
    FdOStream os(fd, tmp);
    {
      Imf::OutputFile out(os, header, /*numThreads=*/0);
      out.setFrameBuffer(fb);
      out.writePixels(img.height);
    }  // the destructor writes the line offset table
    if (os.error() != 0) throw Iex::IoExc(errnoText(os.error()));
  } catch (const std::exception& e) {
    throw Error(kExitIoErr, "cannot write " + path + ": " + e.what());
  }
  if (::fsync(fd) != 0) {
    const int err = errno;
    throw Error(kExitIoErr, "cannot write " + path + ": fsync: " + errnoText(err));
  }
  if (const int err = guard.close())
    throw Error(kExitIoErr, "cannot write " + path + ": close: " + errnoText(err));
  guard.release();
}

// ---------------------------------------------------------------------------
// Reading
// ---------------------------------------------------------------------------

namespace {

[[noreturn]] void readError(const std::string& path, const std::string& reason) {
  throw Error(kExitNoInput, "cannot read " + path + ": " + reason);
}

// Runs f(); OpenEXR / standard exceptions become Error(kExitNoInput).
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

std::unique_ptr<Imf::InputFile> openExr(const std::string& path) {
  struct stat st;
  if (::stat(path.c_str(), &st) != 0) {
    const int err = errno;
    readError(path, errnoText(err));
  }
  if (S_ISDIR(st.st_mode)) readError(path, errnoText(EISDIR));
  auto file = guardRead(path, [&] { return std::make_unique<Imf::InputFile>(path.c_str(), 0); });
  if (!file->isComplete()) readError(path, "file is incomplete (truncated?)");
  return file;
}

struct Window {
  Imath::Box2i box;
  int width = 0, height = 0;
};

Window dataWindowOf(const std::string& path, const Imf::Header& h) {
  Window w;
  w.box = h.dataWindow();
  const int64_t width = int64_t{w.box.max.x} - w.box.min.x + 1;
  const int64_t height = int64_t{w.box.max.y} - w.box.min.y + 1;
  if (width < 1 || height < 1 || width > INT32_MAX || height > INT32_MAX)
    readError(path, "invalid data window");
  w.width = static_cast<int>(width);
  w.height = static_cast<int>(height);
  return w;
}

// Names of the R/G/B/A channels present, in that order.
std::vector<std::string> tableChannels(const std::string& path, const Imf::Header& h) {
  std::vector<std::string> names;
  for (const char* c : kChannelOrder)
    if (h.channels().findChannel(c)) names.emplace_back(c);
  if (names.empty()) readError(path, "none of the channels R, G, B, A is present");
  return names;
}

// Reads the named (unsubsampled) channels as float planes.
std::vector<std::vector<float>> readPlanes(const std::string& path, Imf::InputFile& file,
                                           const Window& win,
                                           const std::vector<std::string>& names) {
  const size_t count = static_cast<size_t>(win.width) * static_cast<size_t>(win.height);
  std::vector<std::vector<float>> planes(names.size());
  Imf::FrameBuffer fb;
  for (size_t i = 0; i < names.size(); ++i) {
    const Imf::Channel* ch = file.header().channels().findChannel(names[i]);
    if (ch->xSampling != 1 || ch->ySampling != 1)
      readError(path, "channel " + names[i] + " is subsampled");
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

const char* pixelTypeName(Imf::PixelType t) {
  switch (t) {
    case Imf::UINT: return "UINT";
    case Imf::HALF: return "HALF";
    case Imf::FLOAT: return "FLOAT";
    default: return "UNKNOWN";
  }
}

const char* compressionName(Imf::Compression c) {
  switch (c) {
    case Imf::NO_COMPRESSION: return "NONE";
    case Imf::RLE_COMPRESSION: return "RLE";
    case Imf::ZIPS_COMPRESSION: return "ZIPS";
    case Imf::ZIP_COMPRESSION: return "ZIP";
    case Imf::PIZ_COMPRESSION: return "PIZ";
    case Imf::PXR24_COMPRESSION: return "PXR24";
    case Imf::B44_COMPRESSION: return "B44";
    case Imf::B44A_COMPRESSION: return "B44A";
    case Imf::DWAA_COMPRESSION: return "DWAA";
    case Imf::DWAB_COMPRESSION: return "DWAB";
    default: return "UNKNOWN";
  }
}

// Keeps one attribute per line: control characters and backslashes are escaped.
std::string escapeText(const std::string& s) {
  std::string out;
  for (unsigned char ch : s) {
    if (ch == '\\') {
      out += "\\\\";
    } else if (ch == '\n') {
      out += "\\n";
    } else if (ch == '\t') {
      out += "\\t";
    } else if (ch < 0x20 || ch == 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", ch);
      out += buf;
    } else {
      out += static_cast<char>(ch);
    }
  }
  return out;
}

template <class A>
const A* as(const Imf::Attribute& a) {
  return dynamic_cast<const A*>(&a);
}

std::string attributeValue(const Imf::Attribute& a) {
  if (auto s = as<Imf::StringAttribute>(a)) return escapeText(s->value());
  if (auto f = as<Imf::FloatAttribute>(a)) return fmtG(f->value());
  if (auto d = as<Imf::DoubleAttribute>(a)) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", d->value());
    return buf;
  }
  if (auto i = as<Imf::IntAttribute>(a)) return std::to_string(i->value());
  if (auto v = as<Imf::V2fAttribute>(a))
    return "(" + fmtG(v->value().x) + ", " + fmtG(v->value().y) + ")";
  if (auto v = as<Imf::V2dAttribute>(a))
    return "(" + fmtG(v->value().x) + ", " + fmtG(v->value().y) + ")";
  if (auto v = as<Imf::V2iAttribute>(a))
    return "(" + std::to_string(v->value().x) + ", " + std::to_string(v->value().y) + ")";
  if (auto v = as<Imf::V3fAttribute>(a))
    return "(" + fmtG(v->value().x) + ", " + fmtG(v->value().y) + ", " + fmtG(v->value().z) + ")";
  if (auto v = as<Imf::V3iAttribute>(a))
    return "(" + std::to_string(v->value().x) + ", " + std::to_string(v->value().y) + ", " +
           std::to_string(v->value().z) + ")";
  if (auto b = as<Imf::Box2iAttribute>(a)) {
    const Imath::Box2i& v = b->value();
    return "(" + std::to_string(v.min.x) + ", " + std::to_string(v.min.y) + ") - (" +
           std::to_string(v.max.x) + ", " + std::to_string(v.max.y) + ")";
  }
  if (auto b = as<Imf::Box2fAttribute>(a)) {
    const Imath::Box2f& v = b->value();
    return "(" + fmtG(v.min.x) + ", " + fmtG(v.min.y) + ") - (" + fmtG(v.max.x) + ", " +
           fmtG(v.max.y) + ")";
  }
  if (auto sv = as<Imf::StringVectorAttribute>(a)) {
    std::string out = "[";
    for (size_t i = 0; i < sv->value().size(); ++i) {
      if (i) out += ", ";
      out += "\"" + escapeText(sv->value()[i]) + "\"";
    }
    return out + "]";
  }
  return "<value not shown>";
}

}  // namespace

TableImage readTableExr(const std::string& path) {
  std::unique_ptr<Imf::InputFile> file = openExr(path);
  const Imf::Header& h = file->header();
  const Window win = dataWindowOf(path, h);

  TableImage img;
  img.width = win.width;
  img.height = win.height;
  img.channels = tableChannels(path, h);
  img.planes = readPlanes(path, *file, win, img.channels);

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

bool tableExrIsHalf(const std::string& path) {
  std::unique_ptr<Imf::InputFile> file = openExr(path);
  const Imf::Header& h = file->header();
  for (const std::string& c : tableChannels(path, h))
    if (h.channels().findChannel(c)->type != Imf::HALF) return false;
  return true;
}

std::string describeTableExr(const std::string& path) {
  std::unique_ptr<Imf::InputFile> file = openExr(path);
  const Imf::Header& h = file->header();
  const Window win = dataWindowOf(path, h);

  std::ostringstream out;
  out << path << "\n";
  out << "  size: " << win.width << "x" << win.height << "\n";
  if (win.box.min.x != 0 || win.box.min.y != 0)
    out << "  data window origin: (" << win.box.min.x << ", " << win.box.min.y << ")\n";

  // Channels in R, G, B, A order, then any others in the file's (alphabetical) order.
  std::vector<std::pair<std::string, const Imf::Channel*>> channels;
  for (const char* c : kChannelOrder)
    if (const Imf::Channel* ch = h.channels().findChannel(c)) channels.emplace_back(c, ch);
  for (Imf::ChannelList::ConstIterator it = h.channels().begin(); it != h.channels().end(); ++it)
    if (channelRank(it.name()) < 0) channels.emplace_back(it.name(), &it.channel());

  std::vector<std::string> names;  // unsubsampled channels
  std::vector<std::string> subsampled;
  out << "  channels:";
  for (size_t i = 0; i < channels.size(); ++i) {
    const Imf::Channel& ch = *channels[i].second;
    out << (i ? ", " : " ") << channels[i].first << " (" << pixelTypeName(ch.type) << ")";
    if (ch.xSampling == 1 && ch.ySampling == 1)
      names.push_back(channels[i].first);
    else
      subsampled.push_back(channels[i].first);
  }
  if (channels.empty()) out << " none";
  out << "\n";
  out << "  compression: " << compressionName(h.compression()) << "\n";

  // Header iteration is in name order already.
  for (Imf::Header::ConstIterator it = h.begin(); it != h.end(); ++it) {
    if (isStandardAttribute(it.name())) continue;
    out << "  " << it.name() << " (" << it.attribute().typeName()
        << "): " << attributeValue(it.attribute()) << "\n";
  }

  const std::vector<std::vector<float>> planes = readPlanes(path, *file, win, names);
  for (size_t i = 0; i < names.size(); ++i) {
    float lo = 0.0f, hi = 0.0f;
    bool any = false;
    size_t nonFinite = 0;
    for (float v : planes[i]) {
      if (!std::isfinite(v)) {
        ++nonFinite;
        continue;
      }
      if (!any || v < lo) lo = v;
      if (!any || v > hi) hi = v;
      any = true;
    }
    out << "  channel " << names[i] << ":";
    if (any)
      out << " min " << fmtG(lo) << " max " << fmtG(hi);
    else
      out << " no finite values";
    if (nonFinite) out << " (" << nonFinite << " non-finite values)";
    out << "\n";
  }
  for (const std::string& c : subsampled) out << "  channel " << c << ": subsampled, not read\n";
  return out.str();
}

}  // namespace brdfbake
