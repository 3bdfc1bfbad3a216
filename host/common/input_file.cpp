#include "common/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "common/errors.h"

namespace brdfbake {

std::string fileTypeName(unsigned mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  if (S_ISREG(mode)) return "a regular file";
  return "not a regular file";
}

namespace {

std::string mib(uint64_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }
std::string cannotRead(const std::string& what, const std::string& path) {
  return "cannot read " + (what.empty() ? "" : what + " ") + path + ": ";
}

// Opens without blocking (a FIFO's open waits for a writer otherwise) and checks the descriptor.
int openChecked(const std::string& path, const std::string& what, uint64_t cap, uint64_t* size) {
  int fd;
  do {
    fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
  } while (fd < 0 && errno == EINTR);
  if (fd < 0) throw Error(kExitNoInput, cannotRead(what, path) + std::strerror(errno));
  struct stat st {};
  if (::fstat(fd, &st) != 0) {
    const int err = errno;
    ::close(fd);
    throw Error(kExitNoInput, cannotRead(what, path) + std::strerror(err));
  }
  if (!S_ISREG(st.st_mode)) {
    ::close(fd);
    throw Error(kExitNoInput, cannotRead(what, path) + fileTypeName(st.st_mode) + ", not a regular file");
  }
  const uint64_t n = static_cast<uint64_t>(st.st_size);
  if (n > cap) {
    ::close(fd);
    throw Error(kExitDataErr, cannotRead(what, path) + std::to_string(n) + " bytes, over the " +
                                  (cap >= (1ull << 20) ? mib(cap) : std::to_string(cap) + "-byte") + " cap");
  }
  // reads block as usual from here (a regular file never blocks; the flag only guarded the open)
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  *size = n;
  return fd;
}

}  // namespace

uint64_t checkInputFile(const std::string& path, const std::string& what, uint64_t cap) {
  uint64_t size = 0;
  ::close(openChecked(path, what, cap, &size));
  return size;
}

std::string readInputPrefix(const std::string& path, const std::string& what, uint64_t n) {
  uint64_t size = 0;
  const int fd = openChecked(path, what, UINT64_MAX, &size);
  std::string out(static_cast<size_t>(std::min(n, size)), '\0');
  size_t done = 0;
  while (done < out.size()) {
    const ssize_t r = ::read(fd, &out[done], out.size() - done);
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) break;
    done += static_cast<size_t>(r);
  }
  ::close(fd);
  out.resize(done);
  return out;
}

std::string readInputFile(const std::string& path, const std::string& what, uint64_t cap) {
  uint64_t size = 0;
  const int fd = openChecked(path, what, cap, &size);
  std::string out;
  out.reserve(static_cast<size_t>(size));
  char buf[65536];
  // up to the cap, even if the file grows meanwhile
  while (out.size() <= cap) {
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int err = errno;
      ::close(fd);
      throw Error(kExitNoInput, cannotRead(what, path) + std::strerror(err));
    }
    if (n == 0) break;
    out.append(buf, static_cast<size_t>(n));
  }
  ::close(fd);
  if (out.size() > cap)
    throw Error(kExitDataErr, "cannot read " + what + " " + path + ": grew past the " + mib(cap) + " cap while read");
  return out;
}

}  // namespace brdfbake
