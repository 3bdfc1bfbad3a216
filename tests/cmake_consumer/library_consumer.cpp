// Links brdfbake::library, bakes the scene's split sum (ggx + smith-correlated, 16 x 16) in memory
// and compares every texel with the file the build-time bake (the command line) wrote, and the
// library's own write() of the same table with that file, byte for byte.
#include <brdfbake/brdfbake.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

static std::string bytes(const std::string& p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

int main(int argc, char** argv) try {
  if (argc != 3) {
    std::fprintf(stderr, "usage: library_consumer CLI_FILE SCRATCH_DIR\n");
    return 2;
  }
  brdfbake::BakeRequest req = brdfbake::defaultRequest();
  req.tables = {brdfbake::tableKind("splitsum")};
  req.size = 16;
  std::vector<brdfbake::Table> tables = brdfbake::bake(req);
  const brdfbake::Table file = brdfbake::readTable(argv[1]);
  const brdfbake::Table& mem = tables.at(0);
  if (mem.width != file.width || mem.height != file.height || mem.planes.size() != file.planes.size()) {
    std::fprintf(stderr, "library_consumer: shapes differ\n");
    return 1;
  }
  int texels = 0;
  for (size_t c = 0; c < mem.planes.size(); ++c)
    for (int y = 0; y < mem.height; ++y)
      for (int x = 0; x < mem.width; ++x, ++texels)
        if (mem.at(x, y, static_cast<int>(c)) != file.at(x, y, static_cast<int>(c))) {
          std::fprintf(stderr, "library_consumer: texel (%d, %d) channel %zu: %.9g in memory, %.9g in %s\n", x, y, c,
                       mem.at(x, y, static_cast<int>(c)), file.at(x, y, static_cast<int>(c)), argv[1]);
          return 1;
        }
  if (mem.texelBounds.size() != static_cast<size_t>(mem.width * mem.height) || !(mem.errorBound > 0)) {
    std::fprintf(stderr, "library_consumer: no per-texel claims\n");
    return 1;
  }
  brdfbake::write(tables, argv[2]);
  const std::string mine = std::string(argv[2]) + "/splitsum_ggx_smith-correlated.exr";
  if (bytes(mine) != bytes(argv[1])) {
    std::fprintf(stderr, "library_consumer: %s differs from %s\n", mine.c_str(), argv[1]);
    return 1;
  }
  std::printf("library_consumer: %d values equal to the command line's file, written the same bytes\n", texels);
  return 0;
} catch (const brdfbake::Error& e) {
  std::fprintf(stderr, "library_consumer: %s (exit %d)\n", e.what(), static_cast<int>(e.code()));
  return 1;
}
