// Formats, precisions, texel packing and the temporary file the non-EXR writers share.
#include "formats/storage.h"

#include <Imath/half.h>
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>

#include "common/errors.h"
#include "common/format.h"
#include "common/models.h"

namespace brdfbake {

namespace {
const std::vector<std::string> kFormatNames = {"exr", "ktx2", "dds", "png16", "header"};
const std::vector<std::string> kPrecisionNames = {"float32", "float16", "unorm16", "unorm8"};

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

double unormMax(Precision p) { return p == Precision::Unorm16 ? 65535.0 : 255.0; }

std::string where(uint64_t idx, int width, int height) {
  const uint64_t w = static_cast<uint64_t>(width), h = static_cast<uint64_t>(height);
  std::string s = "(x=" + std::to_string(idx % w) + ", y=" + std::to_string((idx / w) % h);
  if (idx / (w * h) > 0) s += ", z=" + std::to_string(idx / (w * h));
  return s + ")";
}
}  // namespace

const std::string& formatName(FileFormat f) { return kFormatNames[static_cast<int>(f)]; }
const std::string& precisionName(Precision p) { return kPrecisionNames[static_cast<int>(p)]; }

FileFormat parseFormat(const std::string& opt, const std::string& name) {
  for (size_t i = 0; i < kFormatNames.size(); ++i)
    if (kFormatNames[i] == name) return static_cast<FileFormat>(i);
  std::vector<std::string> all = kFormatNames;
  all.push_back("merl");
  throw Error(kExitUsage, opt + " must be one or more of " + join(kFormatNames) + " (merl: brdf3d only), got '" + name +
                              "'" + didYouMean(name, all));
}

Precision parsePrecision(const std::string& opt, const std::string& name) {
  for (size_t i = 0; i < kPrecisionNames.size(); ++i)
    if (kPrecisionNames[i] == name) return static_cast<Precision>(i);
  throw Error(kExitUsage, opt + " must be one of " + join(kPrecisionNames) + ", got '" + name + "'" +
                              didYouMean(name, kPrecisionNames));
}

std::string formatExtension(FileFormat f) {
  switch (f) {
    case FileFormat::Exr:
      return ".exr";
    case FileFormat::Ktx2:
      return ".ktx2";
    case FileFormat::Dds:
      return ".dds";
    case FileFormat::Png16:
      return ".png";
    case FileFormat::Header:
      return ".h";
  }
  return "";
}

bool formatHolds(FileFormat f, Precision p) {
  if (f == FileFormat::Exr) return p == Precision::Float32 || p == Precision::Float16;
  if (f == FileFormat::Png16) return p == Precision::Unorm16;
  return true;
}

bool isUnorm(Precision p) { return p == Precision::Unorm16 || p == Precision::Unorm8; }

int bytesPerChannel(Precision p) {
  switch (p) {
    case Precision::Float32:
      return 4;
    case Precision::Float16:
    case Precision::Unorm16:
      return 2;
    case Precision::Unorm8:
      return 1;
  }
  return 4;
}

uint32_t storedBits(float v, Precision p) {
  switch (p) {
    case Precision::Float32: {
      uint32_t b;
      std::memcpy(&b, &v, 4);
      return b;
    }
    case Precision::Float16:
      return Imath::half(v).bits();
    default: {
      // round to nearest: the code whose value c/max is closest to v
      const double m = unormMax(p);
      const double c = std::nearbyint(std::min(1.0, std::max(0.0, static_cast<double>(v))) * m);
      return static_cast<uint32_t>(c);
    }
  }
}

double storedValue(float v, Precision p) {
  switch (p) {
    case Precision::Float32:
      return v;
    case Precision::Float16:
      return static_cast<float>(Imath::half(v));
    default:
      return storedBits(v, p) / unormMax(p);
  }
}

double storageError(const std::vector<float>& values, Precision p) {
  double worst = 0;
  if (p != Precision::Float32)
    for (float x : values)
      worst = std::max(worst, std::fabs(storedValue(x, p) - x) / std::max(1.0, std::fabs(static_cast<double>(x))));
  return worst;
}

double storageErrorBound(Precision p) {
  switch (p) {
    case Precision::Float32:
      return std::ldexp(1.0, -24);
    case Precision::Float16:
      return std::ldexp(1.0, -11) + std::ldexp(1.0, -24);
    default:
      return 0.5 / unormMax(p) + std::ldexp(1.0, -24);
  }
}

void packTexels(const std::string& path, const std::vector<std::vector<float>>& planes, int outChannels, Precision p,
                size_t count, uint64_t texel0, int width, int height, std::string& out) {
  const int bytes = bytesPerChannel(p);
  const size_t start = out.size();
  out.resize(start + count * static_cast<size_t>(outChannels) * bytes);
  char* dst = &out[start];
  const char* names = "RGBA";
  for (size_t i = 0; i < count; ++i) {
    for (int c = 0; c < outChannels; ++c) {
      float v = 1.0f;  // alpha padding
      if (static_cast<size_t>(c) < planes.size()) {
        v = planes[c][i];
        std::string problem;
        ExitCode code = kExitDataErr;
        if (!std::isfinite(v))
          problem = std::isnan(v) ? "is NaN" : "is infinite";
        else if (p == Precision::Float16 && std::fabs(v) > 65504.0f)
          problem = "exceeds the float16 range (|v| <= 65504)";
        else if (isUnorm(p) && !(v >= -kUnormSlack && v <= 1.0f + kUnormSlack)) {
          problem = "is outside [0, 1], which " + precisionName(p) +
                    " cannot hold (float32 or float16 can; for 2D tables also png16's mapping)";
          code = kExitUsage;
        }
        if (!problem.empty())
          throw Error(code, "cannot write " + path + ": channel " + std::string(1, names[c]) + " texel " +
                                where(texel0 + i, width, height) + " value " + fmtG9(v) + " " + problem);
      }
      const uint32_t b = storedBits(v, p);
      for (int k = 0; k < bytes; ++k) *dst++ = static_cast<char>((b >> (8 * k)) & 0xFF);
    }
  }
}

TempFileWriter::TempFileWriter(const std::string& tmp, const std::string& path) : tmp_(tmp), path_(path) {
  do {
    fd_ = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW, 0666);
  } while (fd_ < 0 && errno == EINTR);
  if (fd_ < 0)
    throw Error(kExitCantCreat,
                "cannot create " + path + ": " + std::strerror(errno) + " (temporary file " + tmp + ")");
}

