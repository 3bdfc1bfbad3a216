// Tables read back by readers other than ours: FreeImage (Debian libfreeimage3, behind many tools
// and engine importers) and OpenImageIO. Every table kind (the 3D table's atlas too), FLOAT and
// HALF, must read back with the values our own reader sees, in R, G and B.
#include <FreeImage.h>
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "formats/exr/table_file.h"

namespace fs = std::filesystem;
namespace {

const char* kFiles[] = {"splitsum_ggx_smith-correlated.exr", "albedo_ggx_smith-correlated.exr",
                        "albedo-avg_ggx_smith-correlated.exr", "kp_ggx.exr",
                        "brdf3d_ggx_smith-correlated_angles.exr"};  // the 3D table's atlas

fs::path bake(bool half) {
  fs::path d =
      fs::path(testing::TempDir()) / ("brdfbake_readers_" + std::to_string(half) + "_" + std::to_string(getpid()));
  fs::remove_all(d);
  std::string cmd = std::string("'") + BRDFBAKE_EXE + "' --size 16 " + (half ? "--half " : "") + "-o '" + d.string() +
                    "' > /dev/null";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  // a 3D table (16^3, as a 4 x 4 atlas of slices) in the same directory, beside the default set
  std::string vol = std::string("'") + BRDFBAKE_EXE + "' --table brdf3d --size 16 --roughness 0.4 " +
                    (half ? "--half " : "") + "-o '" + d.string() + "' > /dev/null";
  EXPECT_EQ(std::system(vol.c_str()), 0) << vol;
  return d;
}

// Our reader's value of channel c (0 R, 1 G, 2 B) at (x, y).
float ours(const brdfbake::TableImage& t, int c, int x, int y) {
  return t.planes[c][static_cast<size_t>(y) * t.width + x];
}

TEST(OtherReaders, FreeImageReadsEveryTableKind) {
  FreeImage_Initialise();
  for (bool half : {false, true}) {
    fs::path d = bake(half);
    for (const char* name : kFiles) {
      std::string f = (d / name).string();
      brdfbake::TableImage t = brdfbake::readTableExr(f);
      ASSERT_EQ(t.channels.size(), 3u) << f;
      FIBITMAP* bmp = FreeImage_Load(FIF_EXR, f.c_str(), 0);
      ASSERT_NE(bmp, nullptr) << "FreeImage cannot load " << f;
      EXPECT_EQ(FreeImage_GetImageType(bmp), FIT_RGBF) << f;
      EXPECT_EQ(static_cast<int>(FreeImage_GetWidth(bmp)), t.width);
      EXPECT_EQ(static_cast<int>(FreeImage_GetHeight(bmp)), t.height);
      double worst = 0, peak = 0;
      for (int y = 0; y < t.height; ++y) {
        // FreeImage stores rows bottom-up
        const FIRGBF* row = reinterpret_cast<const FIRGBF*>(FreeImage_GetScanLine(bmp, t.height - 1 - y));
        for (int x = 0; x < t.width; ++x) {
          const float v[3] = {row[x].red, row[x].green, row[x].blue};
          for (int c = 0; c < 3; ++c) {
            worst = std::max(worst, static_cast<double>(std::fabs(v[c] - ours(t, c, x, y))));
            peak = std::max(peak, static_cast<double>(std::fabs(v[c])));
          }
        }
      }
      EXPECT_EQ(worst, 0.0) << f;
      EXPECT_GT(peak, 0.0) << f << " read back as zeros";
      FreeImage_Unload(bmp);
    }
  }
  FreeImage_DeInitialise();
}

TEST(OtherReaders, OpenImageIOReadsEveryTableKind) {
  for (bool half : {false, true}) {
    fs::path d = bake(half);
    for (const char* name : kFiles) {
      std::string f = (d / name).string();
      brdfbake::TableImage t = brdfbake::readTableExr(f);
      auto in = OIIO::ImageInput::open(f);
      ASSERT_TRUE(in) << OIIO::geterror();
      const OIIO::ImageSpec& spec = in->spec();
      ASSERT_EQ(spec.nchannels, 3) << f;
      EXPECT_EQ(spec.channelnames[0], "R");
      EXPECT_EQ(spec.width, t.width);
      EXPECT_EQ(spec.height, t.height);
      EXPECT_EQ(spec.get_string_attribute("brdf.table"), t.strings["brdf.table"]) << f;
      std::vector<float> px(static_cast<size_t>(spec.width) * spec.height * 3);
      ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, px.data())) << in->geterror();
      double worst = 0;
      for (int y = 0; y < t.height; ++y)
        for (int x = 0; x < t.width; ++x)
          for (int c = 0; c < 3; ++c)
            worst = std::max(worst, static_cast<double>(std::fabs(px[(static_cast<size_t>(y) * t.width + x) * 3 + c] -
                                                                  ours(t, c, x, y))));
      EXPECT_EQ(worst, 0.0) << f;
    }
  }
}

}  // namespace
