// The launches of the programs that evaluate the models at points (KernelRunner's 3D, rough
// dielectric and family-own methods): one slab of a 3D table, the rough dielectric's slabs and
// points, and a family's own kernel (launch). The integrators' launches are
// host/cl/runner_launch.cpp.
#include <algorithm>
#include <cmath>

#include "cl/runner.h"
#include "cl/runner_internal.h"
#include "common/brdf3d_grid.h"
#include "common/brdf_host.h"
#include "common/errors.h"

using namespace brdfbake::runner_detail;
namespace brdfbake {

std::vector<std::vector<float>> KernelRunner::brdf3dSlab(const Brdf3dSpec& spec, int z0, int zn) {
  Compiled& c = compiled({ProgramKey::Volume, spec.ndf, spec.gaf}, kBrdf3d);
  Slot& s = *slots_[c.slot];
  const int nchan = spec.channels();
  size_t plane = static_cast<size_t>(spec.nx) * spec.ny * zn;
  cl::Buffer out = outBuffer(s.context, plane * nchan);
  cl_float4 fx = {{0, 0, 0, 0}}, fy = {{0, 0, 0, 0}}, rho = {{1, 1, 1, 1}};
  for (int ch = 0; ch < nchan; ++ch) {
    auto [x, y] = spec.fresnel.kernelParams(spec.fresnel.channels() == 3 ? ch : 0);
    fx.s[ch] = static_cast<float>(x);
    fy.s[ch] = static_cast<float>(y);
    if (!spec.rho.empty()) rho.s[ch] = static_cast<float>(spec.rho[spec.rho.size() == 3 ? ch : 0]);
  }
  // the axes' cosines and sines, in the program's `real` (double where the device has fp64)
  std::vector<double> trig = axisTrig(spec);
  cl::Buffer trigBuf;
  if (fp64_) {
    trigBuf = cl::Buffer(s.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, trig.size() * sizeof(double), trig.data());
  } else {
    std::vector<float> tf(trig.begin(), trig.end());
    trigBuf = cl::Buffer(s.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, tf.size() * sizeof(float), tf.data());
  }
  cl::Kernel k(c.program, kBrdf3d);
  int a = 0;
  k.setArg(a++, out);
  k.setArg(a++, trigBuf);
  for (int v : {spec.nx, spec.ny, z0, zn, spec.param == Brdf3dParam::Angles ? 0 : 1, spec.timesCos ? 1 : 0})
    k.setArg(a++, v);
  float r = static_cast<float>(spec.roughness);
  k.setArg(a++, r);
  k.setArg(a++, static_cast<float>(brdf64::brdf_params(spec.ndf, spec.gaf, r).inv_kp));
  k.setArg(a++, spec.fresnel.model);
  k.setArg(a++, fx);
  k.setArg(a++, fy);
  k.setArg(a++, spec.diffuse);
  k.setArg(a++, static_cast<float>(spec.diffuseParam));
  k.setArg(a++, rho);
  k.setArg(a++, nchan);
  run(c, k, spec.nx, static_cast<size_t>(spec.ny) * zn);
  std::vector<float> all = readBack(s.queue, out, plane * nchan);
  std::vector<std::vector<float>> planes(nchan);
  for (int ch = 0; ch < nchan; ++ch)
    planes[ch].assign(all.begin() + static_cast<std::ptrdiff_t>(ch * plane),
                      all.begin() + static_cast<std::ptrdiff_t>((ch + 1) * plane));
  return planes;
}

}  // namespace brdfbake

