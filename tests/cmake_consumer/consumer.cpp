// Loads what the build baked: every table the stamp lists must exist and be an OpenEXR file.
#include <cstdio>
#include <fstream>
#include <string>

int main() {
  std::ifstream list(TABLE_LIST);
  if (!list) {
    std::fprintf(stderr, "consumer: no table list %s\n", TABLE_LIST);
    return 1;
  }
  int found = 0;
  for (std::string line; std::getline(list, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::ifstream f(line, std::ios::binary);
    unsigned char magic[4] = {0, 0, 0, 0};
    f.read(reinterpret_cast<char*>(magic), 4);
    if (!f || magic[0] != 0x76 || magic[1] != 0x2f || magic[2] != 0x31 || magic[3] != 0x01) {
      std::fprintf(stderr, "consumer: %s is missing or not an OpenEXR file\n", line.c_str());
      return 1;
    }
    std::printf("consumer: found %s\n", line.c_str());
    ++found;
  }
  if (found == 0) {
    std::fprintf(stderr, "consumer: the table list is empty\n");
    return 1;
  }
  return 0;
}
