#!/bin/bash
# The NVIDIA OpenCL check of brdfbake (docs/performance.md, "On a GPU"), in two halves:
#   tools/gpu_check.sh pack   here, after a build: copies brdfbake, brdfbake-bench, build/programs and
#                             the libraries a bare GPU machine lacks into build/gpu (15 MB)
#   tools/gpu_check.sh run    there, from the repository root with build/gpu carried: devices, the
#                             default set cold and warm, the benchmark's ratios, the claims against
#                             the reference, verify and stress (about 8 minutes on an H200)
# run points OCL_ICD_VENDORS at the machine's libnvidia-opencl.so.1 and HOME at an empty directory.
set -u
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
    G=$PWD/build/gpu
    export LD_LIBRARY_PATH=$G/lib
    NV=$(ldconfig -p | awk '/libnvidia-opencl.so.1/{print $NF; exit}')
    [ -z "$NV" ] && NV=$(find / -name 'libnvidia-opencl.so.1*' -not -path '/proc/*' 2>/dev/null | head -1)
    mkdir -p /tmp/icd && echo "$NV" > /tmp/icd/nvidia.icd
    export OCL_ICD_VENDORS=/tmp/icd
    step() { echo; echo "=== $* ($(date +%T))"; }
    step driver; echo "$NV"; nvidia-smi -L; nproc
    cd /tmp && export HOME=/tmp/home && mkdir -p "$HOME"
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
  *) echo "usage: tools/gpu_check.sh pack|run" >&2; exit 64 ;;
esac
