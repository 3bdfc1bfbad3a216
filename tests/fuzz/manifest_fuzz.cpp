// libFuzzer target for the scene manifest reader (host/scene/manifest.cpp): any input must either
// parse or be rejected with brdfbake::Error, never crash, hang or throw anything else.
// Built and run by tools/fuzz.sh manifest (clang's -fsanitize=fuzzer,address,undefined), for a
// bounded time in every test run (ctest Fuzz.ManifestBounded); the corpus it grows with --grow lives
// in tests/fuzz/corpus and is replayed by every test run (Scene.FuzzCorpusParsesOrIsRejected).
#include <cstddef>
#include <cstdint>
#include <string>

#include "common/errors.h"
#include "scene/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string text(reinterpret_cast<const char*>(data), size);
  try {
    brdfbake::parseManifest(text, "fuzz.toml");
  } catch (const brdfbake::Error&) {
    // rejected with a message: fine
  }
  return 0;
}
