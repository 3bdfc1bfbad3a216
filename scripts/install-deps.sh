#!/usr/bin/env bash
# Installs the Debian packages brdfbake builds and runs with, and with --tests those its tests need
# too; docs/dependencies.md says why each is there. The README's set-up commands and .ci/run run
# this, so the lists live only here. Run as root, or as a user with sudo.
#   scripts/install-deps.sh            build and run: what `./build/brdfbake` needs
#   scripts/install-deps.sh --tests    that, and the test dependencies
#   scripts/install-deps.sh --list [--tests]   print the packages only
set -euo pipefail
PACKAGES=(
  # build
  cmake g++ make git
  # OpenCL: the PoCL CPU device, the ICD loader, the Khronos C and C++ headers
  pocl-opencl-icd ocl-icd-opencl-dev opencl-headers opencl-clhpp-headers clinfo
  # libraries the binary links
  libopenexr-dev libpng-dev libboost-math-dev libglm-dev libtomlplusplus-dev nlohmann-json3-dev
  # `render` and the report pages' furnace renders: EGL and GLES headers, Mesa's drivers; the plots
  libegl-dev libgles-dev libegl-mesa0 libgl1-mesa-dri gnuplot-nox
)
TEST_PACKAGES=(
  # tests: GoogleTest, other readers of our files, the shader compiler
  libgtest-dev libfreeimage-dev libopenimageio-dev python3-pil glslang-tools
  # tests: libFuzzer (clang's -fsanitize=fuzzer) for the scene readers
  clang libclang-rt-14-dev
  # tests: the report pages opened in a real browser (headless)
  chromium
  # tests: the published 2016 LTC fit (three.js's copy) the LTC tables are measured against
  libjs-three
)
tests=0 list=0
for a in "$@"; do
  case "$a" in
    --tests) tests=1 ;;
    --list) list=1 ;;
    *) echo "install-deps.sh: unknown option '$a' (--tests, --list)" >&2; exit 64 ;;
  esac
done
[ "$tests" -eq 1 ] && PACKAGES+=("${TEST_PACKAGES[@]}")
if [ "$list" -eq 1 ]; then
  printf '%s\n' "${PACKAGES[@]}"
  exit 0
fi
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${PACKAGES[@]}" >/dev/null
echo "installed ${#PACKAGES[@]} packages"
