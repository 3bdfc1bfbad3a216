// Bakes a 64 x 64 GGX split-sum table in memory with the brdfbake library, prints a few texels
// and the claimed error, and writes it as KTX2 (float16) into lut/.
//   cmake -S . -B build -DCMAKE_PREFIX_PATH=<brdfbake's install prefix> && cmake --build build
//   ./build/bake_lut
#include <brdfbake/brdfbake.h>

#include <cstdio>

int main() try {
  brdfbake::BakeRequest req = brdfbake::defaultRequest();  // ggx + smith-correlated
  req.tables = {brdfbake::tableKind("splitsum")};
  req.size = 64;
  req.outDir = "lut";
  req.formats = {brdfbake::FileFormat::Ktx2};
  req.precision = brdfbake::Precision::Float16;

  std::vector<brdfbake::Table> tables = brdfbake::bake(req);
  const brdfbake::Table& lut = tables.front();
  std::printf("%s: %dx%d, channels %s, claimed error %.2e\n", lut.kind.c_str(), lut.width, lut.height,
              lut.metadata.at("brdf.channels").c_str(), lut.errorBound);
  for (int y : {0, 31, 63})  // r rows; x = mu
    std::printf("  r texel %2d: A(mu=1) = %.6f  B(mu=1) = %.6f\n", y, lut.at(63, y, 0), lut.at(63, y, 1));
  brdfbake::write(tables);  // lut/splitsum_ggx_smith-correlated.ktx2
  return 0;
} catch (const brdfbake::Error& e) {
  std::fprintf(stderr, "bake_lut: %s\n", e.what());
  return e.code();
}
