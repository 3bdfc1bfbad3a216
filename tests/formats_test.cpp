// --format and --precision: every format reads back through a reader other than our writer, with
// the values of the float32 EXR within the storage rounding its brdf.error states. KTX2 and DDS by
// the specification-checking readers in tests/ (ktx2_reader.h, dds_reader.h; OpenImageIO 2.4 does
// not read DX10 DDS, Pillow reads its R8G8B8A8_UNORM), PNG by OpenImageIO, FreeImage and Pillow, the
// header by the C++ compiler (and node, when CMake found it). Bad input and determinism too.
#include <FreeImage.h>
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "tables/volume.h"
#include "dds_reader.h"
#include "formats/exr/table_file.h"
#include "formats/storage.h"
#include "formats/writers.h"
#include "ktx2_reader.h"

namespace fs = std::filesystem;
using brdfbake::Precision;
using brdfbake::TableImage;

namespace {

struct CmdResult {
  int code;
  std::string out;
};

CmdResult sh(const std::string& cmd) {
  CmdResult r{-1, ""};
  FILE* p = ::popen((cmd + " 2>&1").c_str(), "r");
  if (!p) return r;
  char buf[4096];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) r.out.append(buf, n);
  const int st = ::pclose(p);
  r.code = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return r;
}

fs::path tempDir(const std::string& name) {
  fs::path d = fs::path(testing::TempDir()) / ("brdfbake_formats_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  return d;
}

CmdResult bake(const std::string& args, const fs::path& dir) {
  return sh(std::string("'") + BRDFBAKE_EXE + "' bake " + args + " -o '" + dir.string() + "'");
}

const char* kTables = "--table splitsum,albedo,albedo-avg --size 16";
const char* kStems[] = {"splitsum_ggx_smith-correlated", "albedo_ggx_smith-correlated",
                        "albedo-avg_ggx_smith-correlated"};

// The reference: the same tables as float32 EXR.
const fs::path& reference() {
  static fs::path d = [] {
    fs::path r = tempDir("reference");
    EXPECT_EQ(bake(kTables, r).code, 0);
    return r;
  }();
  return d;
}

double allowed(Precision p, double v) {
  switch (p) {
    case Precision::Float32:
      return 0;
    case Precision::Float16:
      return std::ldexp(1.0, -11) * std::max(std::fabs(v), std::ldexp(1.0, -14));
    case Precision::Unorm16:
      return 0.5 / 65535 + 1e-12;
    case Precision::Unorm8:
      return 0.5 / 255 + 1e-12;
  }
  return 0;
}

// Texel i's channel c of an interleaved reader's values (stride `n`) against the reference.
void compareTexels(const std::string& what, const TableImage& ref, const std::vector<double>& texels, int n,
                   Precision p, double* worstRel) {
  ASSERT_EQ(texels.size(), static_cast<size_t>(ref.width) * ref.height * n) << what;
  for (size_t i = 0; i < static_cast<size_t>(ref.width) * ref.height; ++i)
    for (int c = 0; c < n; ++c) {
      const double want = c < 3 ? ref.planes[c][i] : 1.0;  // A = 1: padding
      const double got = texels[i * n + c];
      ASSERT_LE(std::fabs(got - want), allowed(p, want)) << what << " texel " << i << " channel " << c;
      *worstRel = std::max(*worstRel, std::fabs(got - want) / std::max(1.0, std::fabs(want)));
    }
}

float statedError(const TableImage& t) { return t.floats.at("brdf.error"); }

TEST(Formats, Ktx2AndDdsOfEveryPrecisionReadBackWithinTheirStatedError) {
  for (Precision p : {Precision::Float32, Precision::Float16, Precision::Unorm16, Precision::Unorm8}) {
    const std::string name = brdfbake::precisionName(p);
    fs::path d = tempDir(name);
    CmdResult r = bake(std::string(kTables) + " --format ktx2,dds --precision " + name, d);
    ASSERT_EQ(r.code, 0) << r.out;
    for (const char* stem : kStems) {
      TableImage ref = brdfbake::readTableExr((reference() / (std::string(stem) + ".exr")).string());
      ktx2check::Texture k = ktx2check::read((d / (std::string(stem) + ".ktx2")).string());
      EXPECT_TRUE(k.problems.empty()) << stem << " " << name << ": " << ::testing::PrintToString(k.problems);
      EXPECT_EQ(k.vkFormat, brdfbake::ktx2VkFormat(4, p));
      EXPECT_EQ(static_cast<int>(k.width), ref.width);
      EXPECT_EQ(static_cast<int>(k.height), ref.height);
      EXPECT_EQ(k.depth, 0u);
      EXPECT_EQ(k.kv["KTXorientation"], "rd");
      EXPECT_EQ(k.kv["brdf.table"], ref.strings["brdf.table"]);
      EXPECT_EQ(k.kv["brdf.precision"], name);
      EXPECT_EQ(k.kv["KTXwriter"].rfind("brdfbake ", 0), 0u);
      double worst = 0;
      compareTexels(std::string(stem) + ".ktx2", ref, k.texels, 4, p, &worst);
      // brdf.error: the computation's error (the float32 file's: float32 storage adds nothing) + this storage
      // the string holds a float to 9 digits: read back as that float (as a double, the nearest
      // double to the decimal can fall below the float it stands for)
      const double stated = static_cast<float>(std::stod(k.kv["brdf.error"]));
      EXPECT_GE(stated, statedError(ref) + worst * (1 - 1e-6)) << stem << " " << name;
      EXPECT_LE(stated, statedError(ref) + brdfbake::storageErrorBound(p) + 1e-9) << stem << " " << name;

      ddscheck::Texture t = ddscheck::read((d / (std::string(stem) + ".dds")).string());
      EXPECT_TRUE(t.problems.empty()) << stem << " " << name << ": " << ::testing::PrintToString(t.problems);
      EXPECT_EQ(t.dimension, 3u);
      double worstDds = 0;
      compareTexels(std::string(stem) + ".dds", ref, t.texels, 4, p, &worstDds);
      EXPECT_EQ(worstDds, worst) << "the DDS and KTX2 files store the same values";
    }
  }
}

// Pillow 9.4 reads DX10 DDS files in R8G8B8A8_UNORM: the unorm8 files through a third reader.
TEST(Formats, PillowReadsTheUnorm8Dds) {
  fs::path d = tempDir("pillow_dds");
  ASSERT_EQ(bake(std::string(kTables) + " --format dds --precision unorm8", d).code, 0);
  const std::string f = (d / "splitsum_ggx_smith-correlated.dds").string();
  CmdResult r =
      sh(std::string("'") + BRDFBAKE_PYTHON + "' -c \"from PIL import Image\nim = Image.open('" + f +
         "')\nprint(im.mode, im.size[0], im.size[1])\nprint(' '.join(str(v) for px in im.getdata() for v in px))\"");
  ASSERT_EQ(r.code, 0) << r.out;
  std::istringstream in(r.out);
  std::string mode;
  int w = 0, h = 0;
  in >> mode >> w >> h;
  EXPECT_EQ(mode, "RGBA");
  TableImage ref = brdfbake::readTableExr((reference() / "splitsum_ggx_smith-correlated.exr").string());
  ASSERT_EQ(w, ref.width);
  ASSERT_EQ(h, ref.height);
  for (size_t i = 0; i < static_cast<size_t>(w) * h; ++i)
    for (int c = 0; c < 4; ++c) {
      int v = -1;
      in >> v;
      const double want = c < 3 ? ref.planes[c][i] : 1.0;
      ASSERT_LE(std::fabs(v / 255.0 - want), 0.5 / 255 + 1e-12) << "texel " << i << " channel " << c;
    }
}

TEST(Formats, ThreeDimensionalTablesAreKtx2AndDdsVolumesEqualToTheExrAtlas) {
  fs::path d = tempDir("volume");
  CmdResult r = bake("--table brdf3d --size 6,5,7 --roughness 0.4 --format exr,ktx2,dds --precision float16", d);
  ASSERT_EQ(r.code, 0) << r.out;
  const std::string stem = (d / "brdf3d_ggx_smith-correlated_angles").string();
  TableImage atlas = brdfbake::readTableExr(stem + ".exr");
  int cols = 0, rows = 0;
  brdfbake::Brdf3dSpec s = brdfbake::specFromHeader(stem + ".exr", atlas, &cols, &rows);
  std::vector<std::vector<float>> vol = brdfbake::volumeFromAtlas(atlas, s, cols);
  ktx2check::Texture k = ktx2check::read(stem + ".ktx2");
  EXPECT_TRUE(k.problems.empty()) << ::testing::PrintToString(k.problems);
  EXPECT_EQ(k.width, 6u);
  EXPECT_EQ(k.height, 5u);
  EXPECT_EQ(k.depth, 7u);
  EXPECT_EQ(k.kv["KTXorientation"], "rdi");
  EXPECT_EQ(k.kv["brdf.size"], "6x5x7");
  EXPECT_EQ(k.kv.count("brdf.atlas"), 0u);
  ddscheck::Texture t = ddscheck::read(stem + ".dds");
  EXPECT_TRUE(t.problems.empty()) << ::testing::PrintToString(t.problems);
  EXPECT_EQ(t.dimension, 4u);
  EXPECT_EQ(t.depth, 7u);
  ASSERT_EQ(k.texels.size(), vol[0].size() * 4);
  ASSERT_EQ(t.texels.size(), vol[0].size() * 4);
  for (size_t i = 0; i < vol[0].size(); ++i)
    for (int c = 0; c < 3; ++c) {
      ASSERT_EQ(k.texels[i * 4 + c], vol[c][i]) << "KTX2 texel " << i;  // both float16: identical
      ASSERT_EQ(t.texels[i * 4 + c], vol[c][i]) << "DDS texel " << i;
    }
}

// The mapping of a PNG: value = png / 65535 * scale + offset, from the file's own text chunks.
struct Mapping {
  double scale = 0, offset = 0;
};

TEST(Formats, Png16ReadsBackInOpenImageIOFreeImageAndPillowWithItsMapping) {
  fs::path d = tempDir("png");
  // --gaf none: E grows like 1/mu, past 1: the mapping scales it onto the 16 bits
  CmdResult r = bake("--table splitsum,albedo --gaf none,smith-correlated --size 16 --format exr,png16", d);
  ASSERT_EQ(r.code, 0) << r.out;
  FreeImage_Initialise();
  for (const char* stem : {"albedo_ggx_none", "splitsum_ggx_smith-correlated"}) {
    const std::string base = (d / stem).string();
    TableImage ref = brdfbake::readTableExr(base + ".exr");
    auto in = OIIO::ImageInput::open(base + ".png");
    ASSERT_TRUE(in) << OIIO::geterror();
    const OIIO::ImageSpec& spec = in->spec();
    EXPECT_EQ(spec.nchannels, 3);
    EXPECT_EQ(spec.format, OIIO::TypeDesc::UINT16);
    Mapping m{std::stod(spec.get_string_attribute("brdf.mapping.scale")),
              std::stod(spec.get_string_attribute("brdf.mapping.offset"))};
    if (std::string(stem) == "albedo_ggx_none")
      EXPECT_GT(m.scale, 1.5) << "E exceeds 1: a scaled mapping";
    else
      EXPECT_EQ(m.scale, 1.0);
    const double stated = std::stod(spec.get_string_attribute("brdf.error"));
    std::vector<uint16_t> px(static_cast<size_t>(spec.width) * spec.height * 3);
    ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT16, px.data()));
    double worst = 0;
    for (size_t i = 0; i < px.size() / 3; ++i)
      for (int c = 0; c < 3; ++c) {
        const double v = px[i * 3 + c] / 65535.0 * m.scale + m.offset, want = ref.planes[c][i];
        ASSERT_LE(std::fabs(v - want), 0.5 / 65535 * m.scale + 1e-9) << stem << " texel " << i;
        worst = std::max(worst, std::fabs(v - want) / std::max(1.0, std::fabs(want)));
      }
    EXPECT_GE(stated, statedError(ref) + worst * (1 - 1e-6));
    // FreeImage: 16-bit RGB, rows bottom-up
    FIBITMAP* bmp = FreeImage_Load(FIF_PNG, (base + ".png").c_str(), PNG_DEFAULT);
    ASSERT_NE(bmp, nullptr);
    EXPECT_EQ(FreeImage_GetImageType(bmp), FIT_RGB16);
    for (int y = 0; y < ref.height; ++y) {
      const FIRGB16* row = reinterpret_cast<const FIRGB16*>(FreeImage_GetScanLine(bmp, ref.height - 1 - y));
      for (int x = 0; x < ref.width; ++x) {
        const size_t i = static_cast<size_t>(y) * ref.width + x;
        ASSERT_EQ(row[x].red, px[i * 3]);
        ASSERT_EQ(row[x].green, px[i * 3 + 1]);
        ASSERT_EQ(row[x].blue, px[i * 3 + 2]);
      }
    }
    FreeImage_Unload(bmp);
    // Pillow: the text chunks, and the samples (Pillow 9 keeps 16-bit RGB as 8-bit: the high byte)
    CmdResult py = sh(std::string("'") + BRDFBAKE_PYTHON + "' -c \"from PIL import Image\nim = Image.open('" + base +
                      ".png')\nprint(im.text['brdf.mapping.scale'], im.text['brdf.table'], im.size[0], im.size[1])\n"
                      "print(' '.join(str(v) for px in im.getdata() for v in px))\"");
    ASSERT_EQ(py.code, 0) << py.out;
    std::istringstream pin(py.out);
    std::string scale, table;
    int w = 0, h = 0;
    pin >> scale >> table >> w >> h;
    EXPECT_EQ(std::stod(scale), m.scale);
    EXPECT_EQ(table, ref.strings["brdf.table"]);
    ASSERT_EQ(w, ref.width);
    ASSERT_EQ(h, ref.height);
    for (size_t i = 0; i < px.size(); ++i) {
      int v = -1;
      pin >> v;
      ASSERT_EQ(v, px[i] >> 8) << "Pillow sample " << i;
    }
  }
}

