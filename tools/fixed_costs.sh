#!/bin/bash
# What a warm bake pays outside its kernels, measured apart from brdfbake (docs/performance.md,
# "Figures"): five runs each of
#   pocl       dlopen of the OpenCL ICD's PoCL library, then clGetPlatformIDs and clGetDeviceIDs
#              (a small C program linked against libOpenCL only)
#   exr        OpenEXR's encoding of a table file: FLOAT channels with ZIP, without compression (the
#              writer's choice for them) and with ZIP on two threads (Imf::setGlobalThreadCount(2),
#              the same bytes); HALF channels with ZIP (the writer's choice for them) and without
#   tools/fixed_costs.sh [TABLE.exr]     (default: a 128^2 split sum baked into a scratch directory)
# Needs gcc, g++, the OpenCL and OpenEXR development packages (the build's own) and ./build/brdfbake.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
table=${1:-}
if [ -z "$table" ]; then
  "$root/build/brdfbake" bake --table splitsum -o "$work/out" --quiet >/dev/null
  table=$(ls "$work"/out/splitsum_*.exr | head -1)
fi

cat > "$work/pocl.c" <<'EOF'
#define CL_TARGET_OPENCL_VERSION 300
#include <CL/cl.h>
#include <dlfcn.h>
#include <stdio.h>
#include <time.h>
static double now(void) { struct timespec t; clock_gettime(CLOCK_MONOTONIC, &t); return t.tv_sec + t.tv_nsec * 1e-9; }
int main(void) {
  double t0 = now();
  if (!dlopen("libpocl.so.2", RTLD_NOW | RTLD_LOCAL)) { fprintf(stderr, "no libpocl.so.2\n"); return 1; }
  double t1 = now();
  cl_uint n; cl_platform_id p[4]; clGetPlatformIDs(4, p, &n);
  double t2 = now();
  cl_device_id d; clGetDeviceIDs(p[0], CL_DEVICE_TYPE_ALL, 1, &d, NULL);
  double t3 = now();
  printf("pocl: dlopen %.4f s, platforms %.4f s, devices %.4f s\n", t1 - t0, t2 - t1, t3 - t2);
  return 0;
}
EOF
gcc -O2 "$work/pocl.c" -o "$work/pocl" -lOpenCL -ldl
for r in 1 2 3 4 5; do "$work/pocl"; done

cat > "$work/exr.cpp" <<'EOF'
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStdIO.h>
#include <ImfThreading.h>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>
int main(int, char** argv) {
  Imf::InputFile in(argv[1]);
  const auto dw = in.header().dataWindow();
  const int w = dw.max.x - dw.min.x + 1, h = dw.max.y - dw.min.y + 1;
  std::vector<std::string> names;
  for (auto it = in.header().channels().begin(); it != in.header().channels().end(); ++it) names.push_back(it.name());
  std::vector<std::vector<float>> planes(names.size(), std::vector<float>(size_t(w) * h));
  Imf::FrameBuffer fb;
  for (size_t c = 0; c < names.size(); ++c)
    fb.insert(names[c], Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(planes[c].data()), 4, size_t(4) * w));
  in.setFrameBuffer(fb);
  in.readPixels(dw.min.y, dw.max.y);
  // the same texels as HALF, for the HALF encodings (an output file takes its channels' own type)
  std::vector<std::vector<Imath::half>> halves(names.size());
  Imf::FrameBuffer fbHalf;
  for (size_t c = 0; c < names.size(); ++c) {
    halves[c].assign(planes[c].begin(), planes[c].end());
    fbHalf.insert(names[c], Imf::Slice(Imf::HALF, reinterpret_cast<char*>(halves[c].data()), 2, size_t(2) * w));
  }
  struct Way { const char* name; Imf::Compression c; int threads; Imf::PixelType type; };
  for (Way way : {Way{"zip", Imf::ZIP_COMPRESSION, 0, Imf::FLOAT}, Way{"none", Imf::NO_COMPRESSION, 0, Imf::FLOAT},
                  Way{"zip, 2 threads", Imf::ZIP_COMPRESSION, 2, Imf::FLOAT},
                  Way{"half, zip", Imf::ZIP_COMPRESSION, 0, Imf::HALF},
                  Way{"half, none", Imf::NO_COMPRESSION, 0, Imf::HALF}}) {
    Imf::setGlobalThreadCount(way.threads);
    double best = 1e30;
    for (int r = 0; r < 10; ++r) {
      auto t0 = std::chrono::steady_clock::now();
      {
        Imf::Header hd(w, h);
        hd.compression() = way.c;
        hd.zipCompressionLevel() = 6;
        for (auto& n : names) hd.channels().insert(n, Imf::Channel(way.type));
        Imf::StdOFStream os(argv[2]);
        Imf::OutputFile out(os, hd, way.threads);
        out.setFrameBuffer(way.type == Imf::HALF ? fbHalf : fb);
        out.writePixels(h);
      }
      best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
    FILE* f = std::fopen(argv[2], "rb");
    std::fseek(f, 0, SEEK_END);
    std::printf("exr %-15s %.2f ms, %ld bytes (best of 10)\n", way.name, best * 1e3, std::ftell(f));
    std::fclose(f);
  }
  return 0;
}
EOF
g++ -O2 -std=c++17 "$work/exr.cpp" -o "$work/exr" $(pkg-config --cflags --libs OpenEXR)
echo "table: $table"
"$work/exr" "$table" "$work/t.exr"
