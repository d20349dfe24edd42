// ViewRoom: what goes on screen (see view_room.h). The take_* steps end opening a file or showing a lesson's mesh,
// once everything that can fail was made: the document takes the mesh, the view mode and the state change by moves,
// the camera takes the file's up axis and is fitted to bounds read from the mesh. The renderer comes last: it is a
// view that every frame updates from the document, so when it cannot take the new mesh at once (memory ran out, a mesh
// too large to draw) it drops what it showed and the next frame tries again, under the frame guard.
#include <utility>

#include "app/document_room.h"
#include "app/view_room.h"
#include "render/mesh_geometry.h"

namespace meshedit {
namespace {

// Has `renderer` show `mesh` now, so that a pick before the next frame draws finds the new mesh. When it cannot, it
// shows nothing (and picks nothing) until the next frame's update, which tries again under the frame guard.
void refresh_view(MeshRenderer& renderer, const HalfedgeMesh& mesh) noexcept {
  try {
    renderer.update(mesh);
  } catch (const std::exception&) {
    renderer.invalidate();
  }
}

}  // namespace

void ViewRoom::take_mesh(HalfedgeMesh&& mesh, std::string&& name, bool fit) noexcept {
  const BoundingBox bounds = mesh_bounds(mesh);  // what the renderer's bounds will be, read before the move
  document_.take_mesh(std::move(mesh), std::move(name));
  mode_ = ViewMode::Mesh;
  if (apply_up_axis()) fit = true;  // a view turned to a new up axis is fitted again
  if (fit) fit_camera(bounds);
  refresh_view(*mesh_renderer_, document_.doc().mesh);
}

void ViewRoom::take_made_mesh(HalfedgeMesh&& mesh, std::string&& name) noexcept {
  file_up_axis_.reset();
  take_mesh(std::move(mesh), std::move(name));
}

void ViewRoom::take_curve(CurveEditorState&& curve) noexcept {
  curve_ = std::move(curve);
  mode_ = ViewMode::Curve;
}

void ViewRoom::take_patches(PatchViewState&& patches) noexcept {
  patches_ = std::move(patches);
  mode_ = ViewMode::Patches;
  apply_up_axis();
  if (!patches_.tessellation.mesh) return;
  fit_camera(mesh_bounds(*patches_.tessellation.mesh));
  refresh_view(*patch_renderer_, *patches_.tessellation.mesh);
}

void ViewRoom::set_file_up_axis(std::optional<FileUpAxis> up) noexcept {
  file_up_axis_ = up;
  up_axis_choice_ = UpAxisChoice::FromFile;
}

void ViewRoom::show_lesson_mesh(const HalfedgeMesh& mesh, bool fit, std::optional<UpAxis> up) {
  HalfedgeMesh copy = mesh;  // the one step that can fail: the window is as it was when it does
  // Core's primitives are Z-up; a mesh the lesson read from a file is shown as the lesson says its file is.
  if (up) file_up_axis_ = FileUpAxis{*up, UpAxisSource::Lesson};
  else file_up_axis_.reset();
  take_mesh(std::move(copy), std::string(), fit || mode_ != ViewMode::Mesh);
}

void ViewRoom::show_curve(const BezierCurve& curve) { take_curve(make_curve_editor(curve)); }

void ViewRoom::show_patches(const std::vector<BezierPatch>& patches) {
  PatchViewState view = make_patch_view(patches);
  update_tessellation(view);
  file_up_axis_.reset();
  take_patches(std::move(view));
}

}  // namespace meshedit
