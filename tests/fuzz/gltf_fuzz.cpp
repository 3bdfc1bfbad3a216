// libFuzzer target for the glTF scene reader (host/scene/gltf_scene.cpp, parseGltf): any JSON text
// must either plan as a scene or be rejected with brdfbake::Error, never crash, hang or throw
// anything else. Built and run by tools/fuzz.sh gltf (clang's -fsanitize=fuzzer,address,undefined),
// for a bounded time in every test run (ctest Fuzz.GltfBounded); its seeds are tests/fuzz/gltf_corpus.
#include <cstddef>
#include <cstdint>
#include <string>

#include "common/errors.h"
#include "scene/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string text(reinterpret_cast<const char*>(data), size);
  try {
    brdfbake::parseGltf(text, "fuzz.gltf");
  } catch (const brdfbake::Error&) {
    // rejected with a message: fine
  }
  return 0;
}
