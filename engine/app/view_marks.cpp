// ViewRoom: the marks drawn over the mesh view (see view_room.h) on top of the mesh, each in its palette colour:
//   - the lesson's highlights (a named swatch in the theme's shade) and its arrows, solid where the mesh does not hide
//     them and faint where it does (a normal on the far side of a closed mesh shows as what it is), also over the
//     patch view;
//   - the repaired spots (app/repair_marks.h), every one in the "last edit" colour, a selected vertex among them
//     keeping its selection colour inside the spot's ring;
//   - the edit playing (app/edit_animator.h) in the view's "changed" colour and highlight sizes, over the mesh after
//     the edit. The timing and which changes play are edit_animator.h's; the pictures render/edit_animation.h's.
#include "app/document_room.h"
#include "app/element_highlight.h"
#include "app/view_room.h"
#include "render/arrow_overlay.h"

namespace meshedit {
namespace {

constexpr float kHiddenArrowAlpha = 0.3f;  // a lesson's arrow where the mesh is in front of it

}  // namespace

void ViewRoom::draw_lesson_marks(const LessonMarks& marks) {
  if (marks.highlights.empty() && marks.arrows.empty()) return;
  const HalfedgeMesh& mesh = document_.doc().mesh;
  Overlay overlay;
  overlay.on_top = true;
  for (const auto& [element, colour] : marks.highlights) {
    const glm::vec4 rgba(swatch_in_theme(colour, theme_), 1.0f);
    add_highlight(overlay, mesh, element, rgba);
  }
  overlay_renderer_->draw(camera_, viewport(), overlay);
  draw_lesson_arrows(marks);
}

void ViewRoom::draw_lesson_arrows(const LessonMarks& marks) {
  if (marks.arrows.empty()) return;
  Overlay hidden, seen;
  hidden.on_top = true;
  for (const LessonArrow& arrow : marks.arrows) {
    const glm::vec3 rgb = swatch_in_theme(arrow.colour, theme_);
    add_arrow(hidden, arrow.from, arrow.to, camera_.eye(), glm::vec4(rgb, kHiddenArrowAlpha), 2.0f);
    add_arrow(seen, arrow.from, arrow.to, camera_.eye(), glm::vec4(rgb, 1.0f), 3.0f);
  }
  overlay_renderer_->draw(camera_, viewport(), hidden);
  overlay_renderer_->draw(camera_, viewport(), seen);
}

void ViewRoom::draw_repair_spots(const RepairMarks& repairs) {
  const HalfedgeMesh& mesh = document_.doc().mesh;
  const ElementRef selected = document_.selection().selected;
  Overlay overlay;
  overlay.on_top = true;
  const glm::vec4 rgba(palette_for(theme_).changed, 1.0f);
  for (const ElementRef spot : repairs.all_spots()) add_highlight(overlay, mesh, spot, rgba);
  if (selected.kind == ElementKind::Vertex && mesh.alive(selected)) {
    const glm::vec4 colour(palette_for(theme_).selected, 1.0f);
    overlay.points.push_back({mesh.position(VertexId(selected.index)), colour, 9.0f});
  }
  overlay_renderer_->draw(camera_, viewport(), overlay);
}

void ViewRoom::draw_edit_animation() {
  if (!edit_animator_.playing()) return;
  const RenderStyle& style = mesh_renderer_->style();
  const EditAnimationLook look{style.changed, style.highlight_width + 1.0f, style.highlight_vertex_size};
  overlay_renderer_->draw(camera_, viewport(), edit_animator_.overlay(look));
}

}  // namespace meshedit
