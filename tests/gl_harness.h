// What the GL tests share (gl_test.cpp, gl_formats_test.cpp, gl_presets_test.cpp): a headless
// OpenGL ES 3.1 context through EGL on Mesa's software rasteriser (llvmpipe), a texture uploaded
// in a chosen internal format, a compute shader around generated lookup code that evaluates an
// expression at thousands of points and reads the results back, and the host's bilinear lookup
// the results are compared with. No EGL or no GLES 3.1: the tests fail (CI installs Mesa's EGL).
#pragma once
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES3/gl31.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace glharness {

struct Gl {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
  std::string problem;
  bool norm16 = false;  // GL_EXT_texture_norm16: RGBA16 (unorm) textures, filterable
  Gl() {
    auto getDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!getDisplay) {
      problem = "no eglGetPlatformDisplayEXT";
      return;
    }
    display = getDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    EGLint major = 0, minor = 0;
    if (display == EGL_NO_DISPLAY || !eglInitialize(display, &major, &minor)) {
      problem = "no EGL surfaceless display (install libegl-mesa0 and libgl1-mesa-dri)";
      return;
    }
    eglBindAPI(EGL_OPENGL_ES_API);
    EGLint cfgAttr[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES3_BIT, EGL_NONE};
    EGLConfig cfg = nullptr;
    EGLint n = 0;
    eglChooseConfig(display, cfgAttr, &cfg, 1, &n);
    EGLint ctxAttr[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 1, EGL_NONE};
    context = eglCreateContext(display, n ? cfg : EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, ctxAttr);
    if (context == EGL_NO_CONTEXT || !eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
      problem = "no OpenGL ES 3.1 context";
      return;
    }
    const char* ext = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
    if (!ext || !std::strstr(ext, "GL_OES_texture_float_linear")) problem = "no GL_OES_texture_float_linear";
    norm16 = ext && std::strstr(ext, "GL_EXT_texture_norm16");
  }
};
inline Gl& gl() {
  static Gl g;
  return g;
}

// GL_EXT_texture_norm16's sized internal format (the extension's enumerant value).
constexpr GLenum kRgba16Ext = 0x805B;

// Compiles `src` as a compute shader; the build log on failure.
inline GLuint program(const std::string& src, std::string* log) {
  GLuint sh = glCreateShader(GL_COMPUTE_SHADER);
  const char* p = src.c_str();
  glShaderSource(sh, 1, &p, nullptr);
  glCompileShader(sh);
  GLint ok = 0;
  glGetShaderiv(sh, GL_COMPILE_STATUS, &ok);
  char buf[8192];
  if (!ok) {
    glGetShaderInfoLog(sh, sizeof buf, nullptr, buf);
    *log = buf;
    return 0;
  }
  GLuint prog = glCreateProgram();
  glAttachShader(prog, sh);
  glLinkProgram(prog);
  glGetProgramiv(prog, GL_LINK_STATUS, &ok);
  if (!ok) {
    glGetProgramInfoLog(prog, sizeof buf, nullptr, buf);
    *log = buf;
    return 0;
  }
  return prog;
}

// A 2D texture's texels as uploaded: RGBA rows (row 0 first), in `type` (GL_FLOAT, GL_HALF_FLOAT,
// GL_UNSIGNED_SHORT, GL_UNSIGNED_BYTE) for the sized `internalFormat`.
struct Texels {
  int width = 0, height = 0;
  GLenum internalFormat = GL_RGBA32F, type = GL_FLOAT;
  std::vector<unsigned char> bytes;
  template <typename T>
  void assign(const std::vector<T>& v) {
    bytes.resize(v.size() * sizeof(T));
    std::memcpy(bytes.data(), v.data(), bytes.size());
  }
};

