// The shapes of element_highlight.h, from the renderer's geometry of edges, arrows and face corners.
#include "app/element_highlight.h"

#include "render/mesh_geometry.h"

namespace meshedit {

void add_highlight(Overlay& overlay, const HalfedgeMesh& mesh, ElementRef element, const glm::vec4& rgba) {
  if (!mesh.alive(element)) return;
  switch (element.kind) {
    case ElementKind::Vertex: overlay.points.push_back({mesh.position(VertexId(element.index)), rgba, 14.0f}); break;
    case ElementKind::Edge:
      if (const auto s = edge_segment(mesh, EdgeId(element.index))) {
        overlay.lines.push_back({{glm::dvec3(s->start), glm::dvec3(s->end)}, rgba, 5.0f, false});
      }
      break;
    case ElementKind::Halfedge:
      if (const auto a = halfedge_arrow(mesh, HalfedgeId(element.index))) {
        overlay.lines.push_back(
            {{glm::dvec3(a->tail), glm::dvec3(a->tip), glm::dvec3(a->barb_inner)}, rgba, 4.0f, false});
      }
      break;
    case ElementKind::Face:
    case ElementKind::Boundary:
      if (const auto corners = face_corners(mesh, element.face_id())) {
        overlay.lines.push_back({*corners, rgba, 4.0f, true});
      }
      break;
  }
}

}  // namespace meshedit
