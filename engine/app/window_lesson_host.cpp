// WindowLessonHost: see window_lesson_host.h.
#include "app/window_lesson_host.h"

#include <algorithm>

#include "app/document_room.h"
#include "app/view_room.h"

namespace meshedit {

void WindowLessonHost::show_mesh(std::shared_ptr<HalfedgeMesh> mesh, std::optional<UpAxis> up) {
  if (!mesh) return;
  view_.show_lesson_mesh(*mesh, !shown_this_step_, up);
  shown_this_step_ = true;
}

void WindowLessonHost::show_curve(const BezierCurve& curve) { view_.show_curve(curve); }

void WindowLessonHost::show_patches(const std::vector<BezierPatch>& patches) { view_.show_patches(patches); }

void WindowLessonHost::highlight(ElementRef element, glm::vec3 colour) {
  marks_.highlights.emplace_back(element, colour);
}

void WindowLessonHost::label(ElementRef element, const std::string& text) { marks_.labels.emplace_back(element, text); }

void WindowLessonHost::arrow(const glm::dvec3& from, const glm::dvec3& to, glm::vec3 colour) {
  marks_.arrows.push_back({from, to, colour});
}

void WindowLessonHost::clear_annotations() {
  marks_ = {};
  shown_this_step_ = false;
}

void WindowLessonHost::camera(const CameraRequest& request) {
  if (request.reset) view_.reset_view();
  if (request.fit) view_.fit_camera();
  OrbitCamera& camera = view_.camera();
  if (request.yaw_degrees || request.pitch_degrees) {
    camera.set_angles(request.yaw_degrees.value_or(camera.yaw_degrees()),
                      request.pitch_degrees.value_or(camera.pitch_degrees()));
  }
  if (request.distance) camera.set_distance(*request.distance);
  if (request.target) camera.set_target(*request.target);
}

void WindowLessonHost::view(const ViewRequest& request) { view_.apply_view_request(request); }

std::shared_ptr<HalfedgeMesh> WindowLessonHost::current_mesh() const {
  if (view_.mode() != ViewMode::Mesh) return nullptr;
  return std::make_shared<HalfedgeMesh>(document_.doc().mesh);
}

ElementRef WindowLessonHost::current_selection() const { return document_.selection().selected; }

std::optional<CurveReading> WindowLessonHost::curve_reading() const {
  if (view_.mode() != ViewMode::Curve) return std::nullopt;
  const CurveEditorState& curve = view_.curve();
  return CurveReading{curve.t, curve.curve.control_points};
}

std::optional<PatchReading> WindowLessonHost::patch_reading() const {
  if (view_.mode() != ViewMode::Patches) return std::nullopt;
  const PatchViewState& patches = view_.patches();
  return PatchReading{patches.u, patches.v, static_cast<size_t>(std::max(patches.selected_patch, 0))};
}

}  // namespace meshedit
