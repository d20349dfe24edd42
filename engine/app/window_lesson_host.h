// WindowLessonHost: what a lesson asks of the window (lesson_host.h), done with the window's open document
// (DocumentRoom) and its views and camera (ViewRoom).
//
// Invariants:
// - show_mesh copies the lesson's mesh into the document (the document owns what the window edits; the
//   lesson keeps its own object). The first show of a step fits the camera; later shows in the same step keep
//   the student's view.
// - Highlights, labels and arrows live in LessonMarks until clear_annotations() (each step start); ids that are not
//   in the shown mesh are kept but draw nothing. Arrows are drawn over the mesh view and the patch view.
// - curve_reading() reads the curve view the student sees (its t and control points) while it is on screen, and
//   patch_reading() the patch view's (u, v) probe while the patch view is.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/lesson_marks.h"
#include "lesson/lesson_host.h"

namespace meshedit {

class DocumentRoom;
class ViewRoom;

class WindowLessonHost : public LessonHost {
 public:
  WindowLessonHost(DocumentRoom& document, ViewRoom& view) : document_(document), view_(view) {}

  void show_mesh(std::shared_ptr<HalfedgeMesh> mesh, std::optional<UpAxis> up) override;
  void show_curve(const BezierCurve& curve) override;
  void show_patches(const std::vector<BezierPatch>& patches) override;
  void highlight(ElementRef element, glm::vec3 colour) override;
  void label(ElementRef element, const std::string& text) override;
  void arrow(const glm::dvec3& from, const glm::dvec3& to, glm::vec3 colour) override;
  void clear_annotations() override;
  void camera(const CameraRequest& request) override;
  void view(const ViewRequest& request) override;
  std::shared_ptr<HalfedgeMesh> current_mesh() const override;
  ElementRef current_selection() const override;
  std::optional<CurveReading> curve_reading() const override;
  std::optional<PatchReading> patch_reading() const override;

  const LessonMarks& marks() const { return marks_; }

 private:
  DocumentRoom& document_;
  ViewRoom& view_;
  LessonMarks marks_;
  bool shown_this_step_ = false;
};

}  // namespace meshedit
