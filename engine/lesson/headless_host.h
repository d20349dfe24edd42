// HeadlessHost: a LessonHost without a window. It records every call as one line of text (for tests and for
// `meshedit lesson --headless`) and keeps the scene a window would show, so tests can assert on both the
// sequence of requests and the resulting state.
//
// Invariants:
// - calls() holds one line per LessonHost call, in order: "show_mesh (8 vertices, 18 edges, 12 faces)",
//   "show_curve 4 points", "show_patches 32", "highlight e7 #ff8000", "label v0 \"apex\"",
//   "clear_annotations", "camera fit", "camera yaw=30 pitch=20 distance=4 target=(0, 0, 0)",
//   "view halfedges=on labels=off".
// - The screen mesh is a copy taken when show_mesh is called (as the window's document would be); the
//   pointer the lesson passed is kept too (shown_mesh()). set_current_mesh replaces the screen mesh, the
//   way a student's edit in the window would. Showing a mesh clears the selection; showing a curve or
//   patches removes the screen mesh.
// - current_mesh() always returns a fresh copy, so the runner and a lesson can never change this host's
//   state through it.
// - The curve view's t starts at 0.5 with each shown curve, as the window's does; set_curve_t clamps it to [0, 1] and
//   ignores NaN, as the window's slider. curve_reading() is nullopt while no curve is shown. Likewise the patch view's
//   probe starts at (0.5, 0.5) with each shown set of patches (set_patch_uv), and patch_reading() is nullopt while
//   none is shown.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "lesson/lesson_host.h"

namespace meshedit {

class HeadlessHost : public LessonHost {
 public:
  void show_mesh(std::shared_ptr<HalfedgeMesh> mesh, std::optional<UpAxis> up) override;
  void show_curve(const BezierCurve& curve) override;
  void show_patches(const std::vector<BezierPatch>& patches) override;
  void highlight(ElementRef element, glm::vec3 colour) override;
  void label(ElementRef element, const std::string& text) override;
  void arrow(const glm::dvec3& from, const glm::dvec3& to, glm::vec3 colour) override;
  void clear_annotations() override;
  void camera(const CameraRequest& request) override;
  void view(const ViewRequest& request) override;  // recorded as "view halfedges=on wireframe=off
  std::shared_ptr<HalfedgeMesh> current_mesh() const override;
  ElementRef current_selection() const override { return selection_; }
  std::optional<CurveReading> curve_reading() const override;
  std::optional<PatchReading> patch_reading() const override;

  // ---- what a test (or the headless command) does in the student's place ----
  void set_current_mesh(std::shared_ptr<HalfedgeMesh> mesh) { screen_mesh_ = std::move(mesh); }
  void set_selection(ElementRef element) { selection_ = element; }
  void set_curve_t(double t);
  void set_patch_uv(double u, double v);  // each clamped to [0, 1]; NaN ignored, as the patch view's sliders

  // ---- what was asked ----
  const std::vector<std::string>& calls() const { return calls_; }
  void clear_calls() { calls_.clear(); }
  // The mesh object the lesson passed to the last show_mesh (nullptr if none, or after a curve/patches).
  const std::shared_ptr<HalfedgeMesh>& shown_mesh() const { return shown_mesh_; }
  // The screen mesh itself (not a copy), for assertions.
  const HalfedgeMesh* screen_mesh() const { return screen_mesh_.get(); }
  const std::optional<BezierCurve>& shown_curve() const { return curve_; }
  const std::vector<BezierPatch>& shown_patches() const { return patches_; }
  const std::map<ElementRef, glm::vec3>& highlights() const { return highlights_; }
  const std::map<ElementRef, std::string>& labels() const { return labels_; }
  struct Arrow {
    glm::dvec3 from, to;
    glm::vec3 colour;
  };
  const std::vector<Arrow>& arrows() const { return arrows_; }
  const std::vector<CameraRequest>& camera_requests() const { return cameras_; }

 private:
  std::vector<std::string> calls_;
  std::shared_ptr<HalfedgeMesh> shown_mesh_;
  std::shared_ptr<HalfedgeMesh> screen_mesh_;
  std::optional<BezierCurve> curve_;
  std::vector<BezierPatch> patches_;
  std::map<ElementRef, glm::vec3> highlights_;
  std::map<ElementRef, std::string> labels_;
  std::vector<Arrow> arrows_;
  double curve_t_ = 0.5;
  PatchReading patch_probe_;
  std::vector<CameraRequest> cameras_;
  ElementRef selection_;
};

// "#ff8000": each component clamped to [0, 1] and rounded to 0..255.
std::string colour_hex(glm::vec3 colour);

}  // namespace meshedit
