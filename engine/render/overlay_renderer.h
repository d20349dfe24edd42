// Overlays: 3D polylines and points with a colour and size each, drawn over (or into) the mesh view.
// For the patch view's control net, its row and column curves and the probe point, and later the curve
// lesson. Needs a current OpenGL 3.3 core context. The data is uploaded on every draw(): overlays are
// small (hundreds of points), and re-sending them keeps the API a plain value.
//
// Widths and sizes are in framebuffer pixels; colours may be translucent (alpha blending). Polylines
// join smoothly (each segment is extended by half its width); `closed` adds the segment from the last
// point back to the first. With `on_top` the overlay ignores depth and shows through the mesh;
// otherwise the mesh hides what is behind it.
#pragma once

#include <memory>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "render/camera.h"
#include "render/shader_library.h"

namespace meshedit {

struct OverlayPolyline {
  std::vector<glm::dvec3> points;
  glm::vec4 colour{1.0f};
  float width = 2.0f;
  bool closed = false;
};

struct OverlayPoint {
  glm::dvec3 position{0.0};
  glm::vec4 colour{1.0f};
  float size = 8.0f;
};

struct Overlay {
  std::vector<OverlayPolyline> lines;
  std::vector<OverlayPoint> points;
  bool on_top = false;
};

class OverlayRenderer {
 public:
  // Throws RenderError if a shader is missing or does not compile.
  explicit OverlayRenderer(const ShaderLibrary& shaders);
  ~OverlayRenderer();
  OverlayRenderer(const OverlayRenderer&) = delete;
  OverlayRenderer& operator=(const OverlayRenderer&) = delete;

  // Lines first, then points over them. Leaves depth testing on, program 0 and vertex array 0 bound.
  void draw(const OrbitCamera& camera, Viewport viewport, const Overlay& overlay);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace meshedit