// Compiles `main` against the generated header with the project's C++ compiler; its output.
std::string compileAndRun(const fs::path& dir, const std::string& header, const std::string& body) {
  const fs::path src = dir / "use_header.cpp", exe = dir / "use_header";
  std::ofstream(src) << "#include \"" << header << "\"\n#include <cstdio>\nint main() {\n" << body << "\n}\n";
  CmdResult c = sh(std::string("'") + BRDFBAKE_CXX + "' -std=c++17 -Wall -Wextra -Werror -pedantic -I'" + dir.string() +
                   "' '" + src.string() + "' -o '" + exe.string() + "'");
  EXPECT_EQ(c.code, 0) << c.out;
  CmdResult r = sh("'" + exe.string() + "'");
  EXPECT_EQ(r.code, 0) << r.out;
  return r.out;
}

TEST(Formats, HeaderCompilesAndHoldsTheStoredValues) {
  for (Precision p : {Precision::Float32, Precision::Float16, Precision::Unorm16}) {
    const std::string name = brdfbake::precisionName(p);
    fs::path d = tempDir("header_" + name);
    ASSERT_EQ(bake(std::string(kTables) + " --format header,ktx2 --precision " + name, d).code, 0);
    const std::string id = "brdf_splitsum_ggx_smith_correlated", M = "BRDF_SPLITSUM_GGX_SMITH_CORRELATED";
    std::string out = compileAndRun(d, "splitsum_ggx_smith-correlated.h",
                                    "std::printf(\"%d %d %d %d %s %d\\n\", " + M + "_WIDTH, " + M + "_HEIGHT, " + M +
                                        "_DEPTH, " + M + "_CHANNELS, " + M + "_PRECISION, " + M +
                                        "_ATTRIBUTE_COUNT);\n"
                                        "for (unsigned i = 0; i < sizeof " +
                                        id + "_data / sizeof " + id +
                                        "_data[0]; ++i) std::printf(\"%.9g\\n\", (double)" + id + "_data[i]);");
    std::istringstream in(out);
    int w = 0, h = 0, depth = 0, ch = 0, attrs = 0;
    std::string prec;
    in >> w >> h >> depth >> ch >> prec >> attrs;
    EXPECT_EQ(w, 16);
    EXPECT_EQ(h, 16);
    EXPECT_EQ(depth, 1);
    EXPECT_EQ(ch, 3);
    EXPECT_EQ(prec, name);
    EXPECT_GT(attrs, 10);
    // the header's stored values are exactly the KTX2 file's
    ktx2check::Texture k = ktx2check::read((d / "splitsum_ggx_smith-correlated.ktx2").string());
    std::vector<double> values;
    for (double v; in >> v;) values.push_back(v);
    ASSERT_EQ(values.size(), 16u * 16u * 3u);
    for (size_t i = 0; i < values.size(); ++i) {
      double v = values[i];
      if (p == Precision::Float32) v = static_cast<float>(v);  // 9 digits: the float itself
      if (p == Precision::Float16) v = static_cast<float>(Imath::half(Imath::half::FromBits, static_cast<uint16_t>(v)));
      if (p == Precision::Unorm16) v /= 65535.0;
      ASSERT_EQ(v, k.texels[(i / 3) * 4 + i % 3]) << name << " value " << i;
    }
#ifdef BRDFBAKE_NODE
    CmdResult js = sh(std::string("'") + BRDFBAKE_NODE + "' --input-type=module -e \"import * as t from 'file://" +
                      (d / "splitsum_ggx_smith-correlated.mjs").string() +
                      "'; console.log(t.width, t.height, t.precision, t.attributes['brdf.table']); "
                      "for (const v of t.data) console.log(v.toPrecision(9));\"");
    ASSERT_EQ(js.code, 0) << js.out;
    std::istringstream jin(js.out);
    std::string jp, table;
    jin >> w >> h >> jp >> table;
    EXPECT_EQ(jp, name);
    EXPECT_EQ(table, "splitsum");
    for (size_t i = 0; i < values.size(); ++i) {
      double v = -1;
      jin >> v;
      ASSERT_EQ(static_cast<float>(v), static_cast<float>(values[i])) << "node value " << i;
    }
#endif
  }
}

