// A headless GLES 3.1 context through a run-time-opened libEGL (render/gl_context.h).
#include "render/gl_context.h"

#include <dlfcn.h>

#include <cstdlib>
#include <cstring>

#include "common/errors.h"

namespace brdfbake {

namespace {
const char* const kPackages =
    "install Mesa's EGL and GLES (Debian: apt-get install libegl1 libegl-mesa0 libgles2 "
    "libgl1-mesa-dri)";
}  // namespace

GlContext::GlContext() {
  const char* name = std::getenv("BRDFBAKE_EGL_LIBRARY");
  const std::string lib = name && *name ? name : "libEGL.so.1";
  lib_ = ::dlopen(lib.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!lib_) throw Error(kExitUnavailable, "render: no EGL library (" + lib + "): " + kPackages);
  auto getProc = reinterpret_cast<PFNEGLGETPROCADDRESSPROC>(::dlsym(lib_, "eglGetProcAddress"));
  if (!getProc) throw Error(kExitUnavailable, "render: " + lib + " has no eglGetProcAddress: " + kPackages);
  auto egl = [&](const char* f) {
    void* p = reinterpret_cast<void*>(getProc(f));
    if (!p) p = ::dlsym(lib_, f);
    if (!p) throw Error(kExitUnavailable, std::string("render: EGL lacks ") + f + ": " + kPackages);
    return p;
  };
  auto platformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(egl("eglGetPlatformDisplayEXT"));
  auto initialize = reinterpret_cast<PFNEGLINITIALIZEPROC>(egl("eglInitialize"));
  auto bindApi = reinterpret_cast<PFNEGLBINDAPIPROC>(egl("eglBindAPI"));
  auto chooseConfig = reinterpret_cast<PFNEGLCHOOSECONFIGPROC>(egl("eglChooseConfig"));
  auto createContext = reinterpret_cast<PFNEGLCREATECONTEXTPROC>(egl("eglCreateContext"));
  makeCurrent_ = reinterpret_cast<PFNEGLMAKECURRENTPROC>(egl("eglMakeCurrent"));
  terminate_ = reinterpret_cast<PFNEGLTERMINATEPROC>(egl("eglTerminate"));
  destroy_ = reinterpret_cast<PFNEGLDESTROYCONTEXTPROC>(egl("eglDestroyContext"));
  display_ = platformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  EGLint major = 0, minor = 0;
  if (display_ == EGL_NO_DISPLAY || !initialize(display_, &major, &minor))
    throw Error(kExitUnavailable, "render: no EGL surfaceless display: " + std::string(kPackages));
  bindApi(EGL_OPENGL_ES_API);
  const EGLint cfgAttr[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES3_BIT, EGL_NONE};
  EGLConfig cfg = nullptr;
  EGLint n = 0;
  chooseConfig(display_, cfgAttr, &cfg, 1, &n);
  const EGLint ctxAttr[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 1, EGL_NONE};
  context_ = createContext(display_, n ? cfg : EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, ctxAttr);
  if (context_ == EGL_NO_CONTEXT || !makeCurrent_(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
    throw Error(kExitUnavailable, "render: no OpenGL ES 3.1 context on EGL: " + std::string(kPackages));
#define BRDFBAKE_GL(f) gl_.f = reinterpret_cast<decltype(gl_.f)>(egl("gl" #f))
  BRDFBAKE_GL(GetString);
  BRDFBAKE_GL(GetError);
  BRDFBAKE_GL(CreateShader);
  BRDFBAKE_GL(ShaderSource);
  BRDFBAKE_GL(CompileShader);
  BRDFBAKE_GL(GetShaderiv);
  BRDFBAKE_GL(GetShaderInfoLog);
  BRDFBAKE_GL(CreateProgram);
  BRDFBAKE_GL(AttachShader);
  BRDFBAKE_GL(LinkProgram);
  BRDFBAKE_GL(GetProgramiv);
  BRDFBAKE_GL(GetProgramInfoLog);
  BRDFBAKE_GL(UseProgram);
  BRDFBAKE_GL(GenTextures);
  BRDFBAKE_GL(BindTexture);
  BRDFBAKE_GL(TexImage2D);
  BRDFBAKE_GL(TexParameteri);
  BRDFBAKE_GL(ActiveTexture);
  BRDFBAKE_GL(GetUniformLocation);
  BRDFBAKE_GL(Uniform1i);
  BRDFBAKE_GL(Uniform1f);
  BRDFBAKE_GL(GenBuffers);
  BRDFBAKE_GL(BindBuffer);
  BRDFBAKE_GL(BufferData);
  BRDFBAKE_GL(BindBufferBase);
  BRDFBAKE_GL(DispatchCompute);
  BRDFBAKE_GL(MemoryBarrier);
  BRDFBAKE_GL(MapBufferRange);
  BRDFBAKE_GL(UnmapBuffer);
  BRDFBAKE_GL(Finish);
  BRDFBAKE_GL(DeleteTextures);
  BRDFBAKE_GL(DeleteBuffers);
  BRDFBAKE_GL(DeleteProgram);
#undef BRDFBAKE_GL
  const char* ext = reinterpret_cast<const char*>(gl_.GetString(GL_EXTENSIONS));
  if (!ext || !std::strstr(ext, "GL_OES_texture_float_linear"))
    throw Error(kExitUnavailable,
                "render: the GLES context cannot filter float textures (no "
                "GL_OES_texture_float_linear): " +
                    std::string(kPackages));
}

GlContext::~GlContext() {
  if (display_ != EGL_NO_DISPLAY) {
    if (makeCurrent_) makeCurrent_(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (context_ != EGL_NO_CONTEXT && destroy_) destroy_(display_, context_);
    if (terminate_) terminate_(display_);
  }
  // libEGL stays loaded: Mesa's drivers register exit handlers that must still find their code
}

std::string GlContext::renderer() const {
  const char* r = reinterpret_cast<const char*>(gl_.GetString(GL_RENDERER));
  return r ? r : "unknown";
}

GLuint GlContext::computeProgram(const std::string& source) const {
  GLuint sh = gl_.CreateShader(GL_COMPUTE_SHADER);
  const char* p = source.c_str();
  gl_.ShaderSource(sh, 1, &p, nullptr);
  gl_.CompileShader(sh);
  GLint ok = 0;
  gl_.GetShaderiv(sh, GL_COMPILE_STATUS, &ok);
  std::string log(16384, '\0');
  if (!ok) {
    gl_.GetShaderInfoLog(sh, static_cast<GLsizei>(log.size()), nullptr, &log[0]);
    throw Error(kExitSoftware, "render: the furnace shader did not compile; log:\n" + std::string(log.c_str()));
  }
  GLuint prog = gl_.CreateProgram();
  gl_.AttachShader(prog, sh);
  gl_.LinkProgram(prog);
  gl_.GetProgramiv(prog, GL_LINK_STATUS, &ok);
  if (!ok) {
    gl_.GetProgramInfoLog(prog, static_cast<GLsizei>(log.size()), nullptr, &log[0]);
    throw Error(kExitSoftware, "render: the furnace shader did not link; log:\n" + std::string(log.c_str()));
  }
  return prog;
}

}  // namespace brdfbake