// Runs `body` (GLSL statements that read `vec4 p` and `sampler2D tab` and write `res[k * i + j]`
// for j < k = outPerPoint) after `decls` at each point of `points` (4 floats each) with `tex`
// bound as `tab` (linear, clamp to edge); the results, outPerPoint vec4 per point. Empty (and a
// test failure naming the log) when the shader does not compile.
inline std::vector<float> runOnGpu(const std::string& decls, const std::string& body, const Texels& tex,
                                   const std::vector<float>& points, int outPerPoint) {
  std::string src =
      "#version 310 es\nprecision highp float;\nprecision highp int;\nprecision highp sampler2D;\n" + decls +
      "layout(local_size_x = 64) in;\n"
      "layout(std430, binding = 0) readonly buffer In { vec4 pts[]; };\n"
      "layout(std430, binding = 1) writeonly buffer Out { vec4 res[]; };\n"
      "uniform sampler2D tab;\nuniform int count;\n"
      "void main() {\n  int i = int(gl_GlobalInvocationID.x);\n  if (i >= count) return;\n  vec4 p = pts[i];\n" +
      body + "}\n";
  std::string log;
  GLuint prog = program(src, &log);
  EXPECT_NE(prog, 0u) << "GLSL does not compile:\n" << log << "\n" << src;
  if (!prog) return {};
  GLuint t;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexStorage2D(GL_TEXTURE_2D, 1, tex.internalFormat, tex.width, tex.height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, tex.width, tex.height, GL_RGBA, tex.type, tex.bytes.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR))
      << "upload, internal format 0x" << std::hex << tex.internalFormat;
  int n = static_cast<int>(points.size() / 4);
  GLuint buf[2];
  glGenBuffers(2, buf);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buf[0]);
  glBufferData(GL_SHADER_STORAGE_BUFFER, points.size() * sizeof(float), points.data(), GL_STATIC_DRAW);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, buf[1]);
  const size_t outFloats = static_cast<size_t>(n) * 4 * outPerPoint;
  glBufferData(GL_SHADER_STORAGE_BUFFER, outFloats * sizeof(float), nullptr, GL_DYNAMIC_READ);
  glUseProgram(prog);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, t);
  glUniform1i(glGetUniformLocation(prog, "tab"), 0);
  glUniform1i(glGetUniformLocation(prog, "count"), n);
  glDispatchCompute((n + 63) / 64, 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<float> out(outFloats);
  const void* mapped = glMapBufferRange(GL_SHADER_STORAGE_BUFFER, 0, out.size() * sizeof(float), GL_MAP_READ_BIT);
  EXPECT_NE(mapped, nullptr);
  if (mapped) std::memcpy(out.data(), mapped, out.size() * sizeof(float));
  glUnmapBuffer(GL_SHADER_STORAGE_BUFFER);
  glDeleteBuffers(2, buf);
  glDeleteTextures(1, &t);
  glDeleteProgram(prog);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  return out;
}

// Texels as planes (planes[c][y * width + x]) -> the host's bilinear lookup of channel c at
// fractional texel (px, py) (texel i's centre at i), clamped; with `bits` > 0 the weights are
// rounded to that many fractional bits (8: NVIDIA's filter).
inline double bilinear(const std::vector<std::vector<float>>& planes, int width, int height, int c, double px,
                       double py, int bits = 0) {
  px = std::clamp(px, 0.0, width - 1.0);
  py = std::clamp(py, 0.0, height - 1.0);
  int x0 = std::min(static_cast<int>(px), std::max(width - 2, 0)),
      y0 = std::min(static_cast<int>(py), std::max(height - 2, 0));
  double fx = width > 1 ? px - x0 : 0, fy = height > 1 ? py - y0 : 0;
  if (bits > 0) {
    fx = std::round(std::ldexp(fx, bits)) / std::ldexp(1.0, bits);
    fy = std::round(std::ldexp(fy, bits)) / std::ldexp(1.0, bits);
  }
  int x1 = std::min(x0 + 1, width - 1), y1 = std::min(y0 + 1, height - 1);
  auto v = [&](int x, int y) { return static_cast<double>(planes[c][static_cast<size_t>(y) * width + x]); };
  return (1 - fy) * ((1 - fx) * v(x0, y0) + fx * v(x1, y0)) + fy * ((1 - fx) * v(x0, y1) + fx * v(x1, y1));
}

}  // namespace glharness
