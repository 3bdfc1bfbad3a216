// A measured material's name, from its MERL file (--brdf merl:FILE; tables/measured/measured.cpp).
#pragma once
#include <string>

namespace brdfbake {

// "dir/gold-metallic-paint.binary" -> "gold-metallic-paint" (brdf.material = "merl:" + that).
std::string merlMaterialName(const std::string& path);

}  // namespace brdfbake
