// Inputs are regular files, read under a size cap. A FIFO would block the read forever, a device
// (a symlink to /dev/zero) would never end, a directory is not a file: each is refused before a
// byte is read, naming the path and what it is. The caps are per kind of input (docs/reliability.md).
#pragma once
#include <cstdint>
#include <string>

namespace brdfbake {

// Size caps, in bytes, by kind of input.
inline constexpr uint64_t kCapManifest = 4ull << 20;   // a scene manifest (TOML): 4 MiB
inline constexpr uint64_t kCapGltfJson = 64ull << 20;  // a .gltf, or a .glb's JSON chunk: 64 MiB
inline constexpr uint64_t kCapGlb = 2ull << 30;        // a .glb file (its JSON chunk alone is read): 2 GiB
inline constexpr uint64_t kCapTable = 16ull << 30;     // a table file (EXR, KTX2, DDS, PNG, .h, .mjs): 16 GiB
inline constexpr uint64_t kCapMerl = 34992012;         // a MERL .binary: 3 x 90 x 90 x 180 doubles + 12

// Throws Error(kExitNoInput) when `path` is missing, unreadable or not a regular file ("cannot read
// scene x.toml: a FIFO (named pipe), not a regular file"), Error(kExitDataErr) when it is larger
// than `cap`. `what` names the input ("scene", "table", "MERL file"). Returns the file's size.
uint64_t checkInputFile(const std::string& path, const std::string& what, uint64_t cap);

// The file's bytes, after the same checks, read from the descriptor that was checked (no window
// for the path to change between the check and the read).
std::string readInputFile(const std::string& path, const std::string& what, uint64_t cap);

// The file's first `n` bytes (fewer if it is shorter), after the same checks with no cap on the
// file's size: for a container whose header says how much of it to read (a .glb's JSON chunk).
std::string readInputPrefix(const std::string& path, const std::string& what, uint64_t n);

// What a file type is, for messages: "a directory", "a FIFO (named pipe)", "a character device", ...
std::string fileTypeName(unsigned mode);

}  // namespace brdfbake
