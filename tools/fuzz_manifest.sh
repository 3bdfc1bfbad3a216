#!/bin/sh
# Fuzzes the scene manifest reader with libFuzzer (Debian's clang), growing tests/fuzz/corpus.
#   tools/fuzz_manifest.sh [SECONDS]   (default 300; needs a configured build/ for version.h)
# -DNDEBUG as in Debian's libtomlplusplus: toml++ 3.3 asserts an internal precondition on "[." (a
# table header starting with a dot) in debug builds, where its release build reports the syntax
# error; the input is kept in the corpus.
# Crashes land in tests/fuzz/crashes/ (libFuzzer's crash-* files): add each to the corpus once
# fixed, so that tests/scene_test.cpp (Scene.FuzzCorpus...) replays it in every test run.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-300}
out=${FUZZ_BUILD:-$root/build/fuzz}
mkdir -p "$out" "$root/tests/fuzz/corpus" "$root/tests/fuzz/crashes"
clang++ -std=c++17 -O1 -g -fsanitize=fuzzer,address,undefined -DTOML_HEADER_ONLY=1 -DNDEBUG \
  -I"$root/host" -I"$root/kernels" -I"$root/build/generated" \
  "$root/tests/fuzz/manifest_fuzz.cpp" "$root/host/scene/manifest.cpp" "$root/host/common/models.cpp" \
  "$root/host/common/material.cpp" "$root/host/common/input_file.cpp" -o "$out/manifest_fuzz"
cd "$root/tests/fuzz/crashes"
"$out/manifest_fuzz" -max_total_time="$seconds" -max_len=4096 -timeout=5 \
  "$root/tests/fuzz/corpus" "$root/examples/scenes"
