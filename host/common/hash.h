// One change-detecting hash for the whole project: FNV-1a over 64 bits (Fowler, Noll, Vo; the
// prime 2^40 + 435). It keys the scenes' table hashes, the texels' hash of scene tables, the kernel
// program cache's entries and the tests' reference keys and goldens. Not for security.
#pragma once
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

namespace brdfbake {

// The seed every hash here starts from. FNV-1a's published 64-bit offset basis is
// 14695981039346656037; this project has always started from 1469598103934665603 (that number
// without its last digit), and keeps it so that every hash already recorded (the scenes' brdf.hash,
// the program cache's file names, the goldens) stays the same.
constexpr uint64_t kFnvSeed = 1469598103934665603ull;
constexpr uint64_t kFnvPrime = 1099511628211ull;

// One step: h takes `word` (a byte, or a whole word where a caller hashes words).
inline uint64_t fnvMix(uint64_t h, uint64_t word) { return (h ^ word) * kFnvPrime; }

inline uint64_t fnv1a(const void* data, size_t n, uint64_t h = kFnvSeed) {
  const unsigned char* p = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < n; ++i) h = fnvMix(h, p[i]);
  return h;
}
inline uint64_t fnv1a(const std::string& s, uint64_t h = kFnvSeed) { return fnv1a(s.data(), s.size(), h); }

// 16 lower-case hex digits.
inline std::string hex16(uint64_t h) {
  char b[17];
  std::snprintf(b, sizeof b, "%016llx", static_cast<unsigned long long>(h));
  return b;
}

}  // namespace brdfbake