TEST(Formats, SameInputSameBytes) {
  fs::path a = tempDir("same_a"), b = tempDir("same_b");
  const std::string args = "--table splitsum,brdf3d --size 8 --format exr,ktx2,dds,header --precision float16";
  ASSERT_EQ(bake(args, a).code, 0);
  ASSERT_EQ(bake(args, b).code, 0);
  ASSERT_EQ(bake("--table splitsum --size 8 --format png16", a / "png").code, 0);
  ASSERT_EQ(bake("--table splitsum --size 8 --format png16", b / "png").code, 0);
  int files = 0;
  for (const auto& e : fs::recursive_directory_iterator(a)) {
    if (!e.is_regular_file()) continue;
    const fs::path other = b / fs::relative(e.path(), a);
    std::ifstream fa(e.path(), std::ios::binary), fb(other, std::ios::binary);
    std::stringstream sa, sb;
    sa << fa.rdbuf();
    sb << fb.rdbuf();
    EXPECT_EQ(sa.str(), sb.str()) << e.path();
    ++files;
  }
  EXPECT_EQ(files, 11);  // 2 tables x (exr, ktx2, dds, h, mjs) + the png
}

TEST(Formats, BadInputIsRefusedWithExit64AndNothingWritten) {
  struct Case {
    std::string args, message;
  } cases[] = {
      {"--table albedo --gaf none --size 8 --format ktx2 --precision unorm16",
       "outside [0, 1], which unorm16 cannot hold; float32 or float16 (exr, ktx2, dds, header) can"},
      {"--table kp --size 8 --format dds,exr --precision unorm8 --format dds", "--format given twice"},
      {"--table splitsum --size 8 --format exr --precision unorm16", "--format exr stores float32 or float16"},
      {"--table splitsum --size 8 --format png16 --precision float16", "--format png16 stores unorm16 only"},
      {"--table brdf3d --size 8 --format png16", "a 3D table (brdf3d) has no PNG form"},
      {"--table brdf3d --size 8 --format ktx2 --precision unorm16", "is outside [0, 1], which unorm16 cannot hold"},
      {"--table splitsum --format bmp", "--format must be one or more of exr, ktx2, dds, png16, header"},
      {"--table splitsum --precision float64", "--precision must be one of float32, float16, unorm16, unorm8"},
      {"--table splitsum --half --precision float32", "--half is --precision float16; give one of them"},
      {"--table brdf3d --format merl,ktx2", "--format merl writes MERL's binary file alone"},
      {"--table albedo --format ktx2 --precision unorm8 --format ktx2", "--format given twice"},
  };
  for (const Case& c : cases) {
    fs::path d = tempDir("bad");
    CmdResult r = bake(c.args, d / "out");
    EXPECT_EQ(r.code, 64) << c.args << "\n" << r.out;
    EXPECT_NE(r.out.find(c.message), std::string::npos) << c.args << "\n" << r.out;
    EXPECT_FALSE(fs::exists(d / "out")) << c.args << ": something was written";
  }
}

}  // namespace
