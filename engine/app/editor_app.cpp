// EditorApp: documents, the 3D view and the panels (see editor_app.h). Keys and mouse are in
// editor_input.cpp, menus and the open panel in editor_menus.cpp, id labels in id_labels.cpp, opening and saving
// files in editor_files.cpp.
#include "app/editor_app.h"

#include <cstdio>

#include <imgui.h>

#include "app/mesh_loading.h"
#include "app/window_host.h"
#include "core/mesh_build.h"
#include "core/mesh_error.h"
#include "document/exception_report.h"
#include "exercise/exercise_registry.h"
#include "exercise/scripted_exercise.h"
#include "io/file_error.h"
#include "io/mesh_file.h"
#include "render/gl_api.h"
#include "render/image_file.h"
#include "render/mesh_geometry.h"
#include "render/render_error.h"
#include "render/render_target.h"
#include "ui/frame_guard.h"
#include "ui/theme.h"

namespace meshedit {

EditorApp::EditorApp()
    : mesh_renderer_(std::make_unique<MeshRenderer>(shaders_)),
      patch_renderer_(std::make_unique<MeshRenderer>(shaders_)),
      overlay_renderer_(std::make_unique<OverlayRenderer>(shaders_)),
      curve_(make_curve_editor(default_curve())) {
  lesson_host_ = std::make_unique<WindowLessonHost>(*this);
  lesson_ = make_lesson_runner();
  lesson_panel_.lessons_dir = lessons_dir();
  lesson_panel_.lessons_editable = host_files_on_users_disk();
  refresh_lessons(lesson_panel_);
  lesson_panel_.reload = [this](LessonRunner&) { return reload_lesson(); };
  lesson_panel_.show_your_turn = [this] { show_your_turn_mine(); };
  // The exercises defined in Lua: a definition that does not load is named (file:line) and left out.
  const std::vector<std::string> errors = load_exercise_folder(default_exercise_folder());
  for (const std::string& error : errors) std::fprintf(stderr, "meshedit: exercise: %s\n", error.c_str());
  if (!errors.empty()) message(Severity::Warning, "an exercise in scripts/exercises did not load: " + errors.front());
}

EditorApp::~EditorApp() = default;

void EditorApp::message(Severity severity, const std::string& text) { set_message(doc_, severity, text); }

void EditorApp::write_pending_screenshot(int width, int height) {
  if (!screenshot_path_) return;
  const std::filesystem::path path = std::move(*screenshot_path_);  // moved: no copy to run out of memory
  screenshot_path_.reset();
  try {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    write_png(path, width, height, read_pixels({width, height}));
    const std::string handed = host_hand_over(path);  // a page's browser downloads it
    message(Severity::Info, "screenshot " + (handed.empty() ? "saved to " + path.string() : handed));
  } catch (const std::exception& e) {
    report_exception(doc_, e);  // called outside the frame guard (between rendering and the swap): never throws
  }
}

void EditorApp::fit_camera() {
  if (mode_ == ViewMode::Patches && patches_.tessellation.mesh) {
    fit_camera(mesh_bounds(*patches_.tessellation.mesh));
  } else {
    fit_camera(mesh_renderer_->bounds());
  }
}

void EditorApp::reset_view() { camera_.reset(); }

void EditorApp::frame(int width, int height, float frame_ms) {
  // The safety net: whatever a key, a click, a menu or a panel throws is shown, not fatal (ui/frame_guard.h).
  run_guarded_frame(doc_, [&] { run_frame(width, height, frame_ms); });
}

void EditorApp::run_frame(int width, int height, float frame_ms) {
  edit_animator_.advance(frame_ms / 1000.0);  // before this frame's actions: an edit they make starts at time 0
  read_mouse_and_keys();                      // in the view placed by the last frame
  update_lesson(frame_ms);
  view_quality_.frame_started(frame_ms);

  const glm::vec4 bg = mesh_renderer_->style().background;  // the theme's (set_theme)
  glViewport(0, 0, std::max(1, width), std::max(1, height));
  glClearColor(bg.r, bg.g, bg.b, bg.a);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  probe_.clear();
  draw_menu_bar();
  const float menu = ImGui::GetFrameHeight();
  status_bar_.mesh_shown = mode_ == ViewMode::Mesh;
  status_bar_.view_is_3d = mode_ != ViewMode::Curve;
  const float status = draw_status_bar(doc_, selection_, status_bar_, frame_ms);
  const ImGuiIO& io = ImGui::GetIO();
  font_pixels_ = ImGui::GetFontSize();
  layout_ = compute_layout(io.DisplaySize.x, io.DisplaySize.y, menu, status, settings_.layout, font_pixels_,
                           console_panel_.open);
  place_view(width, height);

  begin_view_drawing();
  switch (mode_) {
    case ViewMode::Mesh: draw_mesh_view(); break;
    case ViewMode::Patches: draw_patch_view(); break;
    case ViewMode::Curve: break;  // an ImGui canvas, drawn with the panels
  }
  end_view_drawing();
  if (mode_ == ViewMode::Curve) draw_curve_canvas_window();  // before the levels table: it computes the levels
  draw_labels(layout_.view.x, layout_.view.y, layout_.view.width, layout_.view.height, viewport());
  draw_columns();
  keep_student_drafts();
  draw_open_panel();
  draw_help_panel();
  draw_unsaved_code_dialog();
}

void EditorApp::draw_mesh_view() {
  // The document's last change lets the renderer rewrite only what an edit touched (it checks the versions): a local
  // edit by its patch, a listed whole-mesh change by the copy of the state before.
  MeshRenderer::MeshChange change;
  const bool described = doc_.last.patch || doc_.last.before;
  if (described && doc_.last.listed && doc_.last.version_before) {
    change.before = doc_.last.before ? &*doc_.last.before : nullptr;
    change.patch = doc_.last.patch ? &*doc_.last.patch : nullptr;
    change.elements = doc_.last.index.elements();
    change.version_before = *doc_.last.version_before;
    change.version_after = doc_.last.version_after;
  }
  // A mesh too large to draw is refused once per state: an Error says so, the status bar keeps saying it, the rest of
  // the window works on (undo brings back a mesh it can draw), and frames do not try again until the mesh changes.
  const bool refused =
      !undrawable_.empty() && undrawable_generation_ == doc_.generation && undrawable_version_ == doc_.mesh.version();
  if (!refused) {
    undrawable_.clear();
    try {
      mesh_renderer_->update(doc_.mesh, described ? &change : nullptr);
    } catch (const RenderError& e) {
      undrawable_ = e.what();
      undrawable_generation_ = doc_.generation;
      undrawable_version_ = doc_.mesh.version();
      message(Severity::Error, undrawable_);
    }
  }
  apply_size_defaults();
  take_pending_view();
  const ViewOptions drawn =
      undrawable_.empty() ? view_quality_.options_to_draw(view_options_, mesh_renderer_->stats()) : view_options_;
  status_bar_.note = undrawable_.empty() ? view_quality_.note() : "not drawn: " + undrawable_;
  if (status_bar_.note.empty() && !view_options_.wireframe &&
      (size_class_ == SizeClass::Dense || size_class_ == SizeClass::Large)) {
    status_bar_.note = "wireframe off (W shows it)";
  }
  edit_animator_.set_enabled(edits_animate());
  edit_animator_.follow(doc_);
  // While an edit plays, its moving parts are the only highlight: the selection, the changed elements and the lesson's
  // marks, already where the edit put them, would show its end before it is reached. They come back when it lands.
  const bool playing = edit_animator_.playing();
  Highlights highlights;
  highlights.hovered = selection_.hovered;
  if (!playing) {
    highlights.selected = selection_.selected;
    highlights.changed = doc_.last.index.elements();
    highlights.changed_key = doc_.last.serial + 1;  // nonzero; a new change has a new serial
  }
  mesh_renderer_->draw(camera_, viewport(), drawn, highlights);
  if (!playing) draw_lesson_marks();
  if (!playing) draw_repair_spots();
  draw_edit_animation();
}

void EditorApp::apply_size_defaults() {
  // The arrows' and the wireframe's defaults follow the mesh's size class when it changes (opening a file, a
  // subdivision); from there the quality (multisampling, wireframe, back sides) follows the frame time
  // (app/view_quality.h), and W, the menu or a lesson's view{} still choose.
  const bool large = is_large_mesh(mesh_renderer_->stats().triangles, mesh_renderer_->style());
  const size_t faces = doc_.mesh.num_faces();
  const SizeClass size = large                         ? SizeClass::Large
                         : faces <= kArrowsMaxFaces    ? SizeClass::Small
                         : faces <= kWireframeMaxFaces ? SizeClass::Medium
                                                       : SizeClass::Dense;
  if (size != size_class_) {
    size_class_ = size;
    view_options_.wireframe = size == SizeClass::Small || size == SizeClass::Medium;
    view_options_.show_halfedges = size == SizeClass::Small;
  }
  view_quality_.follow_mesh(doc_.generation, mesh_renderer_->stats().triangles, mesh_renderer_->style(), view_options_);
}

void EditorApp::draw_patch_view() {
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
  draw_lesson_arrows();  // a lesson's arrows (a patch normal) over the surface, as over a mesh
}

void EditorApp::apply_view_request(const ViewRequest& request) {
  // The curve view's parts at once; the mesh view's when it next draws, after the shown mesh's size class has set its
  // defaults.
  if (request.curve) curve_.show_curve = *request.curve;
  if (request.tangent) curve_.show_tangent = *request.tangent;
  pending_view_ = request;
}

void EditorApp::take_pending_view() {
  if (!pending_view_) return;
  const ViewRequest request = *pending_view_;
  pending_view_.reset();
  if (request.halfedges) view_options_.show_halfedges = *request.halfedges;
  if (request.wireframe) view_options_.wireframe = *request.wireframe;
  if (request.vertices) view_options_.show_vertices = *request.vertices;
  if (request.labels) show_labels_ = *request.labels;
}

void EditorApp::run_console(const std::string& code) {
  console_panel_.open = true;
  console_panel_.scroll_to_bottom = true;
  exercises_.finish_replay(doc_);
  console_.submit(doc_, selection_, code);
  keep_if_alive(selection_, doc_.mesh);
}

}  // namespace meshedit
