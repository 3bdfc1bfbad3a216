// The LTC tables' lookup code (`brdfbake shader`): their accessors, and the integral of the LTC
// over a quad light, written once with them (tables/kind_info.h ShaderCode).
#pragma once
#include "tables/kind_info.h"

namespace brdfbake {

ShaderCode ltcShaderCode();

}  // namespace brdfbake
