// ViewRoom: the views and their camera. Owns the shaders and the renderers, the orbit camera, what the user and the
// quality governor show (view options, id labels), which view is on screen (the mesh, the curve or the patches) with
// the curve's and the patches' state and their "mine" switches, the up axis, the view's rectangle, the edit playing,
// and the status bar's view remarks. It draws the open document (DocumentRoom) and the marks other rooms lay over it.
//
// Invariants:
// - The mesh, patch and curve views draw only into the view rectangle (GL viewport and scissor set to it, the camera's
//   aspect and picking in its pixels); picking pixels (pick, element_pixel) are framebuffer pixels relative to the
//   view's top-left corner. GL objects are made by the constructor, in the window's context, and go with the room.
// - A mesh too large to draw (past the GPU's buffer limits) is refused by the renderer once per mesh state: an Error
//   and the status bar say so, the view stays empty, and frames do not retry until the mesh changes.
// - A broken mesh (a Lua script's doing) can be drawn: only the core's and the renderer's bounded walks walk it.
// - take_mesh, take_curve and take_patches switch what is on screen with steps that cannot fail (the end of opening a
//   file or showing a lesson's mesh); show_lesson_mesh, show_curve and show_patches are whole or nothing, and throw
//   what stopped them with the view unchanged.
// - An edit playing (app/edit_animator.h, only under a policy that allows it: never in tests, pictures or scripted
//   runs) is drawn over the mesh as it is after the edit; meanwhile the selection, changed and lesson highlights wait.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "app/edit_animator.h"
#include "app/lesson_marks.h"
#include "app/repair_marks.h"
#include "app/up_axis_choice.h"
#include "app/view_quality.h"
#include "core/bezier.h"
#include "core/palette.h"
#include "document/bezier_mine.h"
#include "document/curve_view_state.h"
#include "document/patch_view_state.h"
#include "document/window_layout.h"
#include "lesson/lesson_host.h"
#include "render/camera.h"
#include "render/label_placement.h"
#include "render/mesh_renderer.h"
#include "render/overlay_renderer.h"
#include "render/shader_library.h"
#include "render/view_options.h"
#include "ui/status_bar.h"

namespace meshedit {

class DocumentRoom;

enum class ViewMode { Mesh, Curve, Patches };

// Whether flips, splits and collapses, and their undo and redo, play for a quarter second (app/edit_animator.h): never
// (the default: tests, pictures and scripted runs), as View > Animate edits says (the interactive window), or always
// (a scripted run's `animate-edits on`).
enum class EditAnimationPolicy { Never, AsSettingSays, Always };

// What other rooms lay over the mesh view this frame.
struct ViewMarks {
  const LessonMarks* lesson = nullptr;
  const RepairMarks* repairs = nullptr;  // the repaired spots, while they are the shown mesh's
  bool animate_edits = false;            // View > Animate edits (the setting the policy may follow)
};

class ViewRoom {
 public:
  explicit ViewRoom(DocumentRoom& document);  // needs a current OpenGL 3.3 core context (throws RenderError)
  ~ViewRoom();
  ViewRoom(const ViewRoom&) = delete;
  ViewRoom& operator=(const ViewRoom&) = delete;

  ViewMode mode() const { return mode_; }
  // The document takes `mesh` and the mesh view comes on screen, the camera fitted to it when `fit` (or when the up
  // axis turned); the curve view or the patch view takes its state. None can fail (view_showing.cpp).
  void take_mesh(HalfedgeMesh&& mesh, std::string&& name, bool fit = true) noexcept;
  void take_made_mesh(HalfedgeMesh&& mesh, std::string&& name) noexcept;  // a mesh no file gave: Z-up
  void take_curve(CurveEditorState&& curve) noexcept;
  void take_patches(PatchViewState&& patches) noexcept;
  // The shown file's up axis (nullopt: a mesh no file gave, Z-up), View > Up axis back to "From the file".
  void set_file_up_axis(std::optional<FileUpAxis> up) noexcept;
  // What lessons show (window_lesson_host.h): a mesh (fitting the camera only when asked or when another view was on
  // screen; `up` as show{up=} says, else Z), a curve, patches. Whole or nothing: what stops them is thrown.
  void show_lesson_mesh(const HalfedgeMesh& mesh, bool fit, std::optional<UpAxis> up = std::nullopt);
  void show_curve(const BezierCurve& curve);
  void show_patches(const std::vector<BezierPatch>& patches);
  // A lesson starts: View > Up axis back to "From the file" (its meshes are Z-up), refitted when the axis turned.
  void follow_lesson_up_axis() noexcept;
  // View > Up axis: shows the mesh or patches with that up axis (app/up_axis_choice.h), refitted.
  void choose_up_axis(UpAxisChoice choice);
  UpAxisChoice up_axis_choice() const { return up_axis_choice_; }
  // A lesson's view{...}: the curve view's parts at once, the mesh view's when it next draws (after its size defaults).
  void apply_view_request(const ViewRequest& request);

  OrbitCamera& camera() { return camera_; }
  const OrbitCamera& camera() const { return camera_; }
  void fit_camera();  // to what the view shows: the mesh, or the patches' surface
  void reset_view() { camera_.reset(); }
  Viewport viewport() const { return {view_pixels_.width, view_pixels_.height}; }

