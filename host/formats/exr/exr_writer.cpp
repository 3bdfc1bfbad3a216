// OpenEXR writing of BRDF lookup tables: atomic, deterministic.  See table_file.h
// for the contract.
#include <Iex.h>
#include <ImfChannelList.h>
#include <ImfCompression.h>
#include <ImfFloatAttribute.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfLineOrder.h>
#include <ImfOutputFile.h>
#include <ImfPixelType.h>
#include <ImfStringAttribute.h>
#include <ImfVecAttribute.h>
#include <Imath/half.h>
#include <cstring>
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <mutex>
#include <string>
#include <thread>

#include "common/hash.h"
#include "common/errors.h"
#include "formats/commit_record.h"
#include "formats/exr/exr_internal.h"
#include "formats/exr/table_file.h"

namespace brdfbake {
namespace {

using exr::errnoText;

// Fixed so the output does not depend on Imf::setDefaultZipCompressionLevel().
constexpr int kZipLevel = 6;

// An Imf::OStream over a POSIX file descriptor, buffered: OpenEXR writes a file in pieces of a
// few bytes (each attribute's name, type and size apart), and unbuffered the default set's four
// tables took 2,266 pwrite calls (strace -c); buffered, one per contiguous run and one for the
// line offset table that OpenEXR seeks back to write. Remembers the first write error so it can be
// detected even when OpenEXR swallows the exception (its OutputFile destructor writes the line
// offset table and ignores failures): flush() after the OutputFile is gone reports it.
class FdOStream final : public Imf::OStream {
 public:
  FdOStream(int fd, const std::string& name) : Imf::OStream(name.c_str()), fd_(fd) {}

  void write(const char c[], int n) override {
    if (err_ != 0) throw Iex::IoExc("earlier write failed: " + errnoText(err_));
    if (n <= 0) return;
    if (!buf_.empty() && pos_ != bufAt_ + buf_.size()) flush();  // a seek: the run ends here
    if (buf_.empty()) bufAt_ = pos_;
    buf_.append(c, static_cast<size_t>(n));
    pos_ += static_cast<uint64_t>(n);
    if (buf_.size() >= kFlushBytes) flush();
  }
  uint64_t tellp() override { return pos_; }
  void seekp(uint64_t pos) override { pos_ = pos; }
  // Writes what is buffered; throws Iex::IoExc on failure (and remembers it).
  void flush() {
    if (err_ != 0) throw Iex::IoExc("earlier write failed: " + errnoText(err_));
    const char* c = buf_.data();
    size_t left = buf_.size();
    uint64_t at = bufAt_;
    while (left > 0) {
      const ssize_t r = ::pwrite(fd_, c, left, static_cast<off_t>(at));
      if (r < 0 && errno == EINTR) continue;
      if (r <= 0) {
        err_ = r < 0 ? errno : EIO;
        buf_.clear();
        throw Iex::IoExc(errnoText(err_));
      }
      c += r;
      left -= static_cast<size_t>(r);
      at += static_cast<uint64_t>(r);
    }
    buf_.clear();
  }

 private:
  static constexpr size_t kFlushBytes = size_t{1} << 20;
  int fd_;
  uint64_t pos_ = 0;
  uint64_t bufAt_ = 0;  // the file offset of buf_[0]
  std::string buf_;
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

std::string temporaryPathFor(const std::string& path) { return makeTemporaryFor(path); }

uint64_t tableExrBytesBound(uint64_t width, uint64_t height, uint64_t channels, bool half) {
  return width * height * channels * (half ? 2 : 4) + height * 16 + 65536;
}

void writeTableExr(const std::string& path, const TableImage& img, bool half) {
  replaceWhole(path, [&](const std::string& tmp) { writeTableExrTemporary(tmp, path, img, half); });
}

std::string texelsHash(const std::vector<std::vector<float>>& planes, bool half) {
  uint64_t h = kFnvSeed;  // common/hash.h: the stored bits, little-endian, byte by byte
  auto eat = [&](uint32_t bits, int bytes) {
    for (int k = 0; k < bytes; ++k) h = fnvMix(h, (bits >> (8 * k)) & 0xff);
  };
  for (const auto& p : planes)
    for (float v : p) {
      if (half) {
        eat(Imath::half(v).bits(), 2);
      } else {
        uint32_t bits;
        std::memcpy(&bits, &v, 4);
        eat(bits, 4);
      }
    }
  return hex16(h);
}

void writeTableExrTemporary(const std::string& tmp, const std::string& path, const TableImage& img, bool half) {
  TableFormatRules rules;
  rules.halfRange = half;
  rules.isReservedAttribute = exr::isStructuralAttribute;
  rules.formatName = "OpenEXR";
  validateTableImage(path, img, rules);
  const size_t w = static_cast<size_t>(img.width);
  // a scene's table records its texels' hash, so that a later bake can tell a damaged file
  TableImage meta;
  const bool scene = img.strings.count("brdf.scene") > 0;
  if (scene) {
    meta = headerOf(img);
    meta.strings[kTexelsHashAttribute] = texelsHash(img.planes, half);
  }
  writeTableExrRowsTemporary(tmp, path, scene ? meta : img, half, img.height,
                             [&](int y0, int rows, std::vector<std::vector<float>>& planes) {
                               planes.resize(img.planes.size());
                               for (size_t c = 0; c < img.planes.size(); ++c)
                                 planes[c].assign(img.planes[c].begin() + static_cast<std::ptrdiff_t>(y0 * w),
                                                  img.planes[c].begin() + static_cast<std::ptrdiff_t>((y0 + rows) * w));
                             });
}

void writeTableExrRowsTemporary(const std::string& tmp, const std::string& path, const TableImage& meta, bool half,
                                int rowsPerBlock, const TableRowFill& fill) {
  TableFormatRules rules;
  rules.halfRange = half;
  rules.isReservedAttribute = exr::isStructuralAttribute;
  rules.formatName = "OpenEXR";
  validateTableHeader(path, meta, rules);
  if (rowsPerBlock < 1) rowsPerBlock = meta.height;

  // Everything that can fail for reasons other than the file system is prepared first.
  Imf::Header header(meta.width, meta.height);
  const Imf::PixelType type = half ? Imf::HALF : Imf::FLOAT;
  try {
    // FLOAT tables are stored uncompressed: ZIP took 3.9 to 4.5 ms to encode the default 128^2
    // split sum against 0.4 to 0.5 ms without, for 5.6% fewer bytes (187,819 against 198,969: the
    // mantissas' low bits do not compress; tools/fixed_costs.sh), and their bytes then depend on no
    // deflate implementation. HALF tables keep ZIP, which saves 72% of them (27,934 bytes against
    // 100,665).
    header.compression() = half ? Imf::ZIP_COMPRESSION : Imf::NO_COMPRESSION;
    header.zipCompressionLevel() = kZipLevel;
    header.lineOrder() = Imf::INCREASING_Y;
    for (const auto& kv : meta.strings) header.insert(kv.first, Imf::StringAttribute(kv.second));
    for (const auto& kv : meta.v2f)
      header.insert(kv.first, Imf::V2fAttribute(Imath::V2f(kv.second.first, kv.second.second)));
    for (const auto& kv : meta.floats) header.insert(kv.first, Imf::FloatAttribute(kv.second));
    for (const std::string& c : meta.channels) header.channels().insert(c, Imf::Channel(type));
  } catch (const std::exception& e) {
    throw Error(kExitIoErr, "cannot write " + path + ": " + e.what());
  }

  int fd;
  do {
    fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW, 0666);
  } while (fd < 0 && errno == EINTR);
  if (fd < 0) {
    const int err = errno;
    throw Error(kExitCantCreat, "cannot create " + path + ": " + errnoText(err) + " (temporary file " + tmp + ")");
  }
  TempFileGuard guard(tmp, fd);

