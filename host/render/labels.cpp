#include "render/labels.h"

#include <algorithm>
#include <cstdio>
#include <map>

#include "common/errors.h"

namespace brdfbake {

namespace {
// 5 x 7 glyphs, one string of 7 rows of 5 columns each ('#' lit), drawn for this project.
const std::map<char, const char*>& glyphs() {
  static const std::map<char, const char*> g = {
      {' ', "..................................."}, {'a', "...........###.....#.#####...#.####"},
      {'b', "#....#....####.#...##...##...#####."}, {'c', "...........#####....#....#.....####"},
      {'d', "....#....#.#####...##...##...#.####"}, {'e', "...........###.#...#######.....###."},
      {'f', "..##..#...####..#....#....#....#..."}, {'g', "......#####...##...#.####....#.###."},
      {'h', "#....#....####.#...##...##...##...#"}, {'i', "..#........##....#....#....#...###."},
      {'j', "...#........##....#....#.#..#..##.."}, {'k', "#....#....#..#.#.#..##...#.#..#..#."},
      {'l', ".##....#....#....#....#....#...###."}, {'m', "..........##.#.#.#.##.#.##.#.##...#"},
      {'n', "..........####.#...##...##...##...#"}, {'o', "...........###.#...##...##...#.###."},
      {'p', ".....####.#...##...#####.#....#...."}, {'q', "......#####...##...#.####....#....#"},
      {'r', "..........#.##.##..##....#....#...."}, {'s', "...........#####.....###.....#####."},
      {'t', ".#....#...####..#....#....#.....##."}, {'u', "..........#...##...##...##..##.##.#"},
      {'v', "..........#...##...##...#.#.#...#.."}, {'w', "..........#...##...##.#.##.#.#.#.#."},
      {'x', "..........#...#.#.#...#...#.#.#...#"}, {'y', ".....#...##...##...#.####....#.###."},
      {'z', "..........#####...#...#...#...#####"}, {'0', ".###.#...##..###.#.###..##...#.###."},
      {'1', "..#...##....#....#....#....#...###."}, {'2', ".###.#...#....#...#...#...#...#####"},
      {'3', "#####...#...#.....#.....##...#.###."}, {'4', "...#...##..#.#.#..#.#####...#....#."},
      {'5', "######....####.....#....##...#.###."}, {'6', "..##..#...#....####.#...##...#.###."},
      {'7', "#####....#...#...#...#....#....#..."}, {'8', ".###.#...##...#.###.#...##...#.###."},
      {'9', ".###.#...##...#.####....#...#..##.."}, {'.', "..........................##...##.."},
      {',', ".....................##....#...#..."}, {'=', "..........#####.....#####.........."},
      {'-', "...............#####..............."}, {':', "......##...##........##...##......."},
      {'(', "...#...#...#....#....#.....#.....#."}, {')', ".#.....#.....#....#....#...#...#..."},
      {'+', ".......#....#..#####..#....#......."}, {'/', "....#...#....#...#...#....#...#...."},
  };
  return g;
}
}  // namespace

int textWidth(const std::string& s, int scale) { return static_cast<int>(s.size()) * 6 * scale; }

void drawText(std::vector<std::vector<float>>& planes, int w, int h, int x, int y, const std::string& s, int scale,
              float v) {
  for (size_t k = 0; k < s.size(); ++k) {
    auto it = glyphs().find(s[k]);
    if (it == glyphs().end())
      throw Error(kExitSoftware, std::string("internal: no glyph for '") + s[k] + "' in a picture's label");
    for (int gy = 0; gy < 7; ++gy)
      for (int gx = 0; gx < 5; ++gx) {
        if (it->second[gy * 5 + gx] != '#') continue;
        for (int sy = 0; sy < scale; ++sy)
          for (int sx = 0; sx < scale; ++sx) {
            const int px = x + (static_cast<int>(k) * 6 + gx) * scale + sx, py = y + gy * scale + sy;
            if (px < 0 || py < 0 || px >= w || py >= h) continue;
            for (auto& p : planes) p[static_cast<size_t>(py) * w + px] = v;
          }
      }
  }
}

LabelledPicture labelFurnace(const std::vector<std::vector<float>>& planes, int w, int h, int cell, int columns,
                             const std::vector<std::pair<std::string, std::string>>& rows) {
  // names at twice the font's size where a cell holds two lines of it (cells of 40 pixels and up)
  const int big = cell >= 40 ? 2 : 1, pad = 6;
  int left = 0;
  for (const auto& [name, note] : rows) left = std::max({left, textWidth(name, big), textWidth(note, 1)});
  left += 2 * pad;
  const int top = 7 * big + 2 * pad;
  LabelledPicture out;
  out.width = w + left;
  out.height = h + top;
  out.planes.assign(planes.size(), std::vector<float>(static_cast<size_t>(out.width) * out.height, 1.0f));
  for (size_t c = 0; c < planes.size(); ++c)
    for (int y = 0; y < h; ++y)
      std::copy_n(planes[c].begin() + static_cast<long>(y) * w, w,
                  out.planes[c].begin() + static_cast<long>(y + top) * out.width + left);
  drawText(out.planes, out.width, out.height, pad, pad, "r =", big, 0.0f);
  for (int col = 0; col < columns; ++col) {
    char r[16];
    std::snprintf(r, sizeof r, "%.3g", static_cast<double>(col) / (columns - 1));
    drawText(out.planes, out.width, out.height, left + col * cell + (cell - textWidth(r, 1)) / 2,
             pad + (7 * big - 7) / 2, r, 1, 0.0f);
  }
  for (size_t row = 0; row < rows.size(); ++row) {
    const int y = top + static_cast<int>(row) * cell + (cell - 7 * big - 4 - 7) / 2;
    drawText(out.planes, out.width, out.height, pad, y, rows[row].first, big, 0.0f);
    drawText(out.planes, out.width, out.height, pad, y + 7 * big + 4, rows[row].second, 1, 0.35f);
  }
  return out;
}

}  // namespace brdfbake
