#!/bin/bash
# The NVIDIA OpenCL check of brdfbake (docs/performance.md, "On a GPU"), in two halves:
#   tools/gpu_check.sh pack   here, after a build: copies brdfbake, brdfbake-bench, build/programs and
#                             the libraries a bare GPU machine lacks into build/gpu (15 MB)
#   tools/gpu_check.sh run    there, from the repository root with build/gpu carried: devices, the
#                             default set cold and warm, the benchmark's ratios, the claims against
#                             the reference, verify and stress (about 8 minutes on an H200)
#   tools/gpu_check.sh render there: the default set warm, and `brdfbake render` and verify's page on
#                             that machine's EGL when it has one (NVIDIA's through glvnd)
# run points OCL_ICD_VENDORS at the machine's libnvidia-opencl.so.1 and HOME at an empty directory.
set -u
step() { echo; echo "=== $* ($(date +%T))"; }
# the carried binaries and libraries, NVIDIA's OpenCL through the ICD loader, an empty HOME in /tmp
nvidia_setup() {
  G=$PWD/build/gpu
  export LD_LIBRARY_PATH=$G/lib
  NV=$(ldconfig -p | awk '/libnvidia-opencl.so.1/{print $NF; exit}')
  [ -z "$NV" ] && NV=$(find / -name 'libnvidia-opencl.so.1*' -not -path '/proc/*' 2>/dev/null | head -1)
  mkdir -p /tmp/icd && echo "$NV" > /tmp/icd/nvidia.icd
  export OCL_ICD_VENDORS=/tmp/icd
  step driver; echo "$NV"; nvidia-smi -L
  cd /tmp && export HOME=/tmp/home && mkdir -p "$HOME"
}
case "${1:-}" in
  pack)
    rm -rf build/gpu && mkdir -p build/gpu/lib
    cp build/brdfbake build/brdfbake-bench build/gpu/ && cp -r build/programs build/gpu/programs
    for l in libOpenCL.so.1 libOpenEXR-3_1.so.30 libImath-3_1.so.29 libIex-3_1.so.30 libtomlplusplus.so.3 \
             libpng16.so.16 libIlmThread-3_1.so.30 libstdc++.so.6 libgcc_s.so.1; do
      cp -L "/lib/x86_64-linux-gnu/$l" build/gpu/lib/ || exit 1
    done
    du -sh build/gpu ;;
  run)
    nvidia_setup; nproc
    step devices; timeout 60 "$G/brdfbake" devices
    step "default set: first run (cold: NVIDIA compiles), then two warm runs"
    for i in 1 2 3; do /usr/bin/time -f "%e s wall" timeout 120 "$G/brdfbake" bake --timings -o "d$i"; done
    step "devices after a bake"; timeout 60 "$G/brdfbake" devices
    step "bench: default split sum, GPU vs Karis MC"; timeout 120 "$G/brdfbake-bench" --times-only
    step "bench: cold start"; timeout 200 "$G/brdfbake-bench" --cold-start --repeat 3
    step "bench: bounds against the reference (size 64, stride 8)"
    timeout 150 "$G/brdfbake-bench" --bounds --size 64 --stride 8
    step verify
    timeout 120 "$G/brdfbake" verify --ndf ggx,beckmann,blinn-phong,gaussian \
      --gaf smith,smith-correlated,smith-correlated-exact,schlick-ggx -o v | tail -20
    step stress; timeout 150 "$G/brdfbake" stress -o s | tail -25
    step done ;;
  render)
    # the short check: the default set warm, and `brdfbake render` and verify's page on the
    # machine's own EGL (NVIDIA's through glvnd when it is there) against the same OpenCL device
    nvidia_setup
    step "default set: first run, then two warm runs"
    for i in 1 2 3; do /usr/bin/time -f "%e s wall" timeout 120 "$G/brdfbake" bake --timings -o "d$i" 2>&1 | tail -9; done
    step "EGL on this machine"
    ldconfig -p | grep -E 'libEGL(_nvidia)?\.so' ; ls /usr/share/glvnd/egl_vendor.d 2>/dev/null
    EGL=$(ldconfig -p | awk '/libEGL.so.1 /{print $NF; exit}')
    [ -z "$EGL" ] && EGL=$(find / -name 'libEGL.so.1*' -not -path '/proc/*' 2>/dev/null | head -1)
    [ -z "$EGL" ] && EGL=$(find / -name 'libEGL_nvidia.so.0*' -not -path '/proc/*' 2>/dev/null | head -1)
    echo "libEGL: ${EGL:-none}"
    if [ -n "$EGL" ]; then
      export BRDFBAKE_EGL_LIBRARY=$EGL
      step "render on this machine's GL"
      /usr/bin/time -f "%e s wall" timeout 240 "$G/brdfbake" render -o r; echo "exit $?"
      step "verify's page with its render"
      timeout 120 "$G/brdfbake" verify -o v | tail -3; grep -A7 '^row ' v/verify/index.html
    fi
    step done ;;
  *) echo "usage: tools/gpu_check.sh pack|run|render" >&2; exit 64 ;;
esac
