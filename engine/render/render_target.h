// RenderTarget: an offscreen framebuffer to draw into (RGBA8 colour + 24-bit depth, optionally
// multisampled and resolved on read), and read_pixels for whatever framebuffer is bound for reading
// (the window's, for screenshots). Needs a current OpenGL 3.3 core context.
//
// Pixels come back as RGBA8, the top row first (as PNG files and screen coordinates have them).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec4.hpp>

#include "render/camera.h"

namespace meshedit {

class RenderTarget {
 public:
  // `samples` is clamped to what the driver offers (GL_MAX_SAMPLES); 0 or 1 means no multisampling.
  // Throws RenderError for a size outside [1, GL_MAX_RENDERBUFFER_SIZE] or an incomplete framebuffer.
  RenderTarget(int width, int height, int samples = 4);
  ~RenderTarget();
  RenderTarget(const RenderTarget&) = delete;
  RenderTarget& operator=(const RenderTarget&) = delete;

  // Binds it as the draw and read framebuffer and sets the viewport to cover it.
  void bind() const;
  // Binds it and clears colour to `colour` and depth to far.
  void clear(const glm::vec4& colour) const;
  Viewport viewport() const { return {width_, height_}; }
  int samples() const { return samples_; }
  // Resolves the samples into the single-sampled copy (what a window's buffer swap does); nothing when not
  // multisampled. Leaves the copy bound for reading.
  void resolve() const;
  // Resolves (if multisampled) and reads the colour; leaves this target bound.
  std::vector<uint8_t> read_rgba() const;

 private:
  void release();

  int width_ = 0, height_ = 0, samples_ = 0;
  unsigned framebuffer_ = 0, colour_ = 0, depth_ = 0;
  unsigned resolve_framebuffer_ = 0, resolve_colour_ = 0;  // only when multisampled
};

// RGBA8 of the framebuffer bound for reading, viewport-sized, top row first.
std::vector<uint8_t> read_pixels(Viewport viewport);

}  // namespace meshedit
