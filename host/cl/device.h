// OpenCL platforms and devices: listing and choosing one.
#pragma once
#include <CL/opencl.hpp>
#include <string>
#include <vector>

namespace brdfbake {

struct DeviceEntry {
  std::string platform;
  std::string name;
  std::string type;     // CPU, GPU, ACCELERATOR, ...
  std::string version;  // device OpenCL version string
  bool fp64 = false;
  cl::Device device;
  // Wall seconds the platforms took to list (clGetPlatformIDs): the ICD loader opening each
  // driver, PoCL with the libraries it links (LLVM, Clang), the first time in a process.
  double platformSeconds = 0;
};

// Every device of every platform. Throws Error(kExitUnavailable) when there is no platform,
// naming the package to install.
std::vector<DeviceEntry> listDevices();

// The first device whose name or platform name contains `substring`; with "" the first CPU device
// (PoCL), else the first device at all. Throws Error(kExitUnavailable) listing the devices.
DeviceEntry selectDevice(const std::string& substring);

// `brdfbake devices` output.
std::string describeDevices();

// --cache-dir DIR, before the first OpenCL call (PoCL reads POCL_CACHE_DIR when its platform
// starts): made absolute (PoCL passes it to its linker, which reads "-1/..." as an option), and it
// must be a writable directory or creatable under one. Throws Error(kExitCantCreat) naming it.
void usePoclCache(const std::string& dir);
// The directory PoCL caches its kernels in: $POCL_CACHE_DIR, else $XDG_CACHE_HOME/pocl, else
// ~/.cache/pocl.
std::string poclCacheDir();
// Whether `device` is PoCL's (its platform's name), whose builds write into poclCacheDir().
bool onPocl(const cl::Device& device);

}  // namespace brdfbake
