// OpenCL program binaries kept between runs (cl/program_cache.h).
#include "cl/program_cache.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "cl/programs.h"
#include "common/errors.h"
#include "common/hash.h"
#include "formats/commit_record.h"
#include "formats/storage.h"

#ifndef BRDFBAKE_PROGRAMS_BUILD_DIR
#define BRDFBAKE_PROGRAMS_BUILD_DIR ""
#endif
#ifndef BRDFBAKE_PROGRAMS_INSTALL_DIR
#define BRDFBAKE_PROGRAMS_INSTALL_DIR ""
#endif

namespace brdfbake {

namespace {

const char kMagic[] = "BRDFBAKE-PROGRAM 2\n";
constexpr size_t kMagicLen = sizeof kMagic - 1;
// The largest entry read: the integrators' program binary on PoCL is about 1 MB, NVIDIA's PTX a
// few hundred KB; a file past this is not ours.
constexpr uint64_t kMaxEntry = 256ull << 20;

// The entry's file name (the identity itself is compared in full) and the binary's checksum (a
// torn or truncated write is never loaded): FNV-1a's step, (h ^ x) * prime, on 8-byte words in four
// interleaved streams, then on the tail's bytes, the streams and the length. Each step is a
// bijection of h, so a change in any one word always changes the result. On the default program's
// 1 MB (binary and identity) FNV-1a byte by byte takes 1.2 ms of each bake's program load; this,
// 0.09 ms.
uint64_t entryHash(const unsigned char* p, size_t n) {
  uint64_t h[4] = {kFnvSeed, kFnvSeed ^ 1, kFnvSeed ^ 2, kFnvSeed ^ 3};
  size_t i = 0;
  for (; i + 32 <= n; i += 32)
    for (int k = 0; k < 4; ++k) {
      uint64_t w;
      std::memcpy(&w, p + i + 8 * k, 8);  // the words as the machine reads them: a cache is per machine
      h[k] = fnvMix(h[k], w);
    }
  uint64_t r = fnv1a(p + i, n - i);
  for (uint64_t v : h) r = fnvMix(r, v);
  return fnvMix(r, n);
}
uint64_t entryHash(const std::string& s) {
  return entryHash(reinterpret_cast<const unsigned char*>(s.data()), s.size());
}

std::string hex64(uint64_t v) { return hex16(v); }

bool getU64(const std::string& in, size_t* at, uint64_t* v) {
  if (in.size() < *at + 8) return false;
  *v = 0;
  for (int i = 0; i < 8; ++i) *v |= static_cast<uint64_t>(static_cast<unsigned char>(in[*at + i])) << (8 * i);
  *at += 8;
  return true;
}

// Up to `limit` bytes of a regular file; nullopt for anything else (a FIFO is never opened for
// reading without O_NONBLOCK: it would block).
std::optional<std::string> readRegular(const std::string& path, uint64_t limit) {
  int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return std::nullopt;
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) || static_cast<uint64_t>(st.st_size) > kMaxEntry) {
    ::close(fd);
    return std::nullopt;
  }
  std::string data(static_cast<size_t>(std::min<uint64_t>(limit, static_cast<uint64_t>(st.st_size))), '\0');
  size_t got = 0;
  while (got < data.size()) {
    ssize_t n = ::read(fd, &data[got], data.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    got += static_cast<size_t>(n);
  }
  ::close(fd);
  data.resize(got);
  return data;
}

// The identity stored in an entry's bytes, or nullopt when they are not an entry; `partial`: as
// much of it as `data` holds (an entry's first bytes are enough for its device and program).
std::optional<std::string> storedIdentity(const std::string& data, size_t* at, bool partial = false) {
  if (data.compare(0, kMagicLen, kMagic) != 0) return std::nullopt;
  *at = kMagicLen;
  uint64_t n = 0;
  if (!getU64(data, at, &n)) return std::nullopt;
  if (n > data.size() - *at) {
    if (!partial) return std::nullopt;
    n = data.size() - *at;
  }
  std::string id = data.substr(*at, static_cast<size_t>(n));
  *at += static_cast<size_t>(n);
  return id;
}

// The identity's lines before the options: the platform and the device.
std::string deviceBlock(const std::string& identity) {
  size_t end = identity.find("\noptions: ");
  return end == std::string::npos ? "" : identity.substr(0, end);
}

std::string mkdirs(const std::string& dir) {
  std::string cur;
  size_t from = 0;
  while (from <= dir.size()) {
    size_t slash = dir.find('/', from);
    cur = dir.substr(0, slash == std::string::npos ? dir.size() : slash);
    from = slash == std::string::npos ? dir.size() + 1 : slash + 1;
    if (cur.empty()) continue;
    if (::mkdir(cur.c_str(), 0755) != 0 && errno != EEXIST) return cur + ": " + std::strerror(errno);
  }
  struct stat st {};
  if (::stat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode)) return dir + ": not a directory";
  return "";
}

}  // namespace

