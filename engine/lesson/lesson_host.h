// LessonHost: everything a lesson can ask of the application, and nothing else. The window implements it
// with its document, views and camera; HeadlessHost (headless_host.h) records the calls for tests and for
// `meshedit lesson FILE --headless`.
//
// Invariants (what every implementation keeps, so a lesson behaves the same in the window and headless):
// - The runner calls these only from inside LessonRunner's own calls (load/next/back/reload/update/deliver),
//   never from another thread. A host must not call back into the runner from inside one of these.
// - show_mesh receives the lesson's own mesh (the object the script holds): the lesson may keep changing it
//   after the call. A host that wants a stable picture copies it; the lesson calls show() again after a
//   change it wants seen.
// - current_mesh() returns a copy (or nullptr when no mesh is on screen): the app's document owns its mesh,
//   and a script must never hold a pointer into it.
// - Highlights, labels and arrows belong to the current step: the runner calls clear_annotations() when a step
//   starts (Next, Back, reload), so each step rebuilds its own marks. What is shown (mesh, curve,
//   patches) stays until a step shows something else.
// - Element references are ids of the mesh on screen (format_id prints them: v12 h37 e5 f3 b0); a host
//   ignores ids that are not in its mesh rather than failing.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/bezier.h"
#include "core/halfedge_mesh.h"
#include "core/ids.h"
#include "core/up_axis.h"

namespace meshedit {

// What `camera{...}` asks for. Several fields may be set together; the host applies reset, then fit, then
// the orbit values that are present.
struct CameraRequest {
  bool reset = false;                   // back to the default view
  bool fit = false;                     // frame everything shown
  std::optional<double> yaw_degrees;    // orbit angle around the up axis
  std::optional<double> pitch_degrees;  // angle above the horizon
  std::optional<double> distance;       // from the target
  std::optional<glm::dvec3> target;     // the point the camera orbits
};

// What `view{...}` asks for: each field present turns that part of the mesh view on or off; absent fields keep
// what the student chose. The mesh's own size class sets them again when it changes (a subdivision, another mesh).
// What the curve view shows, for a lesson that reads it (curve_t(), curve_points()).
struct CurveReading {
  double t = 0.5;                          // the curve view's t, in [0, 1]
  std::vector<glm::dvec2> control_points;  // as the student left them (dragged, added, removed)
};

// What the patch view shows, for a lesson that reads it (patch_uv()).
struct PatchReading {
  double u = 0.5;  // the (u, v) probe, each in [0, 1]
  double v = 0.5;
  size_t selected_patch = 0;  // the probed patch's index in the shown list
};

struct ViewRequest {
  std::optional<bool> halfedges;  // the halfedge arrows inside their faces
  std::optional<bool> wireframe;
  std::optional<bool> vertices;
  std::optional<bool> labels;   // the id labels (v3, e5, h12...)
  std::optional<bool> curve;    // the curve view's whole curve (its key C)
  std::optional<bool> tangent;  // the curve view's tangent arrow at C(t)
};

class LessonHost {
 public:
  virtual ~LessonHost() = default;

  // ---- what is on screen ----
  // `up`: the axis shown pointing up (a mesh read from a Y-up file); none: Z, as every mesh MeshEdit makes.
  virtual void show_mesh(std::shared_ptr<HalfedgeMesh> mesh, std::optional<UpAxis> up = std::nullopt) = 0;
  virtual void show_curve(const BezierCurve& curve) = 0;
  virtual void show_patches(const std::vector<BezierPatch>& patches) = 0;

  // ---- marks on the shown mesh (colour components in [0, 1]) ----
  virtual void highlight(ElementRef element, glm::vec3 colour) = 0;
  virtual void label(ElementRef element, const std::string& text) = 0;
  // An arrow from `from` to `to` (the shown mesh's coordinates), drawn over the mesh view.
  virtual void arrow(const glm::dvec3& from, const glm::dvec3& to, glm::vec3 colour) = 0;
  // Removes every highlight, label and arrow.
  virtual void clear_annotations() = 0;

  virtual void camera(const CameraRequest& request) = 0;
  virtual void view(const ViewRequest& request) = 0;

  // ---- what the student sees and has done ----
  // A copy of the mesh on screen (with the student's edits), or nullptr when none is shown.
  virtual std::shared_ptr<HalfedgeMesh> current_mesh() const = 0;
  // The selected element, or an invalid ElementRef when nothing is selected.
  virtual ElementRef current_selection() const = 0;
  // The curve view's t and control points, or nullopt when the curve view is not on screen.
  virtual std::optional<CurveReading> curve_reading() const = 0;
  // The patch view's probe, or nullopt when the patch view is not on screen.
  virtual std::optional<PatchReading> patch_reading() const = 0;
};

}  // namespace meshedit
