// The OpenCL sources compiled into the binary by cmake/embed_kernels.cmake.
#pragma once
#include <string>
#include <vector>

namespace brdfbake {
struct EmbeddedSource {
  const char* path;  // relative to the repository root, for build-log messages
  const char* text;
};
extern const std::vector<EmbeddedSource> kEmbeddedKernelSources;
}  // namespace brdfbake
