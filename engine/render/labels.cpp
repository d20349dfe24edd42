// Screen positions, preferred sides and placement requests of element labels (see labels.h).
#include "render/labels.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/finite.h"
#include "core/normals.h"
#include "render/mesh_geometry.h"

namespace meshedit {
namespace {

bool faces_eye(const glm::dvec3& normal, const glm::dvec3& anchor, const glm::dvec3& eye) {
  return glm::dot(normal, eye - anchor) > 0.0;
}

bool face_faces_eye(const HalfedgeMesh& mesh, FaceId f, const glm::dvec3& anchor, const glm::dvec3& eye) {
  return !f.is_boundary() && mesh.alive(f) && faces_eye(face_normal(mesh, f), anchor, eye);
}

bool element_faces_eye(const HalfedgeMesh& mesh, ElementRef element, const glm::dvec3& anchor, const glm::dvec3& eye) {
  switch (element.kind) {
    case ElementKind::Vertex: {
      bool facing = false;
      const bool closed = mesh.for_each_outgoing(VertexId(element.index), [&](HalfedgeId h) {
        facing = facing || face_faces_eye(mesh, mesh.face(h), anchor, eye);
      });
      return facing || !closed;  // a vertex whose fan cannot be walked is labelled anyway
    }
    case ElementKind::Edge: {
      const HalfedgeId h = mesh.halfedge(EdgeId(element.index));
      if (!mesh.alive(h)) return false;
      const HalfedgeId t = mesh.twin(h);
      return face_faces_eye(mesh, mesh.face(h), anchor, eye) ||
             (mesh.alive(t) && face_faces_eye(mesh, mesh.face(t), anchor, eye));
    }
    case ElementKind::Face: return face_faces_eye(mesh, FaceId::face(element.index), anchor, eye);
    case ElementKind::Halfedge: return face_faces_eye(mesh, mesh.face(HalfedgeId(element.index)), anchor, eye);
    case ElementKind::Boundary: break;
  }
  return false;
}

glm::dvec3 midpoint(const EdgeSegment& s) { return (glm::dvec3(s.start) + glm::dvec3(s.end)) * 0.5; }

// The pixel of a world point, when it is in front of the eye.
std::optional<glm::dvec2> pixel_of(const OrbitCamera& camera, Viewport viewport, const glm::dvec3& p) {
  const ScreenPoint s = camera.project(p, viewport);
  if (!s.in_front || !std::isfinite(s.pixel.x) || !std::isfinite(s.pixel.y)) return std::nullopt;
  return s.pixel;
}

// The side of the segment a -> b where `towards` lies, as a unit perpendicular on screen; zero when the segment
// has no length on screen.
glm::dvec2 perpendicular_towards(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& towards) {
  const glm::dvec2 along = b - a;
  const double length = glm::length(along);
  if (length < 1e-6) return glm::dvec2(0.0);
  glm::dvec2 n(-along.y / length, along.x / length);
  if (glm::dot(n, towards - (a + b) * 0.5) < 0.0) n = -n;
  return n;
}

// The interior (non-boundary) face of a halfedge, or an invalid id.
FaceId real_face(const HalfedgeMesh& mesh, HalfedgeId h) {
  if (!mesh.alive(h)) return FaceId();
  const FaceId f = mesh.face(h);
  return !f.is_boundary() && mesh.alive(f) ? f : FaceId();
}

const glm::dvec2 kTopRight = glm::dvec2(1.0, -1.0);  // screen y grows downwards

// Vertex: away from its neighbours on screen (minus the sum of the unit directions to them), which for a corner is
// the bisector of the angle outside it.
glm::dvec2 vertex_direction(const HalfedgeMesh& mesh, const OrbitCamera& camera, Viewport viewport, VertexId v,
                            const glm::dvec2& anchor) {
  glm::dvec2 towards(0.0);
  mesh.for_each_outgoing(v, [&](HalfedgeId h) {
    const HalfedgeId t = mesh.twin(h);
    if (!mesh.alive(t) || !mesh.alive(mesh.vertex(t))) return;
    const auto pixel = pixel_of(camera, viewport, mesh.position(mesh.vertex(t)));
    if (!pixel) return;
    const double length = glm::length(*pixel - anchor);
    if (length > 1e-6) towards += (*pixel - anchor) / length;
  });
  return glm::length(towards) < 0.25 ? kTopRight : -towards;
}

// Edge: perpendicular, away from its one face, or towards the top of the screen between two.
glm::dvec2 edge_direction(const HalfedgeMesh& mesh, const OrbitCamera& camera, Viewport viewport, EdgeId e) {
  const auto segment = edge_segment(mesh, e);
  if (!segment) return kTopRight;
  const auto a = pixel_of(camera, viewport, glm::dvec3(segment->start));
  const auto b = pixel_of(camera, viewport, glm::dvec3(segment->end));
  if (!a || !b) return kTopRight;
  const HalfedgeId h = mesh.halfedge(e);
  const FaceId one = real_face(mesh, h);
  const FaceId other = real_face(mesh, mesh.twin(h));
  if (one.valid() != other.valid()) {
    const auto centre = label_anchor(mesh, one.valid() ? one : other);
    const auto pixel = centre ? pixel_of(camera, viewport, *centre) : std::nullopt;
    if (pixel) {
      const glm::dvec2 n = perpendicular_towards(*a, *b, *pixel);
      if (n != glm::dvec2(0.0)) return -n;
    }
  }
  const glm::dvec2 mid = (*a + *b) * 0.5;
  glm::dvec2 up = perpendicular_towards(*a, *b, mid + glm::dvec2(0.0, -1.0));
  if (up == glm::dvec2(0.0)) return kTopRight;
  if (std::abs(up.y) < 1e-9) up = glm::dvec2(std::abs(up.x), 0.0);  // a vertical edge: to its right
  return up;
}

// Halfedge: beside its arrow towards its face's centre; on a boundary loop, away from the twin's face.
glm::dvec2 halfedge_direction(const HalfedgeMesh& mesh, const OrbitCamera& camera, Viewport viewport, HalfedgeId h) {
  if (const auto arrow = halfedge_arrow(mesh, h)) {
    const auto tail = pixel_of(camera, viewport, glm::dvec3(arrow->tail));
    const auto tip = pixel_of(camera, viewport, glm::dvec3(arrow->tip));
    const auto centre = label_anchor(mesh, mesh.face(h));
    const auto inside = centre ? pixel_of(camera, viewport, *centre) : std::nullopt;
    if (tail && tip && inside) {
      const glm::dvec2 n = perpendicular_towards(*tail, *tip, *inside);
      return n != glm::dvec2(0.0) ? n : *inside - (*tail + *tip) * 0.5;
    }
    return glm::dvec2(0.0);
  }
  const auto segment = edge_segment(mesh, mesh.edge(h));
  const FaceId inner = real_face(mesh, mesh.twin(h));
  const auto centre = inner.valid() ? label_anchor(mesh, inner) : std::nullopt;
  if (!segment || !centre) return kTopRight;
  const auto a = pixel_of(camera, viewport, glm::dvec3(segment->start));
  const auto b = pixel_of(camera, viewport, glm::dvec3(segment->end));
  const auto inside = pixel_of(camera, viewport, *centre);
  if (!a || !b || !inside) return kTopRight;
  const glm::dvec2 n = perpendicular_towards(*a, *b, *inside);
  return n != glm::dvec2(0.0) ? -n : kTopRight;
}

// The segment an element's label must keep clear of, in framebuffer pixels: an edge's line, a halfedge's arrow (or
// its edge, on a boundary loop).
std::optional<LabelSegment> own_segment(const HalfedgeMesh& mesh, const OrbitCamera& camera, Viewport viewport,
                                        ElementRef element) {
  std::optional<glm::dvec2> a, b;
  auto from = [&](const glm::vec3& p, const glm::vec3& q) {
    a = pixel_of(camera, viewport, glm::dvec3(p));
    b = pixel_of(camera, viewport, glm::dvec3(q));
  };
  if (element.kind == ElementKind::Edge) {
    if (const auto s = edge_segment(mesh, EdgeId(element.index))) from(s->start, s->end);
  } else if (element.kind == ElementKind::Halfedge) {
    const HalfedgeId h(element.index);
    if (const auto arrow = halfedge_arrow(mesh, h)) {
      from(arrow->tail, arrow->tip);
    } else if (mesh.alive(h)) {
      if (const auto s = edge_segment(mesh, mesh.edge(h))) from(s->start, s->end);
    }
  }
  if (!a || !b) return std::nullopt;
  return LabelSegment{*a, *b};
}

}  // namespace

std::optional<glm::dvec3> label_anchor(const HalfedgeMesh& mesh, ElementRef element) {
  if (!element.valid()) return std::nullopt;
  switch (element.kind) {
    case ElementKind::Vertex: {
      const VertexId v(element.index);
      if (!mesh.alive(v) || !finite(mesh.position(v))) return std::nullopt;
      return mesh.position(v);
    }
    case ElementKind::Edge:
      if (auto s = edge_segment(mesh, EdgeId(element.index))) return midpoint(*s);
      return std::nullopt;
    case ElementKind::Face:
      if (auto corners = face_corners(mesh, FaceId::face(element.index))) {
        glm::dvec3 sum(0.0);
        for (const glm::dvec3& c : *corners) sum += c;
        return sum / double(corners->size());
      }
      return std::nullopt;
    case ElementKind::Halfedge: {
      const HalfedgeId h(element.index);
      if (auto arrow = halfedge_arrow(mesh, h)) return (glm::dvec3(arrow->tail) + glm::dvec3(arrow->tip)) * 0.5;
      if (!mesh.alive(h) || !mesh.face(h).is_boundary()) return std::nullopt;
      if (auto s = edge_segment(mesh, mesh.edge(h))) return midpoint(*s);
      return std::nullopt;
    }
    case ElementKind::Boundary: break;
  }
  return std::nullopt;
}

std::optional<ScreenLabel> visible_label(const HalfedgeMesh& mesh, const OrbitCamera& camera, Viewport viewport,
                                         ElementRef element) {
  const auto anchor = label_anchor(mesh, element);
  if (!anchor) return std::nullopt;
  const ScreenPoint p = camera.project(*anchor, viewport);
  if (!p.in_front || p.pixel.x < 0.0 || p.pixel.y < 0.0 || p.pixel.x >= viewport.width ||
      p.pixel.y >= viewport.height) {
    return std::nullopt;
  }
  if (!element_faces_eye(mesh, element, *anchor, camera.eye())) return std::nullopt;
  return ScreenLabel{element, p.pixel, format_id(element)};
}

std::vector<ScreenLabel> visible_labels(const HalfedgeMesh& mesh, const OrbitCamera& camera, Viewport viewport,
                                        const LabelOptions& options) {
  std::vector<ScreenLabel> labels;
  auto consider = [&](ElementRef element) {
    if (labels.size() >= options.max_labels) return;
    if (auto label = visible_label(mesh, camera, viewport, element)) labels.push_back(std::move(*label));
  };
  if (options.vertices) {
    for (VertexId v : mesh.vertices()) consider(v);
  }
  if (options.edges) {
    for (EdgeId e : mesh.edges()) consider(e);
  }
  if (options.faces) {
    for (FaceId f : mesh.faces()) consider(f);
  }
  if (options.halfedges) {
    for (HalfedgeId h : mesh.halfedges()) consider(h);
  }
  return labels;
}

std::optional<glm::dvec2> label_direction(const HalfedgeMesh& mesh, const OrbitCamera& camera, Viewport viewport,
                                          ElementRef element) {
  const auto anchor = label_anchor(mesh, element);
  const auto pixel = anchor ? pixel_of(camera, viewport, *anchor) : std::nullopt;
  if (!pixel) return std::nullopt;
  switch (element.kind) {
    case ElementKind::Vertex: return vertex_direction(mesh, camera, viewport, VertexId(element.index), *pixel);
    case ElementKind::Edge: return edge_direction(mesh, camera, viewport, EdgeId(element.index));
    case ElementKind::Halfedge: return halfedge_direction(mesh, camera, viewport, HalfedgeId(element.index));
    case ElementKind::Face:
    case ElementKind::Boundary: break;
  }
  return glm::dvec2(0.0);
}

glm::dvec2 LabelView::scale() const {
  return {framebuffer.width > 0 ? window.width() / double(framebuffer.width) : 1.0,
          framebuffer.height > 0 ? window.height() / double(framebuffer.height) : 1.0};
}

std::vector<LabelRequest> label_requests(const HalfedgeMesh& mesh, const OrbitCamera& camera, const LabelView& view,
                                         const LabelScene& scene, const TextMeasure& measure) {
  std::vector<LabelRequest> requests;
  const Viewport viewport = view.framebuffer;
  auto add = [&](ElementRef element, const glm::dvec2& pixel, const std::string& text, LabelSource source,
                 int priority) {
    const auto direction = label_direction(mesh, camera, viewport, element);
    if (!direction) return;
    std::optional<LabelSegment> keep_clear = own_segment(mesh, camera, viewport, element);
    if (keep_clear) keep_clear = LabelSegment{view.to_window(keep_clear->a), view.to_window(keep_clear->b)};
    requests.push_back(
        {element, text, source, view.to_window(pixel), *direction * view.scale(), measure(text), priority, keep_clear});
  };

  for (const auto& [element, text] : scene.lesson) {
    const auto anchor = label_anchor(mesh, element);
    const auto pixel = anchor ? pixel_of(camera, viewport, *anchor) : std::nullopt;
    if (!pixel || pixel->x < 0.0 || pixel->y < 0.0 || pixel->x >= viewport.width || pixel->y >= viewport.height) {
      continue;
    }
    add(element, *pixel, text, LabelSource::Lesson, kLessonLabelPriority);
  }
  if (!scene.id_labels) return requests;

  auto repeats_lesson = [&](const ScreenLabel& label) {
    return std::any_of(scene.lesson.begin(), scene.lesson.end(),
                       [&](const auto& l) { return l.first == label.element && l.second == label.text; });
  };
  auto priority_of = [&](ElementRef element) {
    if (element == scene.selected) return kSelectedLabelPriority;
    if (element == scene.hovered) return kHoveredLabelPriority;
    return kOtherLabelPriority;
  };
  std::vector<ScreenLabel> labels = visible_labels(mesh, camera, viewport, scene.ids);
  for (ElementRef wanted : {scene.selected, scene.hovered}) {
    const bool listed =
        std::any_of(labels.begin(), labels.end(), [&](const ScreenLabel& l) { return l.element == wanted; });
    if (wanted.valid() && !listed) {
      if (auto label = visible_label(mesh, camera, viewport, wanted)) labels.push_back(std::move(*label));
    }
  }
  for (const ScreenLabel& label : labels) {
    if (repeats_lesson(label)) continue;
    add(label.element, label.pixel, label.text, LabelSource::Id, priority_of(label.element));
  }
  return requests;
}

}  // namespace meshedit
