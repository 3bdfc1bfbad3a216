// The brdf3d family's kernel (kernels/brdf3d.cl bake_brdf3d): the BRDF at every texel of a slab of
// slices, evaluated in the program's `real` (double where the device has fp64).
#include "common/brdf3d_grid.h"
#include "common/brdf_host.h"
#include "tables/brdf3d/brdf3d.h"

namespace brdfbake {

namespace {
const char* const kKernel = "bake_brdf3d";
}

KernelNeed brdf3dKernel(int ndf, int gaf) {
  using A = LaunchArg;
  const cl_float4 zero = {{0, 0, 0, 0}};
  // (out, trig, nx, ny, z0, zn, param, timesCos, r, inv_kp, fresnel, fr_x, fr_y, diffuse,
  // diffuse_param, rho, channels): zn = 0, nothing to do
  return {
      KernelNeed::Own,
      ndf,
      gaf,
      ProgramKey::Volume,
      kKernel,
      {A::output(0), A::noInput(LaunchArg::InReals), A::of(0), A::of(0), A::of(0), A::of(0), A::of(0), A::of(0),
       A::of(0.5f), A::of(0.0f), A::of(0), A::of(zero), A::of(zero), A::of(-1), A::of(0.0f), A::of(zero), A::of(0)}};
}

std::vector<std::vector<float>> brdf3dSlab(KernelRunner& runner, const Brdf3dSpec& spec, int z0, int zn) {
  const int nchan = spec.channels();
  const size_t plane = static_cast<size_t>(spec.nx) * spec.ny * zn;
  cl_float4 fx = {{0, 0, 0, 0}}, fy = {{0, 0, 0, 0}}, rho = {{1, 1, 1, 1}};
  for (int ch = 0; ch < nchan; ++ch) {
    auto [x, y] = spec.fresnel.kernelParams(spec.fresnel.channels() == 3 ? ch : 0);
    fx.s[ch] = static_cast<float>(x);
    fy.s[ch] = static_cast<float>(y);
    if (!spec.rho.empty()) rho.s[ch] = static_cast<float>(spec.rho[spec.rho.size() == 3 ? ch : 0]);
  }
  // the axes' cosines and sines, in the program's `real`
  const std::vector<double> trig = axisTrig(spec);
  const float r = static_cast<float>(spec.roughness);
  using A = LaunchArg;
  std::vector<float> all =
      runner
          .launch(ProgramKey::Volume, spec.ndf, spec.gaf, kKernel,
                  LaunchShape{static_cast<size_t>(spec.nx), static_cast<size_t>(spec.ny) * zn, LaunchShape::Texels},
                  {A::output(plane * nchan), A::inputReals(trig), A::of(spec.nx), A::of(spec.ny), A::of(z0), A::of(zn),
                   A::of(spec.param == Brdf3dParam::Angles ? 0 : 1), A::of(spec.timesCos ? 1 : 0), A::of(r),
                   A::of(static_cast<float>(brdf64::brdf_params(spec.ndf, spec.gaf, r).inv_kp)),
                   A::of(spec.fresnel.model), A::of(fx), A::of(fy), A::of(spec.diffuse),
                   A::of(static_cast<float>(spec.diffuseParam)), A::of(rho), A::of(nchan)})
          .floats.at(0);
  std::vector<std::vector<float>> planes(nchan);
  for (int ch = 0; ch < nchan; ++ch)
    planes[ch].assign(all.begin() + static_cast<std::ptrdiff_t>(ch * plane),
                      all.begin() + static_cast<std::ptrdiff_t>((ch + 1) * plane));
  return planes;
}

}  // namespace brdfbake
