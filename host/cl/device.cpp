#include "cl/device.h"

#include <limits.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>

#include "cl/program_cache.h"
#include "common/errors.h"

namespace brdfbake {

namespace {
std::string typeName(cl_device_type t) {
  if (t & CL_DEVICE_TYPE_CPU) return "CPU";
  if (t & CL_DEVICE_TYPE_GPU) return "GPU";
  if (t & CL_DEVICE_TYPE_ACCELERATOR) return "ACCELERATOR";
  return "OTHER";
}

// Why a directory cannot serve as PoCL's cache, or "" when it can: it, or the nearest existing
// ancestor it would be created under, is a writable directory.
std::string cacheProblem(const std::string& dir) {
  // root passes access() checks there, but nothing can be created in them
  for (const char* fs : {"/proc", "/sys"})
    if (dir == fs || dir.rfind(std::string(fs) + "/", 0) == 0)
      return "'" + dir + "' is in " + fs + ", a kernel file system";
  std::string cur = dir;
  while (true) {
    struct stat st {};
    if (::stat(cur.c_str(), &st) == 0) {
      if (!S_ISDIR(st.st_mode)) return "'" + cur + "' is not a directory";
      if (::access(cur.c_str(), W_OK | X_OK) != 0) return "cannot write in '" + cur + "': " + std::strerror(errno);
      return "";
    }
    const size_t slash = cur.find_last_of('/');
    if (slash == std::string::npos || slash == 0) return "";
    cur = cur.substr(0, slash);
  }
}

const char* kInstallHint =
    "no OpenCL platform found: install an OpenCL driver, e.g. PoCL for the CPU "
    "(Debian/Ubuntu: apt-get install pocl-opencl-icd)";
}  // namespace

std::vector<DeviceEntry> listDevices() {
  std::vector<cl::Platform> platforms;
  const auto t0 = std::chrono::steady_clock::now();
  try {
    cl::Platform::get(&platforms);
  } catch (const cl::Error&) {
    platforms.clear();  // the ICD loader reports "no platform" as CL_PLATFORM_NOT_FOUND_KHR (-1001)
  }
  const double platformSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (platforms.empty()) {
    // the ICD loader reads its drivers from OCL_ICD_VENDORS when that is set: name it, since the
    // drivers may well be installed and the variable be what hides them
    const char* vendors = std::getenv("OCL_ICD_VENDORS");
    if (vendors && *vendors)
      throw Error(kExitUnavailable, std::string("no OpenCL platform found: OCL_ICD_VENDORS=") + vendors +
                                        " names no loadable driver (the ICD loader looks only there while it is set; "
                                        "unset it, or point it at a driver's .icd file or library); where no driver is "
                                        "installed: apt-get install pocl-opencl-icd (PoCL, for the CPU)");
    throw Error(kExitUnavailable, kInstallHint);
  }
  std::vector<DeviceEntry> out;
  for (auto& p : platforms) {
    std::vector<cl::Device> devs;
    try {
      p.getDevices(CL_DEVICE_TYPE_ALL, &devs);
    } catch (const cl::Error&) {
      continue;  // a platform without devices
    }
    for (auto& d : devs) {
      DeviceEntry e;
      e.platform = p.getInfo<CL_PLATFORM_NAME>();
      e.name = d.getInfo<CL_DEVICE_NAME>();
      e.type = typeName(d.getInfo<CL_DEVICE_TYPE>());
      e.version = d.getInfo<CL_DEVICE_VERSION>();
      e.fp64 = d.getInfo<CL_DEVICE_EXTENSIONS>().find("cl_khr_fp64") != std::string::npos;
      e.device = d;
      e.platformSeconds = platformSeconds;
      out.push_back(e);
    }
  }
  if (out.empty()) {
    // PoCL lists no device when it cannot write its kernel cache: say that, not "install a driver"
    const std::string cache = poclCacheDir(), why = cacheProblem(cache);
    if (!why.empty())
      throw Error(kExitCantCreat, "PoCL's kernel cache " + cache + " cannot be written (" + why +
                                      "), so PoCL lists no device; give --cache-dir DIR or set POCL_CACHE_DIR to a "
                                      "writable directory");
    throw Error(kExitUnavailable, std::string(kInstallHint) + " (platforms exist but list no device)");
  }
  return out;
}

DeviceEntry selectDevice(const std::string& substring) {
  std::vector<DeviceEntry> all = listDevices();
  if (substring.empty()) {
    for (auto& e : all)
      if (e.type == "CPU") return e;
    return all.front();
  }
  for (auto& e : all)
    if (e.name.find(substring) != std::string::npos || e.platform.find(substring) != std::string::npos) return e;
  std::string names;
  for (auto& e : all) names += "\n  " + e.platform + ": " + e.name;
  throw Error(kExitUnavailable,
              "--device: no OpenCL device or platform name contains '" + substring + "'; available:" + names);
}

std::string describeDevices() {
  std::string s;
  int i = 0;
  for (auto& e : listDevices()) {
    s += "[" + std::to_string(i++) + "] " + e.type + "  " + e.name + "\n      platform: " + e.platform +
         "\n      version: " + e.version +
         (e.fp64 ? "  (fp64: double accumulators)" : "  (no fp64: float accumulators)") + "\n";
    // the program binaries ready for this device (cl/program_cache.h), where they are
    bool any = false;
    for (const std::string& dir : programCacheDirs()) {
      PreparedPrograms found = preparedPrograms(dir, e.device);
      const std::string stale =
          found.stale ? ", " + std::to_string(found.stale) + " stale (other sources or options: never loaded)" : "";
      if (found.ready.empty()) {
        if (found.stale) s += "      programs in " + dir + ": none ready" + stale + "\n";
        continue;
      }
      any = true;
      std::string list;
      for (const std::string& n : found.ready) list += (list.empty() ? "" : "; ") + n;
      s += "      programs ready in " + dir + ": " + std::to_string(found.ready.size()) + " (" + list + ")" + stale +
           "\n";
    }
    if (!any)
      s += "      programs ready: none (each bake builds its programs from source, then keeps their binaries)\n";
  }
  return s;
}

bool onPocl(const cl::Device& device) {
  try {
    const cl::Platform platform(device.getInfo<CL_DEVICE_PLATFORM>());
    return platform.getInfo<CL_PLATFORM_NAME>().find("Portable Computing Language") != std::string::npos;
  } catch (const cl::Error&) {
    return false;
  }
}

std::string poclCacheDir() {
  if (const char* d = std::getenv("POCL_CACHE_DIR"); d && *d) return d;
  if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) return std::string(x) + "/pocl";
  const char* home = std::getenv("HOME");
  return std::string(home && *home ? home : ".") + "/.cache/pocl";
}

void usePoclCache(const std::string& dir) {
  if (dir.empty()) throw Error(kExitUsage, "--cache-dir: empty directory name");
  std::string abs = dir;
  if (abs[0] != '/') {
    char cwd[PATH_MAX];
    if (!::getcwd(cwd, sizeof cwd)) throw Error(kExitCantCreat, "--cache-dir " + dir + ": " + std::strerror(errno));
    abs = std::string(cwd) + "/" + dir;
  }
  const std::string why = cacheProblem(abs);
  if (!why.empty()) throw Error(kExitCantCreat, "--cache-dir " + dir + ": " + why);
  ::setenv("POCL_CACHE_DIR", abs.c_str(), 1);
}

}  // namespace brdfbake
