// Hostile input: what is not a regular file is refused before it is read (a FIFO would block the
// read forever, /dev/zero never ends), nesting that would overflow the TOML parser's stack is
// refused before it parses, and a --stamp that is not a file is refused before anything is baked.
// Each command runs under `timeout 20`: a hang fails as exit 124 instead of stalling the suite.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>

#include <filesystem>
#include <cstdint>
#include <fstream>
#include <vector>

#include "cli_run.h"

namespace fs = std::filesystem;
using namespace brdfbake::testing_cli;

namespace {

CmdResult runBounded(const std::string& args, const std::string& cwd) { return run(args, cwd, "timeout 20"); }

void expectRefused(const CmdResult& r, int code, const std::string& says, const std::string& what) {
  EXPECT_EQ(r.code, code) << what << "\n" << r.out;
  EXPECT_NE(r.out.find(says), std::string::npos) << what << "\n" << r.out;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << what << ": one line\n" << r.out;
}

}  // namespace

// Runs a shell script in a private mount namespace (unshare -m; needs root, as CI has), so that
// the tmpfs it mounts is seen by it alone and gone when it ends; its output and status.
CmdResult runInPrivateMounts(const fs::path& script) {
  CmdResult r{0, ""};
  FILE* p = popen(("unshare -m sh '" + script.string() + "' 2>&1").c_str(), "r");
  char buf[4096];
  for (size_t n; (n = fread(buf, 1, sizeof buf, p)) > 0;) r.out.append(buf, n);
  r.code = pclose(p);
  return r;
}

TEST(Hostile, NonRegularInputsAreRefusedBeforeTheyAreRead) {
  const fs::path d = freshDir("hostile", "inputs");
  ASSERT_EQ(::mkfifo((d / "f.exr").c_str(), 0600), 0);
  ASSERT_EQ(::mkfifo((d / "f.toml").c_str(), 0600), 0);
  ASSERT_EQ(::mkfifo((d / "f.binary").c_str(), 0600), 0);
  fs::create_symlink("/dev/zero", d / "zero.toml");
  fs::create_symlink("/dev/zero", d / "zero.gltf");
  fs::create_directory(d / "dir.toml");
  const std::string fifo = "a FIFO (named pipe), not a regular file";
  expectRefused(runBounded("info f.exr", d.string()), 66, "cannot read f.exr: " + fifo, "info FIFO");
  expectRefused(runBounded("shader --lang glsl f.exr", d.string()), 66, "cannot read f.exr: " + fifo, "shader FIFO");
  expectRefused(runBounded("plan f.toml", d.string()), 66, "cannot read scene f.toml: " + fifo, "plan FIFO");
  expectRefused(runBounded("plan zero.toml", d.string()), 66, "zero.toml: a character device, not a regular file",
                "plan /dev/zero");
  expectRefused(runBounded("bake zero.gltf", d.string()), 66, "zero.gltf: a character device", "bake glTF /dev/zero");
  expectRefused(runBounded("plan dir.toml", d.string()), 66, "dir.toml: a directory, not a regular file", "plan dir");
  expectRefused(runBounded("bake --brdf merl:f.binary -o out", d.string()), 66,
                "cannot read MERL file f.binary: " + fifo, "MERL FIFO");
  EXPECT_FALSE(fs::exists(d / "out"));
}

