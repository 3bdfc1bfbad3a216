// Furnace renders on the report pages (report/furnace_figure.h).
#include "report/furnace_figure.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "brdfbake/error.h"
#include "common/format.h"
#include "common/models.h"
#include "formats/writers.h"
#include "render/furnace.h"
#include "render/gl_context.h"
#include "render/labels.h"
#include "tables/registry.h"

namespace fs = std::filesystem;

namespace brdfbake {

namespace {

// A private directory for the tables, removed when it goes out of scope.
struct ScratchDir {
  std::string path;
  ScratchDir() {
    const char* env = std::getenv("TMPDIR");
    std::string tmpl = std::string(env && *env ? env : "/tmp") + "/brdfbake-figure-XXXXXX";
    if (!mkdtemp(tmpl.data())) throw Error(kExitCantCreat, "cannot create a temporary directory from " + tmpl);
    path = tmpl;
  }
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

}  // namespace

bool furnaceSamples(const std::string& kind) {
  const KindInfo* k = findKind(kind);
  return k && k->furnace;
}

FurnaceFigures::FurnaceFigures(std::string device) : device_(std::move(device)) {}
FurnaceFigures::~FurnaceFigures() = default;

bool FurnaceFigures::add(ReportPage& page, int ndf, int gaf) {
  const std::string pair = ndfNames()[static_cast<size_t>(ndf)] + " + " + gafNames()[static_cast<size_t>(gaf)];
  FurnaceSpec spec;
  spec.ndf = ndf;
  spec.gaf = gaf;
  spec.cell = 32;
  spec.columns = 9;
  spec.glassMu = 16;
  spec.glassR = 8;
  for (const char* row : {"single", "kulla-conty", "single-table", "glass"}) {
    const int k = furnaceRowIndex(row);
    if (furnaceRowFits(k, ndf, gaf)) spec.rows.push_back(k);
  }
  if (isSheenNdf(ndf)) {
    page.paragraph("Furnace render: not drawn for " + pair +
                   " (a sheen layer, not a material: `brdfbake render` draws "
                   "charlie + charlie-smith's albedo in its sheen row).");
    return true;
  }
  if (!tried_) {
    tried_ = true;
    try {
      gl_ = std::make_unique<GlContext>();
    } catch (const Error& e) {
      unavailable_ = e.what();
    }
  }
  if (!gl_) {
    page.paragraph("Furnace render: not drawn, no OpenGL ES device: " + unavailable_);
    return true;
  }
  FurnacePicture pic;
  try {
    ScratchDir dir;
    const FurnaceTables tables = bakeFurnaceTables(spec, dir.path, device_, false);
    pic = renderFurnace(*gl_, spec, tables);
  } catch (const Error& e) {
    // the report's verdict does not depend on the render: say why it is missing, keep the page
    page.paragraph("Furnace render of " + pair + ": not drawn: " + e.what());
    return false;
  }
  std::string rowNames;
  for (int k : spec.rows) rowNames += (rowNames.empty() ? "" : ", ") + furnaceRows()[static_cast<size_t>(k)].name;
  const std::string file =
      "render_" + ndfNames()[static_cast<size_t>(ndf)] + "_" + gafNames()[static_cast<size_t>(gaf)] + ".png";
  // the text chunks: what made it, without the scratch directory's name (the page's bytes repeat)
  std::vector<std::pair<std::string, std::string>> text = {
      {"render.kind", "white furnace: uniform environment of radiance 1, background 1"},
      {"render.model", pair},
      {"render.rows", rowNames},
      {"render.columns", "perceptual roughness r = column/" + std::to_string(spec.columns - 1)},
      {"render.renderer", pic.renderer},
      {"render.generator", "brdfbake (report page)"}};
  std::vector<std::pair<std::string, std::string>> rowLabels;
  for (int k : spec.rows)
    rowLabels.push_back({furnaceRows()[static_cast<size_t>(k)].name, furnaceRows()[static_cast<size_t>(k)].expect});
  LabelledPicture shown = labelFurnace(pic.rgb, pic.width, pic.height, spec.cell, spec.columns, rowLabels);
  const int W = shown.width, H = shown.height;
  page.image(file,
             "White furnace, " + pair + ": rows " + rowNames + "; roughness 0 to 1 across; shaded on " + pic.renderer +
                 " by the generated lookups of the baked tables (rows that conserve vanish into the background)",
             [W, H, rgb = std::move(shown.planes), text](const std::string& path) {
               writePng8SrgbTemporary(path, path, W, H, rgb, text);
             });
  page.preformatted(furnaceTable(spec, pic) + (pic.fail
                                                   ? "FAIL: a row's pixels are off by more than the tables predict\n"
                                                   : "every measured pixel within its bound (docs/reports.md)\n"));
  return !pic.fail;
}

}  // namespace brdfbake
