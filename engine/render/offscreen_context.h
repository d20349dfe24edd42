// OffscreenContext: an OpenGL 3.3 core context with no window and no X server, through EGL's
// surfaceless platform (EGL_MESA_platform_surfaceless; Mesa's llvmpipe on any Linux machine). It is
// current on the calling thread from construction on; draw into a RenderTarget (render_target.h).
//
// Construction throws RenderError saying which step failed (no surfaceless platform, eglInitialize,
// no OpenGL API, no 3.3 core context...). The EGL display is process-wide and stays initialised after
// the context is destroyed (terminating it would pull it from under any other context on it).
#pragma once

#include <string>

namespace meshedit {

class OffscreenContext {
 public:
  OffscreenContext();
  ~OffscreenContext();
  OffscreenContext(const OffscreenContext&) = delete;
  OffscreenContext& operator=(const OffscreenContext&) = delete;

  void make_current();
  // GL_RENDERER and GL_VERSION, e.g. "llvmpipe (LLVM 15.0.6, 256 bits), 4.5 (Core Profile) Mesa 22.3.6".
  static std::string description();

 private:
  void* display_ = nullptr;  // EGLDisplay
  void* context_ = nullptr;  // EGLContext
};

}  // namespace meshedit
