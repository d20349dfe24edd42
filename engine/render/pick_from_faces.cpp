// pick_from_faces (see pick_from_faces.h for the rule).
#include "render/pick_from_faces.h"

#include <algorithm>
#include <optional>
#include <vector>

#include <glm/geometric.hpp>

#include "render/mesh_geometry.h"
#include "render/pick_id.h"
#include "render/slot_geometry.h"

namespace meshedit {
namespace {

// The nearest candidate of one kind so far: squared distance, then the lower id.
struct Best {
  ElementRef element;
  double distance_sq = 0.0;

  void offer(ElementRef candidate, double d_sq) {
    if (!element.valid() || d_sq < distance_sq || (d_sq == distance_sq && candidate.index < element.index)) {
      element = candidate;
      distance_sq = d_sq;
    }
  }
};

class Screen {
 public:
  Screen(const OrbitCamera& camera, Viewport viewport, int x, int y)
      : camera_(camera), viewport_(viewport), cursor_(x + 0.5, y + 0.5) {}

  // Squared distance from the cursor to p on the screen, if p is in front of the eye.
  std::optional<double> to_point(const glm::vec3& p) const {
    const ScreenPoint s = camera_.project(glm::dvec3(p), viewport_);
    if (!s.in_front) return std::nullopt;
    const glm::dvec2 d = s.pixel - cursor_;
    return glm::dot(d, d);
  }

  // Squared distance from the cursor to the segment's image, if both ends are in front of the eye.
  std::optional<double> to_segment(const EdgeSegment& segment) const {
    if ((segment.flags & kEdgeHiddenFlag) != 0) return std::nullopt;
    const ScreenPoint a = camera_.project(glm::dvec3(segment.start), viewport_);
    const ScreenPoint b = camera_.project(glm::dvec3(segment.end), viewport_);
    if (!a.in_front || !b.in_front) return std::nullopt;
    const glm::dvec2 ab = b.pixel - a.pixel, ac = cursor_ - a.pixel;
    const double length_sq = glm::dot(ab, ab);
    const double t = length_sq > 0.0 ? std::clamp(glm::dot(ac, ab) / length_sq, 0.0, 1.0) : 0.0;
    const glm::dvec2 d = ac - t * ab;
    return glm::dot(d, d);
  }

 private:
  const OrbitCamera& camera_;
  Viewport viewport_;
  glm::dvec2 cursor_;
};

// The faces in the window's pixels within kVertexPickRadius of the cursor, each once.
std::vector<FaceId> faces_seen(const PickWindow& window, int x, int y) {
  std::vector<FaceId> faces;
  const size_t pixels = std::min(window.ids.size(), size_t(window.width) * size_t(std::max(window.height, 0)));
  for (size_t i = 0; i < pixels; ++i) {
    const int dx = window.left + int(i % size_t(window.width)) - x, dy = window.top + int(i / size_t(window.width)) - y;
    if (dx * dx + dy * dy > kVertexPickRadius * kVertexPickRadius) continue;
    const ElementRef seen = decode_pick_id(window.ids[i]);
    if (seen.kind != ElementKind::Face || !seen.valid()) continue;
    const FaceId f = seen.face_id();
    if (std::find(faces.begin(), faces.end(), f) == faces.end()) faces.push_back(f);
  }
  return faces;
}

}  // namespace

ElementRef pick_from_faces(const HalfedgeMesh& mesh, const OrbitCamera& camera, Viewport viewport,
                           const PickWindow& window, int x, int y, bool halfedges) {
  const Screen screen(camera, viewport, x, y);
  constexpr double kVertexReachSq = double(kVertexPickRadius) * kVertexPickRadius;
  constexpr double kReachSq = double(kPickRadius) * kPickRadius;
  Best vertex, arrow, edge;
  FaceDraw draw;
  std::vector<HalfedgeId> cycle;
  for (FaceId f : faces_seen(window, x, y)) {
    if (!mesh.alive(f)) continue;
    draw_face(mesh, f, draw, cycle);
    if (!draw.drawn()) continue;
    for (HalfedgeId h : cycle) {
      const VertexPoint point = slot_point(mesh, mesh.vertex(h));
      if (point.vertex != kInvalidIndex) {
        const auto d = screen.to_point(point.position);
        if (d && *d <= kVertexReachSq) vertex.offer(VertexId(point.vertex), *d);
      }
      if (halfedges) {
        for (const EdgeSegment& piece : slot_arrow(mesh, h)) {
          if (auto d = screen.to_segment(piece); d && *d <= kReachSq) arrow.offer(h, *d);
        }
      }
      const EdgeId e = mesh.edge(h);
      if (!mesh.alive(e)) continue;
      if (auto d = screen.to_segment(slot_edge(mesh, e)); d && *d <= kReachSq) edge.offer(e, *d);
    }
  }
  for (const Best* best : {&vertex, &arrow, &edge}) {
    if (best->element.valid()) return best->element;
  }
  return choose_pick(window.ids, window.width, window.height, x - window.left, y - window.top);
}

}  // namespace meshedit
