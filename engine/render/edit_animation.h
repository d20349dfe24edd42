// EditAnimation: what the mesh view draws over the mesh while a flip, split or collapse plays, so a student sees the
// edge turn, the new vertex appear or the two ends meet. A pure function of the edit's geometry and the time: no GL,
// no mesh, unit-tested; the window (app/edit_animator.h) times it and hands the overlay to the OverlayRenderer.
//
// The pictures, named as in core/mesh_ops.h, at progress p (0: as before the operation, 1: as after it):
// - flip: the edge a-b turns inside the quad a, d, b, c into d-c, its end at a sliding along the side a-d to d and
//   its end at b along b-c to c (a counter-clockwise turn, as flip makes it). Each end is a convex combination of two
//   corners of the quad, so the moving edge never leaves it.
// - split: the new vertex m grows from nothing at the midpoint of a-b (it moves from there to m, where split puts it
//   anyway), and its new edges grow out of it to their far ends (c, and d when the edge had two faces).
// - collapse: the ends a and b slide together to where they meet, pulling their edges with them (every edge of a and
//   of b, drawn from the moving end to its fixed far end), while the edge a-b between them shrinks to nothing.
//
// Invariants:
// - The time t is clamped to [0, 1] (NaN counts as 0) and eased (ease_in_out: slow start and end, symmetric:
//   ease(1 - t) = 1 - ease(t)). Forward play shows progress ease(t); backward play (an undo) shows ease(1 - t): the
//   same pictures, run back.
// - Forward at t = 1 and backward at t = 0 show the mesh after the operation; forward at t = 0 and backward at t = 1
//   the mesh before it (for a split: nothing; its edge a-b is the mesh's own).
// - Lines and points are drawn on top of the mesh (depth ignored) in the look's colour; a line of zero length and a
//   point of zero size are left out, so an overlay holds only what can be seen.
#pragma once

#include <variant>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "render/overlay_renderer.h"

namespace meshedit {

// How long an edit plays in the window, in seconds.
inline constexpr double kEditAnimationSeconds = 0.25;

struct FlipMotion {
  glm::dvec3 a{0.0}, b{0.0};  // the edge's ends before
  glm::dvec3 c{0.0}, d{0.0};  // where they go: a slides to d, b to c
};

struct SplitMotion {
  glm::dvec3 a{0.0}, b{0.0};              // the split edge's ends
  glm::dvec3 m{0.0};                      // the new vertex
  std::vector<glm::dvec3> new_edge_ends;  // the far ends of m's edges that are not halves of a-b (c, d)
};

struct CollapseMotion {
  glm::dvec3 a{0.0}, b{0.0};             // the collapsing edge's ends
  glm::dvec3 meet{0.0};                  // where they meet (the surviving vertex's position after)
  std::vector<glm::dvec3> a_neighbours;  // the far ends of a's other edges, before
  std::vector<glm::dvec3> b_neighbours;  // the far ends of b's other edges, before
};

using EditMotion = std::variant<FlipMotion, SplitMotion, CollapseMotion>;

enum class PlayDirection { Forward, Backward };  // Backward: an undo, from the operation's result back to its start

struct EditAnimation {
  EditMotion motion;
  PlayDirection direction = PlayDirection::Forward;
};

struct EditAnimationLook {
  glm::vec4 colour{1.0f, 0.55f, 0.1f, 1.0f};  // the view's "changed" colour (RenderStyle::changed)
  float line_width = 4.0f;                    // framebuffer pixels
  float point_size = 11.0f;
};

// Smoothstep of t clamped to [0, 1]: 0 at 0, 1/2 at 1/2, 1 at 1, flat at both ends.
double ease_in_out(double t);
// How far along the operation the picture is at time t in [0, 1] (clamped) of the animation (see the invariants).
double operation_progress(double t, PlayDirection direction);
// The overlay at progress p in [0, 1] (clamped) of the operation.
Overlay edit_overlay(const EditMotion& motion, double progress, const EditAnimationLook& look);
// The overlay at time t in [0, 1] of the animation: edit_overlay at operation_progress(t, direction).
Overlay edit_animation_frame(const EditAnimation& animation, double t, const EditAnimationLook& look);

}  // namespace meshedit
