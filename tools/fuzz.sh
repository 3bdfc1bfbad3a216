#!/bin/sh
# Fuzzes a scene reader with libFuzzer (Debian's clang and libclang-rt-14-dev):
#   tools/fuzz.sh manifest|gltf [SECONDS] [--grow]
#   manifest: host/scene/manifest.cpp (TOML), seeds tests/fuzz/corpus and examples/scenes
#   gltf:     host/scene/gltf_scene.cpp (JSON), seeds tests/fuzz/gltf_corpus
# SECONDS defaults to 300. The test run calls it with 10 (ctest Fuzz.ManifestBounded,
# Fuzz.GltfBounded): new inputs then go to a scratch directory, and the seeds stay as they are.
# With --grow they join the seed corpus. A crash fails the run; its input (crash-*) is printed
# and kept in the scratch directory: fix the reader, then add the input to the seeds so that
# every test run replays it (tests/scene_test.cpp, Scene.*FuzzCorpus*).
# FUZZ_RUNS=N stops after N inputs instead of after SECONDS, and FUZZ_SEED=S fixes libFuzzer's
# seed: the test run sets both, so that it tries the same inputs on every machine and a landing
# does not depend on the luck of a random seed. Exploration (a bare call) uses a fresh seed.
# FUZZ_BUILD (default build/fuzz) holds the fuzzers, rebuilt when a source is newer; BUILD_DIR
# (default build) a configured build, for generated/version.h.
# -DNDEBUG as in Debian's libtomlplusplus: toml++ 3.3 asserts an internal precondition on "[." (a
# table header starting with a dot) in debug builds, where its release build reports the syntax
# error; the input is kept in the corpus.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
target=${1:-}
seconds=${2:-300}
grow=${3:-}
out=${FUZZ_BUILD:-$root/build/fuzz}
build=${BUILD_DIR:-$root/build}
case "$target" in
  manifest) seeds="$root/tests/fuzz/corpus"; extra="$root/examples/scenes"; main="$root/tests/fuzz/manifest_fuzz.cpp" ;;
  gltf) seeds="$root/tests/fuzz/gltf_corpus"; extra=""; main="$root/tests/fuzz/gltf_fuzz.cpp" ;;
  *) echo "usage: tools/fuzz.sh manifest|gltf [SECONDS] [--grow]" >&2; exit 64 ;;
esac
command -v clang++ >/dev/null || { echo "fuzz: clang++ not found (scripts/install-deps.sh installs clang)" >&2; exit 69; }
[ -f "$build/generated/version.h" ] || { echo "fuzz: $build/generated/version.h missing: configure a build first" >&2; exit 66; }
mkdir -p "$out"
sources="$main $root/host/scene/manifest.cpp $root/host/scene/gltf_scene.cpp $root/host/common/models.cpp
         $root/host/common/material.cpp $root/host/common/input_file.cpp"
bin="$out/${target}_fuzz"
stale=no
[ -x "$bin" ] || stale=yes
for s in $sources; do [ "$s" -nt "$bin" ] && stale=yes; done
if [ "$stale" = yes ]; then
  echo "fuzz: building $bin"
  clang++ -std=c++17 -O1 -g -fsanitize=fuzzer,address,undefined -DTOML_HEADER_ONLY=1 -DNDEBUG \
    -I"$root/host" -I"$root/include" -I"$root/kernels" -I"$build/generated" $sources -o "$bin"
fi
scratch=$(mktemp -d "${TMPDIR:-/tmp}/brdfbake-fuzz-$target.XXXXXX")
if [ "$grow" = --grow ]; then first="$seeds"; else first="$scratch/new"; mkdir -p "$first"; fi
cd "$scratch"
bound="-max_total_time=$seconds"
[ -n "${FUZZ_RUNS:-}" ] && bound="-runs=$FUZZ_RUNS"
if "$bin" $bound -seed="${FUZZ_SEED:-0}" -max_len=4096 -timeout=5 -rss_limit_mb=2048 -print_final_stats=0 \
     "$first" "$seeds" $extra > "$scratch/log" 2>&1; then
  echo "fuzz $target: no crash, hang or foreign exception ($bound, seed ${FUZZ_SEED:-random}): $(tail -1 "$scratch/log")"
  rm -rf "$scratch"
else
  tail -40 "$scratch/log"
  echo "fuzz $target: FAILED; the input is in $scratch (crash-*)" >&2
  exit 1
fi
