// libFuzzer target for the scene manifest reader (host/scene/manifest.cpp): any input must either
// parse or be rejected with brdfbake::Error, never crash, hang or throw anything else.
// Built and run by tools/fuzz_manifest.sh (clang's -fsanitize=fuzzer,address,undefined); the
// corpus it grows lives in tests/fuzz/corpus and is replayed by every test run
// (tests/scene_fuzz_corpus_test.cpp).
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
