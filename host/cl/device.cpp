#include "cl/device.h"

#include "common/errors.h"

namespace brdfbake {

namespace {
std::string typeName(cl_device_type t) {
  if (t & CL_DEVICE_TYPE_CPU) return "CPU";
  if (t & CL_DEVICE_TYPE_GPU) return "GPU";
  if (t & CL_DEVICE_TYPE_ACCELERATOR) return "ACCELERATOR";
  return "OTHER";
}

const char* kInstallHint =
    "no OpenCL platform found: install an OpenCL driver, e.g. PoCL for the CPU "
    "(Debian/Ubuntu: apt-get install pocl-opencl-icd)";
}  // namespace

std::vector<DeviceEntry> listDevices() {
  std::vector<cl::Platform> platforms;
  try {
    cl::Platform::get(&platforms);
  } catch (const cl::Error&) {
    platforms.clear();  // the ICD loader reports "no platform" as CL_PLATFORM_NOT_FOUND_KHR (-1001)
  }
  if (platforms.empty()) throw Error(kExitUnavailable, kInstallHint);
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
      out.push_back(e);
    }
  }
  if (out.empty()) throw Error(kExitUnavailable, std::string(kInstallHint) + " (platforms exist but list no device)");
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
  throw Error(kExitUnavailable, "--device: no OpenCL device or platform name contains '" + substring +
                                    "'; available:" + names);
}

std::string describeDevices() {
  std::string s;
  int i = 0;
  for (auto& e : listDevices()) {
    s += "[" + std::to_string(i++) + "] " + e.type + "  " + e.name + "\n      platform: " + e.platform +
         "\n      version: " + e.version + (e.fp64 ? "  (fp64: double accumulators)" : "  (no fp64: float accumulators)") +
         "\n";
  }
  return s;
}

}  // namespace brdfbake
