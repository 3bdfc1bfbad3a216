#!/usr/bin/env bash
# Installs the Debian packages brdfbake builds and tests with; docs/dependencies.md says why each
# is there. The README's set-up command and .ci/run both run this, so the list lives only here.
# Run as root, or as a user with sudo. `scripts/install-deps.sh --list` prints the packages only.
set -euo pipefail
PACKAGES=(
  # build
  cmake g++ make git
  # OpenCL: the PoCL CPU device, the ICD loader, the Khronos C and C++ headers
  pocl-opencl-icd ocl-icd-opencl-dev opencl-headers opencl-clhpp-headers clinfo
  # libraries the binary links
  libopenexr-dev libpng-dev libboost-math-dev libglm-dev libtomlplusplus-dev nlohmann-json3-dev
  # tests: GoogleTest, other readers of our files, a real GL pipeline, the shader compiler, plots
  libgtest-dev libfreeimage-dev libopenimageio-dev python3-pil
  libegl-dev libgles-dev libegl-mesa0 libgl1-mesa-dri glslang-tools gnuplot-nox
  # tests: libFuzzer (clang's -fsanitize=fuzzer) for the scene readers
  clang libclang-rt-14-dev
  # tests: the report pages opened in a real browser (headless)
  chromium
)
if [ "${1:-}" = "--list" ]; then
  printf '%s\n' "${PACKAGES[@]}"
  exit 0
fi
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${PACKAGES[@]}" >/dev/null
echo "installed ${#PACKAGES[@]} packages"