TEST(Hostile, DeepNestingIsRefusedBeforeTheParserRecurses) {
  const fs::path d = freshDir("hostile", "nesting");
  std::string key = "a";
  for (int i = 0; i < 50000; ++i) key += ".a";  // 100 KB, one dotted key: overflows toml++'s stack
  std::ofstream(d / "key.toml") << "# a comment\n" << key << " = 1\n";
  std::ofstream(d / "arrays.toml") << "x = " << std::string(5000, '[') << std::string(5000, ']') << "\n";
  expectRefused(runBounded("plan key.toml", d.string()), 65,
                "key.toml:2:64: the parts of a dotted key nest deeper than 32 levels", "dotted key");
  expectRefused(runBounded("bake key.toml", d.string()), 65, "key.toml:2:64:", "dotted key, bake");
  expectRefused(runBounded("plan arrays.toml", d.string()), 65,
                "arrays.toml:1:37: arrays, tables and inline tables nest deeper than 32 levels", "arrays");
  // within the limit, and dots in strings, comments and numbers: not nesting
  std::ofstream(d / "fine.toml") << "# a.b.c.d.e.f.g.h.i.j.k.l.m.n.o.p.q.r.s.t.u.v.w.x.y.z.aa.bb.cc.dd.ee.ff.gg.hh\n"
                                 << "name = \"a.b.c.d.e.f.g.h.i.j.k.l.m.n.o.p.q.r.s.t.u.v.w.x.y.z.a.b.c.d.e.f.g.h\"\n"
                                 << "[[material]]\nname = \"m\"\nndf = \"ggx\"\ngaf = \"smith-correlated\"\n"
                                 << "roughness = [0.125, 0.5]\n";
  CmdResult r = runBounded("plan fine.toml", d.string());
  EXPECT_EQ(r.out.find("nest deeper"), std::string::npos) << r.out;
}

// A glTF nested 100,000 deep (200 KB) is refused before nlohmann's parser recurses (it crashed
// `plan` while building its error message); brackets inside strings are not nesting.
TEST(Hostile, DeepJsonIsRefusedBeforeTheParserRecurses) {
  const fs::path d = freshDir("hostile", "json");
  std::ofstream(d / "deep.gltf") << R"({"asset":{"version":"2.0"},"materials":[{"name":)" << std::string(100000, '[')
                                 << std::string(100000, ']') << "}]}";
  expectRefused(runBounded("plan deep.gltf", d.string()), 65,
                "deep.gltf: byte 109: arrays and objects nest deeper than 64 levels", "deep glTF");
  std::ofstream(d / "strings.gltf") << R"({"asset":{"version":"2.0"},"materials":[{"name":")" << std::string(1000, '[')
                                    << R"("}]})";
  CmdResult r = runBounded("plan strings.gltf", d.string());
  EXPECT_EQ(r.code, 0) << r.out;
}

// Planning is linear in the materials: 4 times the glTF materials take less than 8 times the CPU
// time (a search of every table's reasons made it quadratic: 25k / 100k materials 0.9 / 40 s).
TEST(Hostile, PlanningIsLinearInTheMaterials) {
  const fs::path d = freshDir("hostile", "linear");
  auto scene = [&](int n) {
    const fs::path p = d / ("m" + std::to_string(n) + ".gltf");
    std::ofstream f(p);
    f << R"({"asset":{"version":"2.0"},"materials":[)";
    for (int i = 0; i < n; ++i)
      f << (i ? "," : "") << R"({"name":"m)" << i << R"(","pbrMetallicRoughness":{"roughnessFactor":)"
        << (i % 97) / 97.0 << "}}";
    f << "]}";
    return p.filename().string();
  };
  auto cpu = [&](const std::string& file) {
    struct rusage before {
    }, after{};
    ::getrusage(RUSAGE_CHILDREN, &before);
    CmdResult r = run("plan " + file + " -o out", d.string());
    ::getrusage(RUSAGE_CHILDREN, &after);
    EXPECT_EQ(r.code, 0) << r.out.substr(0, 2000);
    auto sec = [](const timeval& t) { return t.tv_sec + t.tv_usec * 1e-6; };
    return sec(after.ru_utime) + sec(after.ru_stime) - sec(before.ru_utime) - sec(before.ru_stime);
  };
  const std::string small = scene(25000), big = scene(100000);
  const double a = cpu(small), b = cpu(big);
  EXPECT_LT(b, 8 * std::max(a, 0.05)) << "25,000 materials " << a << " s, 100,000 materials " << b << " s of CPU";
}

