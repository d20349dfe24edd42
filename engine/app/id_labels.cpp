// Id labels (`v3`, `e5`, `f2`, `h12`) drawn next to the elements of a small mesh, so students can match
// the pointer tables to the picture. Only elements on faces turned towards the camera are labelled, and
// only while the mesh is small enough for the labels to be read (kMaxLabelledFaces).
#include <imgui.h>

#include "app/editor_app.h"
#include "core/normals.h"
#include "render/mesh_geometry.h"

namespace meshedit {
namespace {

constexpr size_t kMaxLabelledFaces = 120;

}  // namespace

void EditorApp::draw_id_labels() {
  const HalfedgeMesh& mesh = doc_.mesh;
  if (mesh.num_faces() > kMaxLabelledFaces) return;
  const float to_window_x = layout_.view.width / float(std::max(1, view_pixels_.width));
  const float to_window_y = layout_.view.height / float(std::max(1, view_pixels_.height));
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  const glm::dvec3 eye = camera_.eye();

  auto facing = [&](FaceId f) {
    if (!mesh.alive(f) || f.is_boundary()) return false;
    const auto corners = face_corners(mesh, f);
    if (!corners || corners->empty()) return false;
    glm::dvec3 centre(0.0);
    for (const auto& p : *corners) centre += p;
    centre /= double(corners->size());
    return glm::dot(face_normal(mesh, f), eye - centre) > 0.0;
  };
  auto label = [&](const glm::dvec3& where, ElementRef element, ImU32 colour) {
    const ScreenPoint s = camera_.project(where, viewport());
    if (!s.in_front) return;
    const std::string text = format_id(element);
    const ImVec2 at(layout_.view.x + float(s.pixel.x) * to_window_x, layout_.view.y + float(s.pixel.y) * to_window_y);
    const ImVec2 size = ImGui::CalcTextSize(text.c_str());
    const ImVec2 corner(at.x - size.x * 0.5f, at.y - size.y * 0.5f);
    draw->AddRectFilled(ImVec2(corner.x - 2, corner.y - 1), ImVec2(corner.x + size.x + 2, corner.y + size.y + 1),
                        IM_COL32(0, 0, 0, 150), 3.0f);
    draw->AddText(corner, colour, text.c_str());
  };

  for (FaceId f : mesh.faces()) {
    if (!facing(f)) continue;
    const auto corners = face_corners(mesh, f);
    glm::dvec3 centre(0.0);
    for (const auto& p : *corners) centre += p;
    label(centre / double(corners->size()), f, IM_COL32(150, 200, 255, 255));
  }
  for (EdgeId e : mesh.edges()) {
    const auto segment = edge_segment(mesh, e);
    const HalfedgeId h = mesh.halfedge(e);
    if (!segment || !mesh.alive(h) || !(facing(mesh.face(h)) || facing(mesh.face(mesh.twin(h))))) continue;
    label((glm::dvec3(segment->start) + glm::dvec3(segment->end)) * 0.5, e, IM_COL32(230, 230, 230, 255));
  }
  for (VertexId v : mesh.vertices()) {
    const glm::dvec3 n = vertex_normal(mesh, v);
    if (glm::dot(n, eye - mesh.position(v)) <= 0.0) continue;
    label(mesh.position(v), v, IM_COL32(255, 230, 120, 255));
  }
  if (view_options_.show_halfedges) {
    for (HalfedgeId h : mesh.halfedges()) {
      if (!facing(mesh.face(h))) continue;
      const auto arrow = halfedge_arrow(mesh, h);
      if (!arrow) continue;
      label((glm::dvec3(arrow->tail) + glm::dvec3(arrow->tip)) * 0.5, h, IM_COL32(255, 170, 240, 255));
    }
  }
}

}  // namespace meshedit
