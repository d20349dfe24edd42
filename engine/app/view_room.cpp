// ViewRoom: placing the view in the layout and drawing one frame of it (see view_room.h). What goes on screen is
// view_showing.cpp's, the up axis view_up_axis.cpp's, the marks over the mesh view_marks.cpp's, the labels
// id_labels.cpp's.
#include "app/view_room.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "app/document_room.h"
#include "core/translation.h"
#include "render/gl_api.h"
#include "render/labels.h"
#include "render/mesh_geometry.h"
#include "render/render_error.h"
#include "ui/curve_editor.h"
#include "ui/patch_view.h"
#include "ui/theme.h"

namespace meshedit {

ViewRoom::ViewRoom(DocumentRoom& document)
    : document_(document),
      mesh_renderer_(std::make_unique<MeshRenderer>(shaders_)),
      patch_renderer_(std::make_unique<MeshRenderer>(shaders_)),
      overlay_renderer_(std::make_unique<OverlayRenderer>(shaders_)),
      curve_(make_curve_editor(default_curve())) {}

ViewRoom::~ViewRoom() = default;

void ViewRoom::fit_camera() {
  if (mode_ == ViewMode::Patches && patches_.tessellation.mesh) {
    fit_camera(mesh_bounds(*patches_.tessellation.mesh));
  } else {
    fit_camera(mesh_renderer_->bounds());
  }
}

void ViewRoom::place(const ScreenRect& view, int framebuffer_width, int framebuffer_height) {
  view_rect_ = view;
  const ImGuiIO& io = ImGui::GetIO();
  const float sx = io.DisplaySize.x > 0 ? float(framebuffer_width) / io.DisplaySize.x : 1.0f;
  const float sy = io.DisplaySize.y > 0 ? float(framebuffer_height) / io.DisplaySize.y : 1.0f;
  pixels_per_point_ = {sx, sy};
  const int x0 = int(std::lround(view.x * sx)), y0 = int(std::lround(view.y * sy));
  const int x1 = int(std::lround(view.right() * sx)), y1 = int(std::lround(view.bottom() * sy));
  view_pixels_ = {x0, y0, std::max(1, x1 - x0), std::max(1, y1 - y0)};
  framebuffer_height_ = std::max(1, framebuffer_height);
}

void ViewRoom::draw(const ViewMarks& marks) {
  const PixelRect& v = view_pixels_;
  const int gl_y = framebuffer_height_ - (v.y + v.height);  // GL counts rows from the bottom
  glViewport(v.x, gl_y, v.width, v.height);
  glScissor(v.x, gl_y, v.width, v.height);
  glEnable(GL_SCISSOR_TEST);
  switch (mode_) {
    case ViewMode::Mesh: draw_mesh_view(marks); break;
    case ViewMode::Patches: draw_patch_view(marks); break;
    case ViewMode::Curve: break;  // an ImGui canvas, drawn with the panels (draw_curve_canvas_window)
  }
  glDisable(GL_SCISSOR_TEST);
}

void ViewRoom::draw_mesh_view(const ViewMarks& marks) {
  MeshDocument& doc = document_.doc();
  const Selection& selection = document_.selection();
  // The document's last change lets the renderer rewrite only what an edit touched (it checks the versions): a local
  // edit by its patch, a listed whole-mesh change by the copy of the state before.
  MeshRenderer::MeshChange change;
  const bool described = doc.last.patch || doc.last.before;
  if (described && doc.last.listed && doc.last.version_before) {
    change.before = doc.last.before ? &*doc.last.before : nullptr;
    change.patch = doc.last.patch ? &*doc.last.patch : nullptr;
    change.elements = doc.last.index.elements();
    change.version_before = *doc.last.version_before;
    change.version_after = doc.last.version_after;
  }
  // A mesh too large to draw is refused once per state: an Error says so, the status bar keeps saying it, the rest of
  // the window works on (undo brings back a mesh it can draw), and frames do not try again until the mesh changes.
  const bool refused =
      !undrawable_.empty() && undrawable_generation_ == doc.generation && undrawable_version_ == doc.mesh.version();
  if (!refused) {
    undrawable_.clear();
    try {
      mesh_renderer_->update(doc.mesh, described ? &change : nullptr);
    } catch (const RenderError& e) {
      undrawable_ = e.what();
      undrawable_generation_ = doc.generation;
      undrawable_version_ = doc.mesh.version();
      document_.message(Severity::Error, undrawable_);
    }
  }
  apply_size_defaults();
  take_pending_view();
  const ViewOptions drawn =
      undrawable_.empty() ? view_quality_.options_to_draw(view_options_, mesh_renderer_->stats()) : view_options_;
  status_bar_.note =
      undrawable_.empty() ? view_quality_.note() : tr_format("not drawn: {reason}", {{"reason", undrawable_}});
  if (status_bar_.note.empty() && !view_options_.wireframe &&
      (size_class_ == SizeClass::Dense || size_class_ == SizeClass::Large)) {
    status_bar_.note = tr("wireframe off (W shows it)");
  }
  edit_animator_.set_enabled(edits_animate(marks.animate_edits));
  edit_animator_.follow(doc);
  // While an edit plays, its moving parts are the only highlight: the selection, the changed elements and the lesson's
  // marks, already where the edit put them, would show its end before it is reached. They come back when it lands.
  const bool playing = edit_animator_.playing();
  Highlights highlights;
  highlights.hovered = selection.hovered;
  if (!playing) {
    highlights.selected = selection.selected;
    highlights.changed = doc.last.index.elements();
    highlights.changed_key = doc.last.serial + 1;  // nonzero; a new change has a new serial
  }
  mesh_renderer_->draw(camera_, viewport(), drawn, highlights);
  if (!playing && marks.lesson) draw_lesson_marks(*marks.lesson);
  if (!playing && marks.repairs) draw_repair_spots(*marks.repairs);
  draw_edit_animation();
}

void ViewRoom::apply_size_defaults() {
  // The arrows' and the wireframe's defaults follow the mesh's size class when it changes (opening a file, a
  // subdivision); from there the quality (multisampling, wireframe, back sides) follows the frame time
  // (app/view_quality.h), and W, the menu or a lesson's view{} still choose.
  const bool large = is_large_mesh(mesh_renderer_->stats().triangles, mesh_renderer_->style());
  const size_t faces = document_.doc().mesh.num_faces();
  const SizeClass size = large                         ? SizeClass::Large
                         : faces <= kArrowsMaxFaces    ? SizeClass::Small
                         : faces <= kWireframeMaxFaces ? SizeClass::Medium
                                                       : SizeClass::Dense;
  if (size != size_class_) {
    size_class_ = size;
    view_options_.wireframe = size == SizeClass::Small || size == SizeClass::Medium;
    view_options_.show_halfedges = size == SizeClass::Small;
  }
  view_quality_.follow_mesh(document_.doc().generation, mesh_renderer_->stats().triangles, mesh_renderer_->style(),
                            view_options_);
}

void ViewRoom::draw_patch_view(const ViewMarks& marks) {
  update_tessellation(patches_);  // the controls (in the right column, drawn after the view) change it next frame
  const PatchMinePoint* mine = nullptr;
  if (bezier_mine_.patch_on() && !patches_.patches.empty()) {
    mine = &bezier_mine_.patch_point(patches_.patches[patches_.selected_patch], patches_.u, patches_.v);
  }
  if (patches_.show_surface && patches_.tessellation.mesh) {
    patch_renderer_->update(*patches_.tessellation.mesh);
    patch_renderer_->draw(camera_, viewport(), view_options_, {});
  }
  // The control net and the (u, v) probe, drawn over the surface so the probe points stay visible.
  Overlay overlay;
  overlay.on_top = true;
  for (const PatchOverlayItem& item : patch_view_overlay(patches_, mine)) {
    if (item.points_only) {
      for (const auto& p : item.points) overlay.points.push_back({p, item.colour, item.width});
    } else {
      overlay.lines.push_back({item.points, item.colour, item.width, false});
    }
  }
  overlay_renderer_->draw(camera_, viewport(), overlay);
  if (marks.lesson) draw_lesson_arrows(*marks.lesson);  // a lesson's arrows (a patch normal) over the surface
}

void ViewRoom::apply_view_request(const ViewRequest& request) {
  if (request.curve) curve_.show_curve = *request.curve;
  if (request.tangent) curve_.show_tangent = *request.tangent;
  pending_view_ = request;
}

void ViewRoom::take_pending_view() {
  if (!pending_view_) return;
  const ViewRequest request = *pending_view_;
  pending_view_.reset();
  if (request.halfedges) view_options_.show_halfedges = *request.halfedges;
  if (request.wireframe) view_options_.wireframe = *request.wireframe;
  if (request.vertices) view_options_.show_vertices = *request.vertices;
  if (request.labels) show_labels_ = *request.labels;
}

void ViewRoom::draw_curve_canvas_window() {
  const ScreenRect& v = view_rect_;
  if (v.empty()) return;
  ImGui::SetNextWindowPos(ImVec2(v.x, v.y));
  ImGui::SetNextWindowSize(ImVec2(v.width, v.height));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
  // The wheel belongs to t over the canvas: the window itself must not scroll with it.
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus |
                                 ImGuiWindowFlags_NoScrollWithMouse;
  if (ImGui::Begin("###curve view", nullptr, flags)) {
    draw_curve_canvas(curve_, ImVec2(v.width, v.height), &bezier_mine_);
  }
  ImGui::End();
  ImGui::PopStyleVar(2);
}

std::optional<glm::ivec2> ViewRoom::mouse_in_view() const {
  const ImGuiIO& io = ImGui::GetIO();
  if (!ImGui::IsMousePosValid() || !view_rect_.contains(io.MousePos.x, io.MousePos.y)) return std::nullopt;
  return glm::ivec2(int((io.MousePos.x - view_rect_.x) * pixels_per_point_.x),
                    int((io.MousePos.y - view_rect_.y) * pixels_per_point_.y));
}

ElementRef ViewRoom::pick(int x, int y) { return mesh_renderer_->pick(camera_, viewport(), x, y); }

bool ViewRoom::pick_is_cheap() {
  // The id buffer is stale after a camera move; redrawing it is slow for a large mesh on a software renderer.
  constexpr double kSlowIdPassMs = 30.0;
  return mesh_renderer_->pick_is_cheap(camera_, viewport()) || mesh_renderer_->stats().last_id_pass_ms < kSlowIdPassMs;
}

std::optional<ScreenPoint> ViewRoom::element_pixel(ElementRef element) const {
  const std::optional<glm::dvec3> anchor = label_anchor(document_.doc().mesh, element);
  if (!anchor) return std::nullopt;
  const Viewport view = viewport();
  const ScreenPoint p = camera_.project(*anchor, view);
  if (!p.in_front || p.pixel.x < 0.0 || p.pixel.y < 0.0 || p.pixel.x >= view.width || p.pixel.y >= view.height) {
    return std::nullopt;
  }
  return p;
}

void ViewRoom::set_theme(Theme theme) {
  theme_ = theme;
  const Palette& palette = palette_for(theme);
  set_render_colours(mesh_renderer_->style(), palette);
  set_render_colours(patch_renderer_->style(), palette);
}

bool ViewRoom::edits_animate(bool setting) const {
  switch (edit_animation_policy_) {
    case EditAnimationPolicy::Never: return false;
    case EditAnimationPolicy::AsSettingSays: return setting;
    case EditAnimationPolicy::Always: return true;
  }
  return false;
}

}  // namespace meshedit
