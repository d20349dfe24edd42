// Labels over the mesh view: the id labels (`v3`, `e5`, `f2`, `h12`) that let students match the pointer tables to
// the picture, and the lesson's labels (LessonMarks::labels), placed together so that none overlaps another
// (render/labels.h makes the requests, render/label_placement.h places them) and drawn with ImGui behind every
// panel, clipped to the view's rectangle.
//
// Invariants: id labels appear only while the mesh is small enough for them to be read (kMaxLabelledFaces) and the
// View menu's "Id labels" is on; halfedge id labels only while the arrows are shown (the selected or hovered
// halfedge's label always). The lesson's labels are placed first, then the selected element's id label, the
// hovered one's, the rest. ViewRoom::last_labels_ holds what the last frame drew (empty outside the mesh view).
#include <imgui.h>

#include "app/document_room.h"
#include "app/view_room.h"
#include "core/palette.h"
#include "render/labels.h"
#include "ui/theme.h"

namespace meshedit {
namespace {

constexpr size_t kMaxLabelledFaces = 120;

// A label's text takes its element kind's colour from the palette, a lesson's label the lesson colour; each sits on a
// box of the theme's label_box (dark boxes on the dark theme, light ones on the light), so it reads over any face.
ImU32 text_colour(const PlacedLabel& label, const Palette& palette) {
  if (label.source == LabelSource::Lesson) return im_colour_u32(palette.lesson_label);
  switch (label.element.kind) {
    case ElementKind::Vertex: return im_colour_u32(palette.vertex_label);
    case ElementKind::Edge: return im_colour_u32(palette.edge_label);
    case ElementKind::Halfedge: return im_colour_u32(palette.halfedge_label);
    case ElementKind::Face:
    case ElementKind::Boundary: break;
  }
  return im_colour_u32(palette.face_label);
}

ImU32 box_colour(const PlacedLabel& label, const Palette& palette) {
  return im_colour_u32(label.source == LabelSource::Lesson ? palette.lesson_label_box : palette.neutrals.label_box);
}

ImVec2 to_imgui(const glm::dvec2& p) { return ImVec2(float(p.x), float(p.y)); }

}  // namespace

void ViewRoom::draw_labels(const LessonMarks& lesson) {
  last_labels_ = {};
  const float view_x = view_rect_.x, view_y = view_rect_.y, view_width = view_rect_.width,
              view_height = view_rect_.height;
  if (mode_ != ViewMode::Mesh || view_width <= 0.0f || view_height <= 0.0f) return;
  const HalfedgeMesh& mesh = document_.doc().mesh;
  const Selection& selection = document_.selection();
  LabelScene scene;
  scene.id_labels = show_labels_ && mesh.num_faces() <= kMaxLabelledFaces;
  scene.ids.halfedges = view_options_.show_halfedges;
  scene.lesson = lesson.labels;
  scene.selected = selection.selected;
  scene.hovered = selection.hovered;
  if (!scene.id_labels && scene.lesson.empty()) return;

  const LabelView view{{{view_x, view_y}, {double(view_x) + view_width, double(view_y) + view_height}}, viewport()};
  const TextMeasure measure = [](const std::string& text) {
    const ImVec2 size = ImGui::CalcTextSize(text.c_str());
    return glm::dvec2(size.x, size.y);
  };
  const std::vector<LabelRequest> requests = label_requests(mesh, camera_, view, scene, measure);
  last_labels_ = place_labels(requests, view.window);

  const Palette& palette = palette_for(theme_);
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  draw->PushClipRect(to_imgui(view.window.min), to_imgui(view.window.max), true);
  for (const PlacedLabel& label : last_labels_.placed) {
    draw->AddRectFilled(to_imgui(label.rect.min), to_imgui(label.rect.max), box_colour(label, palette), 3.0f);
    draw->AddText(to_imgui(label.text_min), text_colour(label, palette), label.text.c_str());
  }
  draw->PopClipRect();
}

}  // namespace meshedit
