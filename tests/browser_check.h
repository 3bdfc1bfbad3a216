// A report page opened in a real browser: headless Chromium (Debian `chromium`; CI installs it,
// scripts/install-deps.sh), offline (every host name resolves to nothing). On a copy of the page a
// script placed first in <head> counts console errors, uncaught exceptions and resources that fail
// to load, and at `load` writes the counts and each image's natural width into the title, which
// --dump-dom prints. A screenshot must not be blank. No Chromium: the check fails, loudly.
#pragma once
#include <gtest/gtest.h>
#include <png.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

namespace brdfbake::testing_browser {

struct PageCheck {
  int images = -1, loaded = -1, errors = -1;
  double inked = 0;  // fraction of the screenshot's pixels that are not the background's white
};

inline std::string chromium() {
  if (const char* c = std::getenv("BRDFBAKE_CHROMIUM"); c && *c) return c;
  return "chromium";
}

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

// The fraction of a PNG's pixels that differ from white by more than 8 levels (libpng's simple API).
inline double inkedFraction(const std::filesystem::path& png) {
  png_image img{};
  img.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&img, png.c_str())) return -1;
  img.format = PNG_FORMAT_RGB;
  std::vector<png_byte> px(PNG_IMAGE_SIZE(img));
  if (!png_image_finish_read(&img, nullptr, px.data(), 0, nullptr)) return -1;
  size_t inked = 0, n = static_cast<size_t>(img.width) * img.height;
  for (size_t i = 0; i < n; ++i)
    if (px[i * 3] < 247 || px[i * 3 + 1] < 247 || px[i * 3 + 2] < 247) ++inked;
  return n ? static_cast<double>(inked) / n : 0;
}

// Opens `page` (an index.html beside its images) in headless Chromium; `scratch` holds the copy,
// the profile and the screenshot.
inline PageCheck openInBrowser(const std::filesystem::path& page, const std::filesystem::path& scratch) {
  namespace fs = std::filesystem;
  PageCheck c;
  fs::remove_all(scratch);
  fs::create_directories(scratch);
  fs::copy(page.parent_path(), scratch / "page", fs::copy_options::recursive);
  const fs::path html = scratch / "page" / page.filename();
  std::string text = slurp(html);
  const std::string probe =
      "<script>var bbErrors=0;window.addEventListener('error',function(){bbErrors++;},true);"
      "var bbConsoleError=console.error;console.error=function(){bbErrors++;bbConsoleError.apply(console,arguments);};"
      "window.addEventListener('load',function(){var i=Array.prototype.slice.call(document.images);"
      "var ok=i.filter(function(x){return x.complete&&x.naturalWidth>0;}).length;"
      "document.title='brdfbake-check '+i.length+' '+ok+' '+bbErrors;});</script>";
  const size_t head = text.find("<head>");
  if (head == std::string::npos) {
    ADD_FAILURE() << page << ": no <head>";
    return c;
  }
  text.insert(head + 6, probe);
  std::ofstream(html, std::ios::binary | std::ios::trunc) << text;
  const std::string common = "'" + chromium() + "' --headless --no-sandbox --disable-gpu --user-data-dir='" +
                             (scratch / "profile").string() + "' --host-resolver-rules='MAP * ~NOTFOUND' ";
  const std::string url = "'file://" + html.string() + "'";
  const std::string dom = (scratch / "dom.html").string(), log = (scratch / "chromium.log").string();
  int rc = std::system(
      ("timeout 120 " + common + "--virtual-time-budget=5000 --dump-dom " + url + " >'" + dom + "' 2>'" + log + "'")
          .c_str());
  if (rc != 0) {
    ADD_FAILURE() << "Chromium did not run (" << chromium() << ", exit " << rc
                  << "): apt-get install chromium (scripts/install-deps.sh)\n"
                  << slurp(log);
    return c;
  }
  std::smatch m;
  const std::string out = slurp(dom);
  if (std::regex_search(out, m, std::regex("<title>brdfbake-check ([0-9]+) ([0-9]+) ([0-9]+)</title>"))) {
    c.images = std::stoi(m[1]);
    c.loaded = std::stoi(m[2]);
    c.errors = std::stoi(m[3]);
  } else {
    ADD_FAILURE() << page << ": the page's load event never came\n" << out.substr(0, 2000);
  }
  const fs::path shot = scratch / "shot.png";
  rc = std::system(("timeout 120 " + common + "--window-size=1000,1400 --screenshot='" + shot.string() + "' " + url +
                    " >/dev/null 2>>'" + log + "'")
                       .c_str());
  c.inked = rc == 0 ? inkedFraction(shot) : -1;
  return c;
}

// The checks every report page passes: each image loads, no error, not blank, nothing fetched
// from the network (no external URL in the page).
inline void expectPageWorks(const std::filesystem::path& page, const std::filesystem::path& scratch, int minImages) {
  const PageCheck c = openInBrowser(page, scratch);
  EXPECT_GE(c.images, minImages) << page;
  EXPECT_EQ(c.loaded, c.images) << page << ": an image did not load (natural width 0)";
  EXPECT_EQ(c.errors, 0) << page << ": console errors, exceptions or failed resources";
  EXPECT_GT(c.inked, 0.02) << page << ": the screenshot is blank";
  const std::string html = slurp(page);
  EXPECT_EQ(html.find("src=\"http"), std::string::npos) << page << ": an external resource";
  EXPECT_EQ(html.find("href=\"http"), std::string::npos) << page << ": an external link or stylesheet";
}

}  // namespace brdfbake::testing_browser
