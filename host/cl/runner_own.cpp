// The launch of a family's own kernel (KernelRunner::launch): its arguments in order, its outputs
// read back. The 3D tables, the rough dielectric and the LTC fit run their kernels so; the
// integrators' launches are host/cl/runner_launch.cpp.
#include <algorithm>

#include "cl/runner.h"
#include "cl/runner_internal.h"

namespace brdfbake {

namespace runner_detail {

namespace {
// Reals as the program's `real` (double when fp64, else float), at least one value.
cl::Buffer realsBuffer(const cl::Context& ctx, const std::vector<double>* v, bool fp64) {
  static const std::vector<double> one = {0.0};
  const std::vector<double>& d = v && !v->empty() ? *v : one;
  if (fp64)  // copied by the driver at creation: the const is not written through
    return cl::Buffer(ctx, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, d.size() * sizeof(double),
                      const_cast<double*>(d.data()));
  std::vector<float> f(d.begin(), d.end());
  return cl::Buffer(ctx, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, f.size() * sizeof(float), f.data());
}
}  // namespace

void setLaunchArgs(cl::Kernel& k, const cl::Context& ctx, const std::vector<LaunchArg>& args, bool fp64,
                   std::vector<cl::Buffer>* ins, std::vector<cl::Buffer>* outs) {
  const size_t real = fp64 ? sizeof(double) : sizeof(float);
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
      case LaunchArg::Float4:
        k.setArg(at, x.f4);
        break;
      case LaunchArg::In: {
        std::vector<float> data = x.in && !x.in->empty() ? *x.in : std::vector<float>{0.0f};
        ins->emplace_back(ctx, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, data.size() * sizeof(float), data.data());
        k.setArg(at, ins->back());
        break;
      }
      case LaunchArg::InReals:
        ins->push_back(realsBuffer(ctx, x.reals, fp64));
        k.setArg(at, ins->back());
        break;
      case LaunchArg::Out:
        outs->emplace_back(ctx, CL_MEM_WRITE_ONLY, std::max<size_t>(x.out, 1) * sizeof(float));
        k.setArg(at, outs->back());
        break;
      case LaunchArg::OutReals:
        outs->emplace_back(ctx, CL_MEM_WRITE_ONLY, std::max<size_t>(x.out, 1) * real);
        k.setArg(at, outs->back());
        break;
    }
  }
}

}  // namespace runner_detail

using namespace runner_detail;

LaunchOutputs KernelRunner::launch(ProgramKey::Kind program, int ndf, int gaf, const char* kernel,
                                   const LaunchShape& shape, const std::vector<LaunchArg>& args) {
  Compiled& c = compiled({program, ndf, gaf}, kernel);
  Slot& s = *slots_[c.slot];
  cl::Kernel k(c.program, kernel);
  std::vector<cl::Buffer> ins, outs;  // alive until the launch has run
  setLaunchArgs(k, s.context, args, fp64_, &ins, &outs);
  LaunchOutputs result;
  // groups of one on a CPU device: a family's long, uneven work-items balance over the cores; the
  // texels' kernels keep the fixed local size PoCL compiled once
  if (shape.groups == LaunchShape::One && cpu_)
    s.queue.enqueueNDRangeKernel(k, cl::NullRange,
                                 shape.gy == 0 ? cl::NDRange(shape.gx) : cl::NDRange(shape.gx, shape.gy),
                                 shape.gy == 0 ? cl::NDRange(1) : cl::NDRange(1, 1));
  else
    run(c, k, shape.gx, shape.gy);
  size_t o = 0;
  for (const LaunchArg& x : args) {
    if (x.type == LaunchArg::Out) {
      result.floats.push_back(readBack(s.queue, outs[o++], x.out));
    } else if (x.type == LaunchArg::OutReals) {
      if (fp64_) {
        result.reals.push_back(readBack<double>(s.queue, outs[o++], x.out));
      } else {
        std::vector<float> f = readBack(s.queue, outs[o++], x.out);
        result.reals.emplace_back(f.begin(), f.end());
      }
    }
  }
  return result;
}

}  // namespace brdfbake