namespace brdfbake {

namespace {
// Reals (etas, mus, rs) as the program's `real` (double where the device has fp64).
cl::Buffer etaBuffer(const cl::Context& ctx, const std::vector<double>& etas, bool fp64) {
  if (fp64)
    return cl::Buffer(ctx, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, etas.size() * sizeof(double),
                      const_cast<double*>(etas.data()));
  std::vector<float> f(etas.begin(), etas.end());
  return cl::Buffer(ctx, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, f.size() * sizeof(float), f.data());
}
}  // namespace

std::vector<std::vector<float>> KernelRunner::dielectricSlab(int ndf, int gaf, int nx, int ny,
                                                             const std::vector<double>& etas, bool nodeGrid,
                                                             float target) {
  Compiled& c = compiled({ProgramKey::Dielectric, ndf, gaf}, kDielectric);
  Slot& s = *slots_[c.slot];
  const int zn = static_cast<int>(etas.size());
  size_t plane = static_cast<size_t>(nx) * ny * zn;
  cl::Buffer out = outBuffer(s.context, plane * 3);
  cl::Buffer eb = etaBuffer(s.context, etas, fp64_);
  cl::Kernel k(c.program, kDielectric);
  int a = 0;
  k.setArg(a++, out);
  k.setArg(a++, eb);
  for (int v : {nx, ny, zn, nodeGrid ? 1 : 0}) k.setArg(a++, v);
  k.setArg(a++, target);
  run(c, k, nx, static_cast<size_t>(ny) * zn);
  std::vector<float> all = readBack(s.queue, out, plane * 3);
  std::vector<std::vector<float>> planes(3);
  for (int ch = 0; ch < 3; ++ch)
    planes[ch].assign(all.begin() + static_cast<std::ptrdiff_t>(ch * plane),
                      all.begin() + static_cast<std::ptrdiff_t>((ch + 1) * plane));
  return planes;
}

std::vector<std::vector<float>> KernelRunner::launch(ProgramKey::Kind program, int ndf, int gaf, const char* kernel,
                                                     size_t gx, const std::vector<LaunchArg>& args) {
  Compiled& c = compiled({program, ndf, gaf}, kernel);
  Slot& s = *slots_[c.slot];
  cl::Kernel k(c.program, kernel);
  std::vector<cl::Buffer> ins, outs;  // alive until the launch has run: setArg keeps no reference
  std::vector<size_t> sizes;
  for (size_t a = 0; a < args.size(); ++a) {
    const LaunchArg& x = args[a];
    const cl_uint at = static_cast<cl_uint>(a);
    switch (x.type) {
      case LaunchArg::Int:
        k.setArg(at, x.i);
        break;
      case LaunchArg::Float:
        k.setArg(at, x.f);
        break;
      case LaunchArg::In: {
        // a kernel may read nothing from an empty input: one float keeps the buffer valid
        std::vector<float> data = x.in->empty() ? std::vector<float>{0.0f} : *x.in;
        ins.emplace_back(s.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, data.size() * sizeof(float), data.data());
        k.setArg(at, ins.back());
        break;
      }
      case LaunchArg::Out:
        outs.push_back(outBuffer(s.context, std::max<size_t>(x.out, 1)));
        sizes.push_back(x.out);
        k.setArg(at, outs.back());
        break;
    }
  }
  // one work-item a group: a family's own kernels run long per work-item (an LTC fit: ~3 ms) and
  // unevenly (a second start at grazing views), so groups of one balance the cores; the tables'
  // kernels keep the fixed local size PoCL compiles once
  if (cpu_)
    s.queue.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(gx), cl::NDRange(1));
  else
    run(c, k, gx, 0);
  std::vector<std::vector<float>> result;
  for (size_t o = 0; o < outs.size(); ++o) result.push_back(readBack(s.queue, outs[o], sizes[o]));
  return result;
}

std::vector<std::vector<double>> KernelRunner::dielectricPoints(int ndf, int gaf, const std::vector<double>& mus,
                                                                const std::vector<double>& rs,
                                                                const std::vector<double>& etas, float target) {
  Compiled& c = compiled({ProgramKey::Dielectric, ndf, gaf}, kDielectricNodes);
  Slot& s = *slots_[c.slot];
  const size_t n = mus.size();
  std::vector<std::vector<double>> planes(4);
  if (n == 0) return planes;
  const size_t real = fp64_ ? sizeof(double) : sizeof(float);
  cl::Buffer out(s.context, CL_MEM_WRITE_ONLY, n * 4 * real);
  cl::Buffer mb = etaBuffer(s.context, mus, fp64_), rb = etaBuffer(s.context, rs, fp64_),
             eb = etaBuffer(s.context, etas, fp64_);
  cl::Kernel k(c.program, kDielectricNodes);
  int a = 0;
  k.setArg(a++, out);
  k.setArg(a++, mb);
  k.setArg(a++, rb);
  k.setArg(a++, eb);
  k.setArg(a++, static_cast<int>(n));
  k.setArg(a++, target);
  run(c, k, n, 0);
  std::vector<double> all;
  if (fp64_) {
    all = readBack<double>(s.queue, out, n * 4);
  } else {
    std::vector<float> f = readBack(s.queue, out, n * 4);
    all.assign(f.begin(), f.end());
  }
  for (size_t ch = 0; ch < 4; ++ch)
    planes[ch].assign(all.begin() + static_cast<std::ptrdiff_t>(ch * n),
                      all.begin() + static_cast<std::ptrdiff_t>((ch + 1) * n));
  return planes;
}

}  // namespace brdfbake
