// Offscreen framebuffers and pixel read-back (see render_target.h).
#include "render/render_target.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include "render/gl_api.h"
#include "render/render_error.h"

namespace meshedit {
namespace {

GLuint make_renderbuffer(GLenum format, int width, int height, int samples) {
  GLuint name = 0;
  glGenRenderbuffers(1, &name);
  glBindRenderbuffer(GL_RENDERBUFFER, name);
  if (samples > 1) {
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, width, height);
  } else {
    glRenderbufferStorage(GL_RENDERBUFFER, format, width, height);
  }
  return name;
}

void check_complete(const char* what) {
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    char code[16];
    std::snprintf(code, sizeof code, "0x%04x", unsigned(status));
    throw RenderError(std::string("offscreen framebuffer (") + what + ") is incomplete: status " + code);
  }
}

}  // namespace

RenderTarget::RenderTarget(int width, int height, int samples) : width_(width), height_(height) {
  GLint max_size = 0, max_samples = 0;
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  if (width < 1 || height < 1 || width > max_size || height > max_size) {
    throw RenderError("image size " + std::to_string(width) + "x" + std::to_string(height) +
                      " is outside what this OpenGL allows (1 to " + std::to_string(max_size) + " per side)");
  }
  samples_ = std::clamp(samples, 0, int(max_samples));
  if (samples_ == 1) samples_ = 0;

  try {
    glGenFramebuffers(1, &framebuffer_);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    colour_ = make_renderbuffer(GL_RGBA8, width, height, samples_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_);
    depth_ = make_renderbuffer(GL_DEPTH_COMPONENT24, width, height, samples_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
    check_complete("draw");
    if (samples_ > 1) {
      glGenFramebuffers(1, &resolve_framebuffer_);
      glBindFramebuffer(GL_FRAMEBUFFER, resolve_framebuffer_);
      resolve_colour_ = make_renderbuffer(GL_RGBA8, width, height, 0);
      glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, resolve_colour_);
      check_complete("resolve");
    }
  } catch (...) {
    release();
    throw;
  }
  bind();
}

RenderTarget::~RenderTarget() { release(); }

void RenderTarget::release() {
  const GLuint renderbuffers[] = {colour_, depth_, resolve_colour_};
  glDeleteRenderbuffers(3, renderbuffers);  // zero names are ignored
  const GLuint framebuffers[] = {framebuffer_, resolve_framebuffer_};
  glDeleteFramebuffers(2, framebuffers);
  framebuffer_ = colour_ = depth_ = resolve_framebuffer_ = resolve_colour_ = 0;
}

void RenderTarget::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glViewport(0, 0, width_, height_);
}

void RenderTarget::clear(const glm::vec4& colour) const {
  bind();
  glDepthMask(GL_TRUE);
  glClearColor(colour.r, colour.g, colour.b, colour.a);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

void RenderTarget::resolve() const {
  if (samples_ <= 1) return;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolve_framebuffer_);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, resolve_framebuffer_);
}

std::vector<uint8_t> RenderTarget::read_rgba() const {
  if (samples_ > 1) {
    resolve();
  } else {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
  }
  std::vector<uint8_t> pixels = read_pixels(viewport());
  bind();
  return pixels;
}

std::vector<uint8_t> read_pixels(Viewport viewport) {
  const size_t width = size_t(std::max(viewport.width, 0));
  const size_t height = size_t(std::max(viewport.height, 0));
  std::vector<uint8_t> pixels(width * height * 4);
  if (pixels.empty()) return pixels;
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, GLsizei(width), GLsizei(height), GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  // OpenGL's rows start at the bottom; images and screen coordinates start at the top.
  const size_t row = width * 4;
  for (size_t y = 0; y < height / 2; ++y) {
    std::swap_ranges(pixels.begin() + long(y * row), pixels.begin() + long((y + 1) * row),
                     pixels.begin() + long((height - 1 - y) * row));
  }
  return pixels;
}

}  // namespace meshedit