  const size_t w = static_cast<size_t>(meta.width);
  try {
    FdOStream os(fd, tmp);
    {
      Imf::OutputFile out(os, header, /*numThreads=*/0);
      std::vector<std::vector<float>> planes;
      std::vector<std::vector<Imath::half>> halfPlanes(half ? meta.channels.size() : 0);
      for (int y0 = 0; y0 < meta.height; y0 += rowsPerBlock) {
        const int rows = std::min(rowsPerBlock, meta.height - y0);
        planes.clear();
        fill(y0, rows, planes);
        validateTableRows(path, meta, planes, y0, rows, rules);
        // OpenEXR addresses texel (x, y) at base + x xStride + y yStride: the block's base is
        // shifted back by its first row
        Imf::FrameBuffer fb;
        for (size_t ci = 0; ci < meta.channels.size(); ++ci) {
          char* base;
          size_t stride;
          if (half) {
            halfPlanes[ci].assign(planes[ci].begin(), planes[ci].end());
            base = reinterpret_cast<char*>(halfPlanes[ci].data());
            stride = sizeof(Imath::half);
          } else {
            base = reinterpret_cast<char*>(planes[ci].data());
            stride = sizeof(float);
          }
          base -= static_cast<std::ptrdiff_t>(y0) * static_cast<std::ptrdiff_t>(stride * w);
          fb.insert(meta.channels[ci], Imf::Slice(type, base, stride, stride * w));
        }
        out.setFrameBuffer(fb);
        out.writePixels(rows);
      }
    }  // the destructor writes the line offset table
    os.flush();
  } catch (const Error&) {
    throw;  // a value the format cannot hold (validateTableRows), or the fill's own error
  } catch (const std::exception& e) {
    throw Error(kExitIoErr, "cannot write " + path + ": " + e.what());
  }
  if (::fsync(fd) != 0) {
    const int err = errno;
    throw Error(kExitIoErr, "cannot write " + path + ": fsync: " + errnoText(err));
  }
  if (const int err = guard.close()) throw Error(kExitIoErr, "cannot write " + path + ": close: " + errnoText(err));
  guard.release();
}

void writeTableExrTemporaries(const std::vector<ExrTemporary>& files) {
  auto one = [&](size_t k) { writeTableExrTemporary(files[k].tmp, files[k].path, *files[k].image, files[k].half); };
  const unsigned threads = std::min(2u, std::max(1u, std::thread::hardware_concurrency()));
  if (files.size() < 2 || threads < 2) {
    for (size_t k = 0; k < files.size(); ++k) one(k);
    return;
  }
  std::atomic<size_t> next{0};
  std::exception_ptr first;
  std::mutex m;
  auto worker = [&] {
    for (size_t i; (i = next.fetch_add(1)) < files.size();) {
      try {
        one(i);
      } catch (...) {
        std::lock_guard<std::mutex> g(m);
        if (!first) first = std::current_exception();
        next = files.size();  // the other thread stops at its next file
      }
    }
  };
  std::thread helper(worker);
  worker();
  helper.join();
  if (first) std::rethrow_exception(first);
}

}  // namespace brdfbake