TempFileWriter::~TempFileWriter() {
  if (fd_ >= 0) ::close(fd_);
  if (!done_) ::unlink(tmp_.c_str());
}

void TempFileWriter::write(const void* data, size_t n) {
  const char* c = static_cast<const char*>(data);
  while (n > 0) {
    const ssize_t r = ::write(fd_, c, n);
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) throw Error(kExitIoErr, "cannot write " + path_ + ": " + std::strerror(r < 0 ? errno : EIO));
    c += r;
    n -= static_cast<size_t>(r);
    offset_ += static_cast<uint64_t>(r);
  }
}

void TempFileWriter::finish() {
  if (::fsync(fd_) != 0) throw Error(kExitIoErr, "cannot write " + path_ + ": fsync: " + std::strerror(errno));
  const int r = ::close(fd_);
  fd_ = -1;
  if (r != 0) throw Error(kExitIoErr, "cannot write " + path_ + ": close: " + std::strerror(errno));
  done_ = true;
}

void putU8(std::string& s, uint32_t v) { s.push_back(static_cast<char>(v & 0xFF)); }
void putU16(std::string& s, uint32_t v) {
  for (int k = 0; k < 2; ++k) s.push_back(static_cast<char>((v >> (8 * k)) & 0xFF));
}
void putU32(std::string& s, uint32_t v) {
  for (int k = 0; k < 4; ++k) s.push_back(static_cast<char>((v >> (8 * k)) & 0xFF));
}
void putU64(std::string& s, uint64_t v) {
  for (int k = 0; k < 8; ++k) s.push_back(static_cast<char>((v >> (8 * k)) & 0xFF));
}

std::vector<std::pair<std::string, std::string>> attributesAsText(const TableImage& meta) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& [k, v] : meta.strings) out.emplace_back(k, v);
  for (const auto& [k, v] : meta.v2f) out.emplace_back(k, fmtG9(v.first) + "," + fmtG9(v.second));
  for (const auto& [k, v] : meta.floats) out.emplace_back(k, fmtG9(v));
  std::sort(out.begin(), out.end());
  return out;
}

void writeSlices(TempFileWriter& out, const SliceSource& src, const std::string& path, int outChannels, Precision p) {
  const uint64_t sliceTexels = static_cast<uint64_t>(src.width) * src.height;
  std::vector<std::vector<float>> planes;
  std::string block;
  for (int z0 = 0; z0 < src.depth; z0 += src.slicesPerBlock) {
    const int zn = std::min(src.slicesPerBlock, src.depth - z0);
    planes.clear();
    src.fill(z0, zn, planes);
    block.clear();
    packTexels(path, planes, outChannels, p, sliceTexels * zn, sliceTexels * z0, src.width, src.height, block);
    out.write(block);
  }
}

}  // namespace brdfbake
