// A headless OpenGL ES 3.1 context through EGL (Mesa's surfaceless platform: llvmpipe on a machine
// without a GPU), with the GL functions `brdfbake render` calls. libEGL is opened at run time
// (dlopen), so brdfbake runs where no EGL is installed and only `render` needs it: without EGL or a
// GLES 3.1 context, Error(kExitUnavailable) names the Debian packages to install.
#pragma once
#define EGL_EGL_PROTOTYPES 0
#define GL_GLES_PROTOTYPES 0
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES3/gl31.h>

#include <string>

namespace brdfbake {

struct GlFunctions {
  PFNGLGETSTRINGPROC GetString;
  PFNGLGETERRORPROC GetError;
  PFNGLCREATESHADERPROC CreateShader;
  PFNGLSHADERSOURCEPROC ShaderSource;
  PFNGLCOMPILESHADERPROC CompileShader;
  PFNGLGETSHADERIVPROC GetShaderiv;
  PFNGLGETSHADERINFOLOGPROC GetShaderInfoLog;
  PFNGLCREATEPROGRAMPROC CreateProgram;
  PFNGLATTACHSHADERPROC AttachShader;
  PFNGLLINKPROGRAMPROC LinkProgram;
  PFNGLGETPROGRAMIVPROC GetProgramiv;
  PFNGLGETPROGRAMINFOLOGPROC GetProgramInfoLog;
  PFNGLUSEPROGRAMPROC UseProgram;
  PFNGLGENTEXTURESPROC GenTextures;
  PFNGLBINDTEXTUREPROC BindTexture;
  PFNGLTEXIMAGE2DPROC TexImage2D;
  PFNGLTEXPARAMETERIPROC TexParameteri;
  PFNGLACTIVETEXTUREPROC ActiveTexture;
  PFNGLGETUNIFORMLOCATIONPROC GetUniformLocation;
  PFNGLUNIFORM1IPROC Uniform1i;
  PFNGLUNIFORM1FPROC Uniform1f;
  PFNGLGENBUFFERSPROC GenBuffers;
  PFNGLBINDBUFFERPROC BindBuffer;
  PFNGLBUFFERDATAPROC BufferData;
  PFNGLBINDBUFFERBASEPROC BindBufferBase;
  PFNGLDISPATCHCOMPUTEPROC DispatchCompute;
  PFNGLMEMORYBARRIERPROC MemoryBarrier;
  PFNGLMAPBUFFERRANGEPROC MapBufferRange;
  PFNGLUNMAPBUFFERPROC UnmapBuffer;
  PFNGLFINISHPROC Finish;
  PFNGLDELETETEXTURESPROC DeleteTextures;
  PFNGLDELETEBUFFERSPROC DeleteBuffers;
  PFNGLDELETEPROGRAMPROC DeleteProgram;
};

class GlContext {
 public:
  // Opens libEGL ($BRDFBAKE_EGL_LIBRARY, default libEGL.so.1), a surfaceless display and a GLES 3.1
  // context with float-texture filtering. Error(kExitUnavailable) naming what is missing.
  GlContext();
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;
  const GlFunctions& gl() const { return gl_; }
  std::string renderer() const;  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  // A compute shader from `source`; Error(kExitSoftware) with the full compile or link log.
  GLuint computeProgram(const std::string& source) const;

 private:
  void* lib_ = nullptr;
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
  GlFunctions gl_{};
  PFNEGLTERMINATEPROC terminate_ = nullptr;
  PFNEGLDESTROYCONTEXTPROC destroy_ = nullptr;
  PFNEGLMAKECURRENTPROC makeCurrent_ = nullptr;
};

}  // namespace brdfbake