// More tables than one set can hold are refused when the bake is planned, before any is computed,
// naming files and the --shard that splits them; `plan` says so too.
TEST(Hostile, TooManyFilesAreRefusedAtPlanning) {
  const fs::path d = freshDir("hostile", "files");
  std::ofstream f(d / "many.toml");
  f << "[scene]\nname = \"many\"\n[output.size]\nalbedo = 4\n";
  for (int i = 0; i < 600; ++i)
    f << "[[material]]\nname = \"w" << i << "\"\nfresnel = \"dielectric\"\neta = " << 1.1 + i * 0.001 << "\n";
  f.close();
  expectRefused(
      runBounded("bake many.toml -o out", d.string()), 64,
      "too many files for one set: 600 tables write at least as many files, and at most 511 land together; bake "
      "the scene in 2 parts: --shard 1/2 ... --shard 2/2",
      "600 tables");
  EXPECT_FALSE(fs::exists(d / "out"));
  CmdResult r = runBounded("plan many.toml -o out", d.string());
  EXPECT_NE(r.out.find("note: 600 tables to bake write more files than one set holds (511): bake them in 2 parts"),
            std::string::npos)
      << r.out.substr(0, 1000);
  r = runBounded("bake many.toml -o out --shard 1/2", d.string());
  EXPECT_EQ(r.code, 0) << r.out.substr(r.out.size() > 2000 ? r.out.size() - 2000 : 0);
}

TEST(Hostile, StampThatIsNotAFileIsRefusedBeforeBaking) {
  const fs::path d = freshDir("hostile", "stamp");
  fs::copy_file(fs::path(BRDFBAKE_SOURCE_DIR) / "examples/scenes/pbr-desktop.toml", d / "s.toml");
  ASSERT_EQ(::mkfifo((d / "stamp").c_str(), 0600), 0);
  fs::create_directory(d / "stampdir");
  expectRefused(runBounded("bake s.toml -o out --stamp stamp", d.string()), 73,
                "--stamp stamp: a FIFO (named pipe), not a regular file", "stamp FIFO");
  expectRefused(runBounded("bake s.toml -o out --stamp stampdir", d.string()), 73, "--stamp stampdir: a directory",
                "stamp dir");
  EXPECT_FALSE(fs::exists(d / "out")) << "baked before the stamp was checked";
  struct stat st {};
  ASSERT_EQ(::lstat((d / "stamp").c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode)) << "the FIFO was replaced";
}

// `brdfbake ARGS` run in `cwd` with its standard output sent to `out` (a shell redirection target);
// returns the exit status and standard error.
CmdResult runStdoutTo(const std::string& args, const std::string& cwd, const std::string& out,
                      const std::string& pre = "") {
  const std::string cmd = "cd '" + cwd + "' && " + pre + "'" BRDFBAKE_EXE "' " + args + " 2>&1 >" + out;
  FILE* p = popen(cmd.c_str(), "r");
  std::string text;
  char buf[4096];
  for (size_t n; (n = fread(buf, 1, sizeof buf, p)) > 0;) text.append(buf, n);
  const int status = pclose(p);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text};
}