  // One frame (view_room.cpp): the last frame's time measured, the view placed in the layout's rectangle (window
  // coordinates) of a framebuffer of the given size, then the mesh or the patch view drawn into it (GL), the curve
  // view's canvas (ImGui) and the labels.
  void measure_frame(float frame_ms) { view_quality_.frame_started(frame_ms); }  // the quality governor's clock
  void place(const ScreenRect& view, int framebuffer_width, int framebuffer_height);
  void draw(const ViewMarks& marks);
  void draw_curve_canvas_window();
  void draw_labels(const LessonMarks& lesson);                                 // id_labels.cpp
  glm::vec4 background() const { return mesh_renderer_->style().background; }  // the theme's
  // The mouse position in view pixels, or nullopt outside the view; framebuffer pixels per window coordinate.
  std::optional<glm::ivec2> mouse_in_view() const;
  glm::vec2 pixels_per_point() const { return pixels_per_point_; }
  // What is under pixel (x, y) of the mesh view; whether picking now is cheap (the id buffer is up to date, or quick
  // to redraw).
  ElementRef pick(int x, int y);
  bool pick_is_cheap();
  // Where the element's label anchor (a vertex's position, an edge's midpoint...) is in the view's pixels; nullopt
  // when it is dead, behind the eye or outside the view.
  std::optional<ScreenPoint> element_pixel(ElementRef element) const;

  ViewOptions& options() { return view_options_; }  // as the user and the quality governor set them
  bool& show_labels() { return show_labels_; }
  // The mesh view at full quality whatever its frames cost (true), or the quality governor's choice (false).
  void hold_full_quality(bool hold) { view_quality_.hold_full(hold, view_options_); }
  CurveEditorState& curve() { return curve_; }
  const CurveEditorState& curve() const { return curve_; }
  PatchViewState& patches() { return patches_; }
  const PatchViewState& patches() const { return patches_; }
  BezierMine& bezier_mine() { return bezier_mine_; }  // the curve and patch views' "mine" switches (M)
  const BezierMine& bezier_mine() const { return bezier_mine_; }
  StatusBarState& status_bar() { return status_bar_; }
  // The labels the last frame drew over the mesh view (window coordinates) and how many it dropped; empty outside it.
  const LabelPlacement& last_labels() const { return last_labels_; }
  const RenderStats& mesh_render_stats() const { return mesh_renderer_->stats(); }
  RenderStyle& mesh_render_style() { return mesh_renderer_->style(); }  // tests lower its buffer cap
  void set_theme(Theme theme);                                          // the renderers' colours and the marks' palette

  void set_edit_animation_policy(EditAnimationPolicy policy) { edit_animation_policy_ = policy; }
  bool edits_animate(bool setting) const;  // under the policy, with View > Animate edits at `setting`
  const EditAnimator& edit_animator() const { return edit_animator_; }
  void advance_edit_animation(float frame_ms) { edit_animator_.advance(frame_ms / 1000.0); }

 private:
  void fit_camera(const BoundingBox& bounds) { camera_.fit(bounds); }
  // Gives the camera and the status bar the up axis of file_up_axis_ and up_axis_choice_; returns whether the camera's
  // axis changed (the view then needs a fit). Cannot fail.
  bool apply_up_axis() noexcept;
  void draw_mesh_view(const ViewMarks& marks);
  void draw_patch_view(const ViewMarks& marks);
  void apply_size_defaults();
  void take_pending_view();
  // The marks over the view (view_marks.cpp): the lesson's highlights and arrows, the repaired spots, the edit playing.
  void draw_lesson_marks(const LessonMarks& marks);
  void draw_lesson_arrows(const LessonMarks& marks);
  void draw_repair_spots(const RepairMarks& repairs);
  void draw_edit_animation();

  DocumentRoom& document_;
  ShaderLibrary shaders_;
  std::unique_ptr<MeshRenderer> mesh_renderer_;
  std::unique_ptr<MeshRenderer> patch_renderer_;
  std::unique_ptr<OverlayRenderer> overlay_renderer_;
  OrbitCamera camera_;
  ViewOptions view_options_;
  bool show_labels_ = true;
  LabelPlacement last_labels_;
  Theme theme_ = Theme::Dark;
  // The shown mesh's size class (apply_size_defaults): small enough for halfedge arrows by default (kArrowsMaxFaces),
  // for the wireframe by default (kWireframeMaxFaces: past it the lines of a fitted mesh cover its faces), dense, or
  // past RenderStyle::large_mesh_triangles. When it changes, the wireframe and the arrows take its defaults; the
  // quality then follows the frame time (app/view_quality.h).
  static constexpr size_t kArrowsMaxFaces = 300;
  static constexpr size_t kWireframeMaxFaces = 20000;
  enum class SizeClass { Unknown, Small, Medium, Dense, Large };
  SizeClass size_class_ = SizeClass::Unknown;
  ViewQuality view_quality_;                 // multisampling, wireframe and back sides by the measured frame time
  std::optional<ViewRequest> pending_view_;  // a lesson's view{...}, for the next mesh frame
  // Why the renderer refused the document's mesh (too large to draw) at this generation and version; "" when drawn.
  std::string undrawable_;
  uint64_t undrawable_generation_ = 0, undrawable_version_ = 0;
  ViewMode mode_ = ViewMode::Mesh;
  CurveEditorState curve_;
  PatchViewState patches_;
  BezierMine bezier_mine_;
  std::optional<FileUpAxis> file_up_axis_;
  UpAxisChoice up_axis_choice_ = UpAxisChoice::FromFile;
  StatusBarState status_bar_;
  ScreenRect view_rect_;  // the view in window coordinates (the layout's), and in framebuffer pixels from the top left
  struct PixelRect {
    int x = 0, y = 0, width = 1, height = 1;
  };
  PixelRect view_pixels_;
  int framebuffer_height_ = 1;
  glm::vec2 pixels_per_point_{1.0f, 1.0f};
  EditAnimationPolicy edit_animation_policy_ = EditAnimationPolicy::Never;
  EditAnimator edit_animator_;
};

}  // namespace meshedit
