// The surfaceless EGL context (see offscreen_context.h; desktop build only). libepoxy resolves both the EGL entry
// points and, once the context is current, the GL ones, so the same renderer code runs under GLFW and here.
#include "render/offscreen_context.h"

#include <cstdio>

#include <epoxy/egl.h>

#include "render/gl_api.h"
#include "render/render_error.h"

namespace meshedit {
namespace {

std::string egl_error() {
  const EGLint code = eglGetError();
  switch (code) {
    case EGL_SUCCESS: return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE: return "EGL_BAD_SURFACE";
    default: break;
  }
  char text[32];
  std::snprintf(text, sizeof text, "EGL error 0x%04x", unsigned(code));
  return text;
}

[[noreturn]] void fail(const std::string& what) {
  throw RenderError("cannot create an offscreen OpenGL context: " + what);
}

}  // namespace

OffscreenContext::OffscreenContext() {
  if (!epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless")) {
    fail("EGL has no surfaceless platform (EGL_MESA_platform_surfaceless; install Mesa's libEGL)");
  }
  EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display == EGL_NO_DISPLAY) fail("no surfaceless EGL display (" + egl_error() + ")");
  EGLint major = 0, minor = 0;
  if (!eglInitialize(display, &major, &minor)) fail("eglInitialize failed (" + egl_error() + ")");
  if (!epoxy_has_egl_extension(display, "EGL_KHR_surfaceless_context")) {
    fail("the EGL display lacks EGL_KHR_surfaceless_context");
  }
  if (!eglBindAPI(EGL_OPENGL_API)) fail("EGL offers no desktop OpenGL (" + egl_error() + ")");

  EGLConfig config = EGL_NO_CONFIG_KHR;
  if (!epoxy_has_egl_extension(display, "EGL_KHR_no_config_context")) {
    const EGLint wanted[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, 0, EGL_NONE};
    EGLint count = 0;
    if (!eglChooseConfig(display, wanted, &config, 1, &count) || count < 1) {
      fail("no EGL config renders desktop OpenGL (" + egl_error() + ")");
    }
  }
  const EGLint attributes[] = {
      EGL_CONTEXT_MAJOR_VERSION,           3,       EGL_CONTEXT_MINOR_VERSION, 3, EGL_CONTEXT_OPENGL_PROFILE_MASK,
      EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, attributes);
  if (context == EGL_NO_CONTEXT) fail("no OpenGL 3.3 core context (" + egl_error() + ")");
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
    const std::string why = egl_error();
    eglDestroyContext(display, context);
    fail("eglMakeCurrent failed (" + why + ")");
  }
  display_ = display;
  context_ = context;
}

OffscreenContext::~OffscreenContext() {
  auto* display = static_cast<EGLDisplay>(display_);
  auto* context = static_cast<EGLContext>(context_);
  if (eglGetCurrentContext() == context) eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display, context);
}

void OffscreenContext::make_current() {
  if (!eglMakeCurrent(static_cast<EGLDisplay>(display_), EGL_NO_SURFACE, EGL_NO_SURFACE,
                      static_cast<EGLContext>(context_))) {
    throw RenderError("cannot make the offscreen OpenGL context current (" + egl_error() + ")");
  }
}

std::string OffscreenContext::description() {
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  return std::string(renderer ? renderer : "?") + ", " + (version ? version : "?");
}

}  // namespace meshedit
