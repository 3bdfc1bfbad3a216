// Bytes, checked fields and texel decoding shared by the readers (reader_internal.h).
#include <Imath/half.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>

#include "common/errors.h"
#include "common/input_file.h"
#include "formats/readers/reader_internal.h"

namespace brdfbake {
namespace readers {

std::string fileBytes(const std::string& path, size_t limit) {
  auto missing = [&](int err) { throw Error(kExitNoInput, "cannot read " + path + ": " + std::strerror(err)); };
  int fd;
  do {
    fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);  // a FIFO's open would block
  } while (fd < 0 && errno == EINTR);
  if (fd < 0) missing(errno);
  struct stat st;
  const int err = ::fstat(fd, &st) != 0 ? errno : S_ISDIR(st.st_mode) ? EISDIR : 0;
  if (err != 0) {
    ::close(fd);
    missing(err);
  }
  if (!S_ISREG(st.st_mode)) {
    ::close(fd);
    throw Error(kExitNoInput, "cannot read " + path + ": " + fileTypeName(st.st_mode) + ", not a regular file");
  }
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  std::string out;
  char buf[65536];
  while (out.size() < limit) {
    const ssize_t n = ::read(fd, buf, std::min(sizeof buf, limit - out.size()));
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int err = errno;
      ::close(fd);
      missing(err);
    }
    if (n == 0) break;
    out.append(buf, static_cast<size_t>(n));
  }
  ::close(fd);
  return out;
}

void bad(const std::string& path, const std::string& format, const std::string& what) {
  throw Error(kExitDataErr, "cannot read " + path + ": " + format + " " + what);
}

void Fields::need(uint64_t end, const std::string& what) const {
  if (end > bytes.size())
    bad(path, format,
        "is truncated: " + what + " would end at byte " + std::to_string(end) + ", the file has " +
            std::to_string(bytes.size()) + " bytes");
}

uint32_t Fields::u32(uint64_t at, const char* what) const {
  need(at + 4, what);
  uint32_t v = 0;
  for (int k = 0; k < 4; ++k) v |= static_cast<uint32_t>(static_cast<unsigned char>(bytes[at + k])) << (8 * k);
  return v;
}

uint64_t Fields::u64(uint64_t at, const char* what) const {
  need(at + 8, what);
  uint64_t v = 0;
  for (int k = 0; k < 8; ++k) v |= static_cast<uint64_t>(static_cast<unsigned char>(bytes[at + k])) << (8 * k);
  return v;
}

double decodeStored(uint32_t bits, Precision p) {
  switch (p) {
    case Precision::Float32: {
      float f;
      std::memcpy(&f, &bits, 4);
      return f;
    }
    case Precision::Float16:
      return static_cast<float>(Imath::half(Imath::half::FromBits, static_cast<uint16_t>(bits)));
    case Precision::Unorm16:
      return bits / 65535.0;
    case Precision::Unorm8:
      return bits / 255.0;
  }
  return 0;
}

void decodeTexels(const std::string& bytes, uint64_t at, uint64_t count, int components, Precision p, TableFile& t) {
  const int size = bytesPerChannel(p);
  t.table.planes.assign(static_cast<size_t>(components), std::vector<float>(count));
  const unsigned char* src = reinterpret_cast<const unsigned char*>(bytes.data()) + at;
  for (uint64_t i = 0; i < count; ++i)
    for (int c = 0; c < components; ++c) {
      uint32_t bits = 0;
      for (int k = 0; k < size; ++k) bits |= static_cast<uint32_t>(*src++) << (8 * k);
      t.table.planes[c][i] = static_cast<float>(decodeStored(bits, p));
    }
}

void setChannels(TableFile& t, int n) { t.table.channels.assign(kTableChannels, kTableChannels + n); }

std::string componentsName(int n, Precision p, bool vulkan) {
  std::string s;
  for (int c = 0; c < n; ++c) s += std::string(1, "RGBA"[c]) + std::to_string(8 * bytesPerChannel(p));
  return s + (isUnorm(p) ? "_UNORM" : vulkan ? "_SFLOAT" : "_FLOAT");
}

}  // namespace readers
}  // namespace brdfbake
