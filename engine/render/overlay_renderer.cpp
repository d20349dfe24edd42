// Overlay polylines and points (see overlay_renderer.h), through the same segment and point shaders as
// the mesh, with per-item colours and sizes instead of element state.
#include "render/overlay_renderer.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/type_ptr.hpp>

#include "render/gl_api.h"
#include "render/gpu_batches.h"

namespace meshedit {
namespace {

gl::ItemStyle item_style(const glm::vec4& colour, float size) {
  gl::ItemStyle style;
  for (int i = 0; i < 4; ++i) {
    style.rgba[i] = uint8_t(std::lround(std::clamp(colour[i], 0.0f, 1.0f) * 255.0f));
  }
  style.size = size;
  return style;
}

}  // namespace

struct OverlayRenderer::Impl {
  explicit Impl(const ShaderLibrary& shaders)
      : segment(shaders.program("segment.vert", "segment.frag")), point(shaders.program("point.vert", "point.frag")) {}

  ShaderProgram segment, point;
  gl::SegmentBatch lines;
  gl::PointBatch points;
  // Kept between draws so their memory is reused.
  std::vector<EdgeSegment> segment_items;
  std::vector<gl::ItemStyle> segment_styles, point_styles;
  std::vector<VertexPoint> point_items;
};

OverlayRenderer::OverlayRenderer(const ShaderLibrary& shaders) : impl_(std::make_unique<Impl>(shaders)) {}

OverlayRenderer::~OverlayRenderer() = default;

void OverlayRenderer::draw(const OrbitCamera& camera, Viewport viewport, const Overlay& overlay) {
  Impl& r = *impl_;
  r.segment_items.clear();
  r.segment_styles.clear();
  for (const OverlayPolyline& line : overlay.lines) {
    const size_t n = line.points.size();
    const size_t segments = n < 2 ? 0 : (line.closed && n > 2 ? n : n - 1);
    const gl::ItemStyle style = item_style(line.colour, line.width);
    for (size_t i = 0; i < segments; ++i) {
      r.segment_items.push_back({glm::vec3(line.points[i]), glm::vec3(line.points[(i + 1) % n]), 0, 0});
      r.segment_styles.push_back(style);
    }
  }
  r.point_items.clear();
  r.point_styles.clear();
  for (const OverlayPoint& p : overlay.points) {
    r.point_items.push_back({glm::vec3(p.position), 0});
    r.point_styles.push_back(item_style(p.colour, p.size));
  }
  r.lines.upload(r.segment_items.data(), r.segment_items.size(), GL_STREAM_DRAW);
  r.lines.upload_styles(r.segment_styles.data(), r.segment_styles.size(), GL_STREAM_DRAW);
  r.points.upload(r.point_items.data(), r.point_items.size(), GL_STREAM_DRAW);
  r.points.upload_styles(r.point_styles.data(), r.point_styles.size(), GL_STREAM_DRAW);

  const gl::CameraUniforms uniforms = gl::camera_uniforms(camera, viewport);
  // Colours may be translucent (a control net over the surface); the caller's blending is restored.
  const GLboolean blending = glIsEnabled(GL_BLEND);
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  if (overlay.on_top) {
    glDisable(GL_DEPTH_TEST);
  } else {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
  }
  gl::enable_program_point_size();
  r.segment.use();
  gl::set_camera(r.segment, uniforms);
  glUniform1i(r.segment.uniform("u_segments"), 1);
  glUniform1i(r.segment.uniform("u_lines"), 0);
  glUniform1i(r.segment.uniform("u_styles"), 2);
  glUniform1i(r.segment.uniform("u_element_colours"), 0);
  glUniform1f(r.segment.uniform("u_pick_width"), 0.0f);
  glUniform1f(r.segment.uniform("u_cap"), 1.0f);
  r.lines.draw();
  r.point.use();
  gl::set_camera(r.point, uniforms);
  glUniform1i(r.point.uniform("u_element_colours"), 0);
  glUniform1i(r.point.uniform("u_hide_invalid"), 0);
  glUniform1f(r.point.uniform("u_pick_size"), 0.0f);
  r.points.draw();
  glEnable(GL_DEPTH_TEST);
  if (!blending) glDisable(GL_BLEND);
  glBindVertexArray(0);
  glUseProgram(0);
}

}  // namespace meshedit