std::string programIdentity(const cl::Device& device, const std::string& name, const std::string& options,
                            const std::string& source) {
  cl::Platform platform(device.getInfo<CL_DEVICE_PLATFORM>());
  return "platform: " + platform.getInfo<CL_PLATFORM_NAME>() + " / " + platform.getInfo<CL_PLATFORM_VERSION>() +
         "\ndevice: " + device.getInfo<CL_DEVICE_NAME>() + " / " + device.getInfo<CL_DEVICE_VERSION>() + " / driver " +
         device.getInfo<CL_DRIVER_VERSION>() + "\noptions: " + options + "\nprogram: " + name +
         "\nsource: " + std::to_string(source.size()) + " bytes\n" + source;
}

bool programCacheOff() {
  const char* d = std::getenv("BRDFBAKE_PROGRAM_CACHE");
  return d && (!*d || std::string(d) == "off");
}

std::string programCacheWriteDir() {
  if (programCacheOff()) return "";
  if (const char* d = std::getenv("BRDFBAKE_PROGRAM_CACHE")) return d;
  if (const char* d = std::getenv("POCL_CACHE_DIR"); d && *d) return std::string(d) + "/brdfbake-programs";
  if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) return std::string(x) + "/brdfbake/programs";
  const char* home = std::getenv("HOME");
  return home && *home ? std::string(home) + "/.cache/brdfbake/programs" : "";
}

std::vector<std::string> programCacheDirs() {
  std::vector<std::string> dirs;
  if (programCacheOff()) return dirs;
  auto add = [&](const std::string& d) {
    if (!d.empty() && std::find(dirs.begin(), dirs.end(), d) == dirs.end()) dirs.push_back(d);
  };
  add(programCacheWriteDir());
  if (const char* p = std::getenv("BRDFBAKE_PREPARED_PROGRAMS")) {
    if (*p && std::string(p) != "off") add(p);
    return dirs;
  }
  // next to an installed executable (a relocated install), then where this build and its install put them
  // (the build's own directory only for an executable of the build tree: an installed brdfbake
  // had listed the build tree it came from)
  char exe[4096];
  ssize_t n = ::readlink("/proc/self/exe", exe, sizeof exe - 1);
  const std::string buildDir = BRDFBAKE_PROGRAMS_BUILD_DIR;
  const std::string buildRoot =
      buildDir.substr(0, buildDir.find_last_of('/') == std::string::npos ? 0 : buildDir.find_last_of('/'));
  bool inBuild = n <= 0;
  if (n > 0) {
    std::string path(exe, static_cast<size_t>(n));
    std::string dir = path.substr(0, path.find_last_of('/'));
    add(dir + "/programs");
    add(dir + "/../share/brdfbake/programs");
    // brdfbake in the build directory, or a test in a directory of its own there
    const std::string up = dir.substr(0, dir.find_last_of('/'));
    inBuild = !buildRoot.empty() && (dir == buildRoot || up == buildRoot);
  }
  if (inBuild) add(buildDir);
  add(BRDFBAKE_PROGRAMS_INSTALL_DIR);
  return dirs;
}

