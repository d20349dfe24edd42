// Screen positions of id labels (see labels.h).
#include "render/labels.h"

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

bool element_faces_eye(const HalfedgeMesh& mesh, ElementRef element, const glm::dvec3& anchor,
                       const glm::dvec3& eye) {
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
      if (auto s = edge_segment(mesh, EdgeId(element.index))) {
        return (glm::dvec3(s->start) + glm::dvec3(s->end)) * 0.5;
      }
      return std::nullopt;
    case ElementKind::Face:
      if (auto corners = face_corners(mesh, FaceId::face(element.index))) {
        glm::dvec3 sum(0.0);
        for (const glm::dvec3& c : *corners) sum += c;
        return sum / double(corners->size());
      }
      return std::nullopt;
    case ElementKind::Halfedge:
      if (auto arrow = halfedge_arrow(mesh, HalfedgeId(element.index))) {
        return (glm::dvec3(arrow->tail) + glm::dvec3(arrow->tip)) * 0.5;
      }
      return std::nullopt;
    case ElementKind::Boundary: break;
  }
  return std::nullopt;
}

std::vector<ScreenLabel> visible_labels(const HalfedgeMesh& mesh, const OrbitCamera& camera, Viewport viewport,
                                        const LabelOptions& options) {
  std::vector<ScreenLabel> labels;
  const glm::dvec3 eye = camera.eye();
  auto consider = [&](ElementRef element) {
    if (labels.size() >= options.max_labels) return;
    const auto anchor = label_anchor(mesh, element);
    if (!anchor) return;
    const ScreenPoint p = camera.project(*anchor, viewport);
    if (!p.in_front || p.pixel.x < 0.0 || p.pixel.y < 0.0 || p.pixel.x >= viewport.width ||
        p.pixel.y >= viewport.height) {
      return;
    }
    if (!element_faces_eye(mesh, element, *anchor, eye)) return;
    labels.push_back({element, p.pixel, format_id(element)});
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

}  // namespace meshedit