// Output that does not land is an I/O error: standard output on a full disk (/dev/full) after info,
// shader, plan and help printed their result; a bake past `ulimit -f` (EFBIG, where SIGXFSZ had
// killed it silently, leaving its temporaries and lock): 74, said, nothing left behind.
TEST(Hostile, OutputThatDoesNotLandIs74) {
  const fs::path d = freshDir("hostile", "stdout");
  ASSERT_EQ(runBounded("bake --table kp -o t", d.string()).code, 0);
  fs::copy_file(fs::path(BRDFBAKE_SOURCE_DIR) / "examples/scenes/pbr-desktop.toml", d / "s.toml");
  for (const std::string& args : {std::string("info t/kp_ggx.exr"), std::string("shader --lang glsl t/kp_ggx.exr"),
                                  std::string("plan s.toml -o out"), std::string("--help")}) {
    CmdResult r = runStdoutTo(args, d.string(), "/dev/full");
    EXPECT_EQ(r.code, 74) << args << "\n" << r.out;
    EXPECT_NE(r.out.find("brdfbake: cannot write standard output: No space left on device"), std::string::npos)
        << args << "\n"
        << r.out;
  }
  CmdResult r = runStdoutTo("bake --table splitsum --size 128 -o big", d.string(), "/dev/null", "ulimit -f 50; ");
  EXPECT_EQ(r.code, 74) << r.out;
  EXPECT_NE(r.out.find("File too large; nothing was written"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(d / "big")) << "a directory the bake created stays behind";
  fs::create_directory(d / "kept");
  r = runStdoutTo("bake --table splitsum --size 128 -o kept", d.string(), "/dev/null", "ulimit -f 50; ");
  EXPECT_EQ(r.code, 74) << r.out;
  EXPECT_TRUE(fs::is_empty(d / "kept")) << "temporaries or the lock's holder line left";
}

// Codes and words true to what happened: `-o` a dangling link is 73 and said (it had been 70
// "internal"); a 250-character file name works for `shader -o` (its temporary's name is cut to
// fit); a KTX2 with a NaN texel is called damaged, not a model borrowing a Lambda; an
// OCL_ICD_VENDORS that hides every driver is named.
TEST(Hostile, CodesAndWordsAreTrue) {
  const fs::path d = freshDir("hostile", "words");
  fs::create_symlink(d / "nowhere" / "x", d / "dangling");
  expectRefused(runBounded("bake --table kp -o dangling", d.string()), 73,
                "-o: 'dangling' is a symbolic link to nothing (a dangling link)", "dangling -o");
  ASSERT_EQ(runBounded("bake --table kp --format exr,ktx2 -o t", d.string()).code, 0);
  const std::string longName = std::string(245, 'a') + ".glsl";
  CmdResult r = runBounded("shader --lang glsl t/kp_ggx.exr -o " + longName, d.string());
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_TRUE(fs::exists(d / longName));
  std::string ktx2 = bytes(d / "t/kp_ggx.ktx2");
  uint64_t level = 0;
  for (int k = 0; k < 8; ++k) level |= static_cast<uint64_t>(static_cast<unsigned char>(ktx2[80 + k])) << (8 * k);
  const uint32_t nan = 0x7fc00000u;
  for (int k = 0; k < 4; ++k) ktx2[level + k] = static_cast<char>(nan >> (8 * k));
  std::ofstream(d / "nan.ktx2", std::ios::binary) << ktx2;
  r = runBounded("info nan.ktx2", d.string());
  EXPECT_NE(r.out.find("warning: 1 texel value(s) are not finite (NaN or Inf): brdfbake never writes one"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("borrowed"), std::string::npos) << r.out;
  fs::create_directory(d / "icd");
  r = run("bake --table kp -o v", d.string(), "OCL_ICD_VENDORS='" + (d / "icd").string() + "'");
  EXPECT_EQ(r.code, 69) << r.out;
  EXPECT_NE(
      r.out.find("no OpenCL platform found: OCL_ICD_VENDORS=" + (d / "icd").string() + " names no loadable driver"),
      std::string::npos)
      << r.out;
}

// A command never replaces what it reads: `--stamp` naming the scene and `shader -o` naming one of
// its tables are refused (73) before anything is baked or generated, and the input is unchanged.
TEST(Hostile, AnOutputThatIsAnInputIsRefused) {
  const fs::path d = freshDir("hostile", "inout");
  fs::copy_file(fs::path(BRDFBAKE_SOURCE_DIR) / "examples/scenes/pbr-desktop.toml", d / "s.toml");
  const std::string manifest = bytes(d / "s.toml");
  expectRefused(runBounded("bake s.toml -o out --stamp s.toml", d.string()), 73,
                "--stamp s.toml: is an input of this command; it would be replaced by its output", "stamp = scene");
  expectRefused(runBounded("bake s.toml -o out --stamp ./s.toml", d.string()), 73,
                "--stamp ./s.toml: is the same file as s.toml, an input of this command",
                "stamp = scene, spelt otherwise");
  EXPECT_EQ(bytes(d / "s.toml"), manifest);
  EXPECT_FALSE(fs::exists(d / "out")) << "baked before the stamp was checked";
  ASSERT_EQ(runBounded("bake --table kp -o t", d.string()).code, 0);
  const std::string table = bytes(d / "t/kp_ggx.exr");
  expectRefused(runBounded("shader --lang glsl -o t/kp_ggx.exr t/kp_ggx.exr", d.string()), 73,
                "-o t/kp_ggx.exr: is an input of this command", "shader over its input");
  EXPECT_EQ(bytes(d / "t/kp_ggx.exr"), table);
  // a stamp inside the output directory, with --prune holding that directory's lock: written after
  // the lock is let go (the stamp's writer takes it too), not a wait on itself
  CmdResult r = runBounded("bake s.toml -o out --prune --stamp out/stamp.txt", d.string());
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_NE(bytes(d / "out/stamp.txt").find("the tables of the last successful bake"), std::string::npos);
  fs::create_directory(d / "adir");
  expectRefused(runBounded("shader --lang glsl -o adir t/kp_ggx.exr", d.string()), 73, "-o adir: a directory",
                "shader -o a directory");
}

// The device layer says what is wrong: --cache-dir is made absolute before PoCL sees it (PoCL
// passes it to its linker, which took "-1/..." for an option and aborted), and a cache that
// cannot be written is named as such, not as a missing OpenCL platform.
TEST(Hostile, CacheDirIsCheckedAndNamed) {
  const fs::path d = freshDir("hostile", "cache");
  CmdResult r = runBounded("--table kp --size 4 --cache-dir -1 -o out", d.string());
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_TRUE(fs::is_directory(d / "-1")) << "the cache is where it was asked to be";
  std::ofstream(d / "file") << "x";
  expectRefused(runBounded("--table kp --cache-dir file -o out2", d.string()), 73,
                "--cache-dir file: '" + (d / "file").string() + "' is not a directory", "cache dir is a file");
  expectRefused(runBounded("--table kp --cache-dir /proc/brdfbake -o out2", d.string()), 73,
                "--cache-dir /proc/brdfbake: '/proc/brdfbake' is in /proc, a kernel file system", "cache in /proc");
  EXPECT_FALSE(fs::exists(d / "out2"));
  // PoCL's own cache location unwritable ($POCL_CACHE_DIR in /proc): named, exit 73, not 69
  r = run("--table kp --size 4 -o out3", d.string(), "timeout 20 env POCL_CACHE_DIR=/proc/brdfbake-cache");
  EXPECT_EQ(r.code, 73) << r.out;
  EXPECT_NE(r.out.find("PoCL's kernel cache /proc/brdfbake-cache cannot be written"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("install an OpenCL driver"), std::string::npos) << r.out;
}

// A MERL file that measures (almost) nothing is refused, not baked into zero tables with a tiny
// claimed error; a measured one's share is in the tables' metadata.
TEST(Hostile, MerlFileWithoutMeasurementsIsRefused) {
  const fs::path d = freshDir("hostile", "merl");
  {
    std::ofstream f(d / "empty.binary", std::ios::binary);
    const int32_t dims[3] = {90, 90, 180};
    f.write(reinterpret_cast<const char*>(dims), sizeof dims);
    const std::vector<double> unmeasured(90 * 90 * 180, -1.0);
    for (int c = 0; c < 3; ++c) f.write(reinterpret_cast<const char*>(unmeasured.data()), unmeasured.size() * 8);
  }
  expectRefused(runBounded("bake --brdf merl:empty.binary -o out", d.string()), 65,
                "MERL file empty.binary: channel R measures 0 of the", "all bins unmeasured");
  EXPECT_FALSE(fs::exists(d / "out"));
  // an analytic material in MERL's layout measures every lit bin, and its tables say so
  ASSERT_EQ(runBounded("bake --table brdf3d --format merl -o m", d.string()).code, 0);
  CmdResult r = run("bake --brdf merl:m/brdf3d_ggx_smith-correlated.binary --table albedo --size 2 -o out", d.string());
  ASSERT_EQ(r.code, 0) << r.out;
  r = run("info out/albedo_merl-brdf3d_ggx_smith-correlated.exr", d.string());
  EXPECT_NE(r.out.find("brdf.merl.measured (string): R 1, G 1, B 1"), std::string::npos) << r.out;
}

// Errors name the option as it was spelt.
TEST(Hostile, ErrorsNameTheOptionAsSpelt) {
  expectRefused(run("devices -o x"), 64, "-o: not a devices option", "devices -o");
  expectRefused(run("devices --output x"), 64, "--output: not a devices option", "devices --output");
}

// Presets never overwrite each other: each preset's file carries its name; info names the preset;
// the DDS preset writes the KTX2 twin that shader reads its layout from.
TEST(Hostile, LayoutPresetsNeverOverwriteEachOther) {
  const fs::path d = freshDir("hostile", "presets");
  ASSERT_EQ(run("--layout filament --size 8 -o o", d.string()).code, 0);
  ASSERT_EQ(run("--layout bevy --size 8 -o o", d.string()).code, 0);
  ASSERT_EQ(run("--layout unreal --size 8 -o o", d.string()).code, 0);
  for (const char* f : {"splitsum_ggx_smith-correlated_filament.ktx2", "splitsum_ggx_smith-correlated_bevy.ktx2",
                        "splitsum_ggx_smith-correlated_unreal.dds", "splitsum_ggx_smith-correlated_unreal.ktx2"})
    EXPECT_TRUE(fs::exists(d / "o" / f)) << f;
  CmdResult r = run("info o/splitsum_ggx_smith-correlated_filament.ktx2", d.string());
  EXPECT_NE(r.out.find("brdf.layout (text): filament"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("brdf.layout.sampling (text): google/filament"), std::string::npos) << r.out;
  r = run("shader --lang glsl o/splitsum_ggx_smith-correlated_unreal.dds", d.string());
  EXPECT_EQ(r.code, 0) << r.out;
}

// No inodes left: the commit's temporaries cannot be created; that is a full file system (74, a
// write error), not "cannot create" (73). A tmpfs of 5 inodes (its root, -o, the lock's holder
// line and two files), mounted in a private mount namespace (needs root, as CI has).
TEST(Hostile, NoInodesLeftIsAWriteError) {
  const fs::path d = freshDir("hostile", "inodes");
  fs::create_directories(d / "disk");
  const std::string disk = (d / "disk").string();
  std::ofstream(d / "t.sh") << "set -u\n"
                               "mount -t tmpfs -o size=10m,nr_inodes=5 tmpfs '"
                            << disk
                            << "' || { echo 'cannot mount a tmpfs (root needed)'; exit 99; }\n"
                               "'" BRDFBAKE_EXE "' --table kp,albedo,albedo-avg,splitsum --size 4 -o '"
                            << disk
                            << "/out'; echo \"rc=$?\"\n"
                               "ls -A '"
                            << disk << "/out' 2>/dev/null | wc -l\n";
  const CmdResult r = runInPrivateMounts(d / "t.sh");
  ASSERT_EQ(r.out.find("cannot mount"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("rc=74"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("No space left on device"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("nothing was written"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\n0\n"), std::string::npos) << "the failed bake left files behind: " << r.out;
}

// The OpenCL driver's own failures in its kernel cache, said in our words with our codes, never a
// raw abort (134), segfault (139) or LLVM's exit(1). Program caches off, so that PoCL builds; a
// tmpfs in a private mount namespace (needs root, as CI has).
//  - 1200 KiB free (a build needs about 2 MB): refused before the driver starts, 74;
//  - the same with the check lowered (the disk fills during the build): LLVM's exit(1) becomes 74;
//  - the cache removed again and again while the kernels are linked (from the moment the program's
//    bitcode appears): PoCL's abort becomes 73 (5 runs of 5 aborted; a build that fails instead is
//    73, or 70 if the directory is back, with the hint).
TEST(Hostile, TheDriversOwnFailuresAreSaid) {
  const fs::path d = freshDir("hostile", "driver");
  fs::create_directories(d / "disk");
  const std::string disk = (d / "disk").string(), dir = d.string();
  std::ofstream(d / "t.sh")
      << "set -u\nexport BRDFBAKE_PROGRAM_CACHE=off BRDFBAKE_PREPARED_PROGRAMS=off\n"
         "mount -t tmpfs -o size=1200k tmpfs '"
      << disk
      << "' || { echo 'cannot mount a tmpfs (root needed)'; exit 99; }\n"
         "POCL_CACHE_DIR='"
      << disk << "' '" BRDFBAKE_EXE "' --table kp --size 4 -o '" << dir
      << "/o1'; echo \"rc1=$?\"\n"
         "POCL_CACHE_DIR='"
      << disk << "' BRDFBAKE_TEST_DRIVER_MIN_FREE=0 '" BRDFBAKE_EXE "' --table kp --size 4 -o '" << dir
      << "/o2'; echo \"rc2=$?\"\n"
         "rm -rf '"
      << dir
      << "/cache'\n"
         "POCL_CACHE_DIR='"
      << dir << "/cache' '" BRDFBAKE_EXE "' --table albedo --size 4 -o '" << dir
      << "/o3' & pid=$!\n"
         "i=0; until ls '"
      << dir
      << "'/cache/*/*/program.bc >/dev/null 2>&1 || [ $i -ge 1000 ]; do sleep 0.02; i=$((i+1)); done\n"
         "while kill -0 $pid 2>/dev/null; do rm -rf '"
      << dir
      << "/cache'; sleep 0.01; done\n"
         "wait $pid; echo \"rc3=$?\"\n"
         "ls -A '"
      << dir << "' | grep -c '^o[123]$'\n";
  const CmdResult r = runInPrivateMounts(d / "t.sh");
  ASSERT_EQ(r.out.find("cannot mount"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("rc1=74"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("kernel cache '" + disk + "' has "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("building the kernels needs up to 16 MiB there"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("rc2=74"), std::string::npos) << r.out;
  EXPECT_NE(
      r.out.find("the OpenCL driver ended the process while it built or ran kernels from its cache '" + disk + "'"),
      std::string::npos)
      << r.out;
  EXPECT_TRUE(r.out.find("rc3=73") != std::string::npos || r.out.find("rc3=70") != std::string::npos) << r.out;
  const bool crashSaid =
      r.out.find("the OpenCL driver crashed (SIGABRT) while it built or ran kernels from its cache '" + dir +
                 "/cache'") != std::string::npos;
  const bool buildSaid =
      r.out.find("on PoCL this is its kernel cache '" + dir + "/cache' removed") != std::string::npos;
  EXPECT_TRUE(crashSaid || buildSaid) << r.out;
  if (crashSaid) {
    EXPECT_NE(r.out.find("rc3=73"), std::string::npos) << r.out;
  }
  // nothing landed: the failures came before any table was written
  EXPECT_NE(r.out.find("\n0\n"), std::string::npos) << r.out;
}

// `--prune` where nothing can be removed (a tmpfs remounted read-only, which stops root too): 73
// naming the file and how many were removed before it (none); nothing is listed as removed, and
// the file stays.
TEST(Hostile, PruneOnAReadOnlyFileSystemListsOnlyWhatItRemoved) {
  const fs::path d = freshDir("hostile", "prune_ro");
  fs::create_directories(d / "disk");
  const std::string disk = (d / "disk").string();
  std::ofstream(d / "t.sh") << "set -u\n"
                               "mount -t tmpfs -o size=20m tmpfs '"
                            << disk
                            << "' || { echo 'cannot mount a tmpfs (root needed)'; exit 99; }\n"
                               "cp '" BRDFBAKE_SOURCE_DIR "/examples/scenes/pbr-desktop.toml' '"
                            << disk
                            << "/s.toml'\n"
                               "'" BRDFBAKE_EXE "' bake '"
                            << disk << "/s.toml' -o '" << disk
                            << "/out' > /dev/null || exit 98\n"
                               "sed -i 's/fresnel = \"dielectric\"/fresnel = \"schlick\"/; s/eta = 1.33/f0 = 0.02/' '"
                            << disk
                            << "/s.toml'\n"
                               "mount -o remount,ro '"
                            << disk
                            << "' || exit 97\n"
                               "'" BRDFBAKE_EXE "' bake '"
                            << disk << "/s.toml' -o '" << disk
                            << "/out' --prune; echo \"rc=$?\"\n"
                               "ls '"
                            << disk << "/out'\n";
  const CmdResult r = runInPrivateMounts(d / "t.sh");
  ASSERT_EQ(r.out.find("cannot mount"), std::string::npos) << r.out;
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("rc=73"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("--prune: cannot remove " + disk +
                       "/out/albedo_ggx_smith-correlated_dielectric-eta1.33.exr (0 of 1 "
                       "removed before it): Read-only file system"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("removed, no longer needed"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\nalbedo_ggx_smith-correlated_dielectric-eta1.33.exr\n"), std::string::npos) << r.out;
}