std::optional<ProgramBinary> loadProgram(const std::string& identity, std::string* where) {
  const std::string file = hex64(entryHash(identity)) + ".clbin";
  for (const std::string& dir : programCacheDirs()) {
    std::optional<std::string> data = readRegular(dir + "/" + file, kMaxEntry);
    if (!data) continue;
    size_t at = 0;
    std::optional<std::string> id = storedIdentity(*data, &at);
    if (!id || *id != identity) continue;  // another program, device, driver or source: never used
    uint64_t n = 0, sum = 0;
    if (!getU64(*data, &at, &n) || n > data->size() - at) continue;
    ProgramBinary bin(data->begin() + static_cast<std::ptrdiff_t>(at),
                      data->begin() + static_cast<std::ptrdiff_t>(at + n));
    at += static_cast<size_t>(n);
    if (!getU64(*data, &at, &sum) || sum != entryHash(bin.data(), bin.size()) || bin.empty()) continue;
    if (where) *where = dir + "/" + file;
    return bin;
  }
  return std::nullopt;
}

std::string storeProgram(const std::string& identity, const ProgramBinary& binary, std::string dir) {
  if (dir.empty()) dir = programCacheWriteDir();
  if (dir.empty()) return "no cache directory (BRDFBAKE_PROGRAM_CACHE=off, or no HOME)";
  if (binary.empty()) return "the driver gave an empty binary";
  if (std::string why = mkdirs(dir); !why.empty()) return why;
  std::string data(kMagic);
  putU64(data, identity.size());
  data += identity;
  putU64(data, binary.size());
  data.append(reinterpret_cast<const char*>(binary.data()), binary.size());
  putU64(data, entryHash(binary.data(), binary.size()));
  const std::string path = dir + "/" + hex64(entryHash(identity)) + ".clbin";
  // first the temporaries of stores that were interrupted (their process is gone), then ours, marked
  // with this process's PID (formats/commit_record.h)
  if (DIR* d = ::opendir(dir.c_str())) {
    std::vector<std::string> gone;
    while (dirent* e = ::readdir(d))
      if (ownerIsGone(temporaryOwner(e->d_name))) gone.push_back(e->d_name);
    ::closedir(d);
    for (const std::string& g : gone) ::unlink((dir + "/" + g).c_str());
  }
  try {
    replaceWhole(path, [&](const std::string& tmp) {
      TempFileWriter out(tmp, path);
      out.write(data);
      out.finish();
    });
  } catch (const Error& e) {
    return e.what();  // a cache that cannot be written costs the next run a build, never a failure
  }
  return "";
}

PreparedPrograms preparedPrograms(const std::string& dir, const cl::Device& device) {
  const std::string mine = deviceBlock(programIdentity(device, "", "", ""));
  PreparedPrograms out;
  DIR* d = ::opendir(dir.c_str());
  if (!d) return out;
  while (dirent* e = ::readdir(d)) {
    std::string f = e->d_name;
    if (f.size() < 6 || f.compare(f.size() - 6, 6, ".clbin") != 0) continue;
    std::optional<std::string> data = readRegular(dir + "/" + f, kMaxEntry);
    size_t at = 0;
    std::optional<std::string> id = data ? storedIdentity(*data, &at, true) : std::nullopt;
    if (!id || deviceBlock(*id) != mine) continue;  // another device's: not listed under this one
    size_t p = id->find("\nprogram: ");
    if (p == std::string::npos) continue;
    const std::string name = id->substr(p + 10, id->find('\n', p + 10) - p - 10);
    // current: the file is where this build's identity of that program hashes to, and stores
    // that identity, byte for byte (what loadProgram asks of it too, with the checksum)
    ProgramKey key;
    bool current = false;
    if (programKeyNamed(name, &key)) {
      const std::string want = programIdentity(device, name, kProgramBuildOptions, programSource(key));
      current = f == hex64(entryHash(want)) + ".clbin" && *id == want;
    }
    if (current)
      out.ready.push_back(name);
    else
      ++out.stale;
  }
  ::closedir(d);
  std::sort(out.ready.begin(), out.ready.end());
  return out;
}

}  // namespace brdfbake
