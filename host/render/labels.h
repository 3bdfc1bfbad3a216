// Text on the pictures `brdfbake render` writes for people (the PNGs): a 5 x 7 pixel font of our
// own for the characters the labels use, and the furnace grid with its row names and roughness
// columns around it. The EXRs stay the bare grid (tests and readers index spheres by cell).
#pragma once
#include <string>
#include <vector>

namespace brdfbake {

// Width in pixels of `s` drawn at `scale` (6 pixels a character, 5 wide and a gap, times scale).
int textWidth(const std::string& s, int scale);
// Draws `s` with its top left at (x, y) into linear planes (R, G, B) of width w, value `v` on every
// plane; pixels outside the image are skipped. Error(kExitSoftware) for a character without a glyph.
void drawText(std::vector<std::vector<float>>& planes, int w, int h, int x, int y, const std::string& s, int scale,
              float v);

struct LabelledPicture {
  int width = 0, height = 0;
  std::vector<std::vector<float>> planes;
};
// The furnace grid (width w, height h, `cell` pixels a sphere) with a band on the left naming each
// row and saying what to expect of it (`rows`: {name, expectation}), and a band on top giving each
// column's roughness r = column/(columns - 1); background 1 (the furnace's white), text black.
LabelledPicture labelFurnace(const std::vector<std::vector<float>>& planes, int w, int h, int cell, int columns,
                             const std::vector<std::pair<std::string, std::string>>& rows);

}  // namespace brdfbake
