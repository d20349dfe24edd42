// Labels of a mesh's elements on screen: id labels (`v3`, `e5`, `f2`, `h12`) and a lesson's labels (any text on an
// element), with the anchor each belongs to and the side it prefers, made into requests for one placement
// (label_placement.h) that the app draws with ImGui. Pure: no GL, unit-tested.
//
// Anchors: a vertex at its position, an edge at its midpoint, a face at its centre (the corners'
// average), a halfedge at the middle of its arrow (mesh_geometry.h), so twins' labels sit on their own
// sides; a halfedge on a boundary loop (no arrow: no face to sit in) at its edge's midpoint.
//
// Preferred directions (label_direction, on screen): a vertex away from its neighbours (minus the sum of the unit
// directions to them: for a corner, the bisector of the angle outside it), so its label sits outside the corner; an
// edge perpendicular to it, away from its face when it has one face, towards the top of the screen when it has two;
// a halfedge perpendicular to its arrow, towards its face's centre (inside the face), or away from the mesh for one
// on a boundary loop; a face none (its label sits on its centre). When the screen gives no direction (a vertex amid
// a flat fan, an edge seen end on) a vertex or an edge prefers the top right.
// An edge's label keeps clear of its line, a halfedge's of its arrow (of its edge on a boundary loop): the requests'
// `keep_clear`.
//
// Id labels: a label is kept when its anchor is in front of the eye, inside the viewport, and its element
// faces the camera: a face (or a halfedge's face) whose normal points towards the eye, an edge or a
// vertex with such a face around it (or a vertex whose fan cannot be walked: a broken mesh still gets
// its labels). Occlusion by other parts of the mesh is not tested. Order: vertices, edges, faces,
// halfedges, each in id order; at most `max_labels` (the rest would be unreadable anyway).
//
// Requests (label_requests): the lesson's labels whose anchors are in front of the eye and inside the view (a lesson
// names what it wants seen; facing is not tested), then the id labels, with priorities: lesson labels first, then the
// selected element's id label, the hovered element's, the rest. The selected and hovered elements get their id label
// even when their kind is not shown (a halfedge without arrows), by the same visibility rules. An id label that would
// repeat a lesson label on the same element (the same text) is left out.
#pragma once

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/halfedge_mesh.h"
#include "render/camera.h"
#include "render/label_placement.h"

namespace meshedit {

struct ScreenLabel {
  ElementRef element;
  glm::dvec2 pixel{0.0};  // top-left origin
  std::string text;       // format_id(element)
};

struct LabelOptions {
  bool vertices = true;
  bool edges = true;
  bool faces = true;
  bool halfedges = false;
  size_t max_labels = 2000;
};

// Placement priorities (LabelRequest::priority): higher is placed first.
inline constexpr int kLessonLabelPriority = 3;
inline constexpr int kSelectedLabelPriority = 2;
inline constexpr int kHoveredLabelPriority = 1;
inline constexpr int kOtherLabelPriority = 0;

// Where the element's label goes in world space; nullopt for dead or unwalkable elements.
std::optional<glm::dvec3> label_anchor(const HalfedgeMesh& mesh, ElementRef element);
// The element's id label by the rules above, or nullopt when it is not visible.
std::optional<ScreenLabel> visible_label(const HalfedgeMesh& mesh, const OrbitCamera& camera, Viewport viewport,
                                         ElementRef element);
std::vector<ScreenLabel> visible_labels(const HalfedgeMesh& mesh, const OrbitCamera& camera, Viewport viewport,
                                        const LabelOptions& options = {});
// The side the element's label prefers, in framebuffer pixels (not normalised; zero for a face), or nullopt when
// the element has no anchor or its anchor is behind the eye.
std::optional<glm::dvec2> label_direction(const HalfedgeMesh& mesh, const OrbitCamera& camera, Viewport viewport,
                                          ElementRef element);

// The view on screen: its rectangle in window coordinates, and its framebuffer size, which the camera projects to.
// A framebuffer pixel p of the view is at window point window.min + p * (window size / framebuffer size).
struct LabelView {
  LabelRect window;
  Viewport framebuffer;

  glm::dvec2 scale() const;
  glm::dvec2 to_window(const glm::dvec2& pixel) const { return window.min + pixel * scale(); }
};

// The size of a text in window pixels (the app: ImGui::CalcTextSize).
using TextMeasure = std::function<glm::dvec2(const std::string&)>;

// What to label.
struct LabelScene {
  bool id_labels = true;  // false: the lesson's labels only
  LabelOptions ids;       // which kinds get id labels (the selected and hovered elements always do)
  std::span<const std::pair<ElementRef, std::string>> lesson;
  ElementRef selected;
  ElementRef hovered;
};

std::vector<LabelRequest> label_requests(const HalfedgeMesh& mesh, const OrbitCamera& camera, const LabelView& view,
                                         const LabelScene& scene, const TextMeasure& measure);

}  // namespace meshedit
