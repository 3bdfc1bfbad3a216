// The furnace render on a report page (verify, stress, convergence, energy): for a pair the pages
// test, the white furnace's single, Kulla-Conty and single-table rows, and rough glass where the
// pair takes it (render/furnace.h), small (32 px spheres, 9 roughness steps), its PNG in the page's
// directory and its measurement beside it. The tables are baked into a private temporary directory,
// removed afterwards. Without EGL the page says what to install and is written all the same: a
// report's verdict does not depend on a GL device.
#pragma once
#include <memory>
#include <string>

#include "report/report_page.h"

namespace brdfbake {

class GlContext;

// Whether the furnace reads a table of this kind (its name: "splitsum", ...): the split sum, the
// albedos and the rough dielectric's tables, which the pages' renders then concern.
bool furnaceSamples(const std::string& kind);

class FurnaceFigures {
 public:
  explicit FurnaceFigures(std::string device);
  ~FurnaceFigures();
  // Adds the pair's render and its measurement to `page` (a paragraph for a pair it does not draw:
  // charlie's, or when no GL device is there). Returns false when a measured row is past its bound.
  bool add(ReportPage& page, int ndf, int gaf);

 private:
  std::string device_;
  std::unique_ptr<GlContext> gl_;
  std::string unavailable_;  // why there is no GL context, once tried
  bool tried_ = false;
};

}  // namespace brdfbake
