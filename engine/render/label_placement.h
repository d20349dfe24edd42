// Label placement: puts text labels (id labels such as `v3`, a lesson's names such as `h0`) on screen beside their
// anchors so that no two overlap. Pure: no GL, no ImGui, unit-tested. The app measures the text, asks for places
// here and draws what comes back; labels.h makes the requests for the elements of a mesh.
//
// Coordinates are window pixels, top-left origin, x right, y down. A rectangle is the label's whole box: the text
// plus `LabelPlacementOptions::padding` on each side, which is what the app fills behind the text.
//
// Invariants of place_labels:
// - No two placed rectangles overlap (their interiors are disjoint, with `spacing` pixels between them), and every
//   placed rectangle lies inside `bounds`.
// - Priority: requests are placed greedily from the highest priority down; among equal priorities in request order
//   (a stable order, so the result depends only on the input). A label is never dropped to make room for a later
//   one: once placed it stays, so a higher-priority label is never dropped for a lower-priority one.
// - Candidates: each label tries a fixed list of positions around its anchor and takes the first that is free.
//   With a preferred direction d, a candidate box sits beside the anchor, `gap` pixels beyond it in direction d'
//   (measured to the box's nearest side), in this order: d turned by 0 and +-45 degrees; beside the anchor in
//   direction d but slid across d by one and two box widths either way (along the edge, for an edge's label); d
//   turned by +-90; further out along d and +-45; on the other side: 180, +-135, and slid by one box width. So the box
//   never covers its anchor. With no direction (d = 0, as for a face's centroid) the box is centred on the anchor
//   first, then moved a little up, down, left and right, then set beside the anchor in eight directions. A box's
//   top-left corner is rounded to a whole pixel (crisp text), which moves it by at most half a pixel. A candidate
//   that crosses the request's `keep_clear` segment (its own edge or arrow) is skipped, so an edge label never
//   covers its edge.
// - A label that fits nowhere is dropped and counted; its text is not shortened.
// - Cost: a uniform grid of placed boxes, so each candidate is tested only against the boxes near it.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "core/ids.h"

namespace meshedit {

struct LabelRect {
  glm::dvec2 min{0.0};
  glm::dvec2 max{0.0};

  double width() const { return max.x - min.x; }
  double height() const { return max.y - min.y; }
  glm::dvec2 centre() const { return (min + max) * 0.5; }
  bool contains(const glm::dvec2& p) const { return p.x >= min.x && p.x <= max.x && p.y >= min.y && p.y <= max.y; }
  bool inside(const LabelRect& outer) const {
    return min.x >= outer.min.x && min.y >= outer.min.y && max.x <= outer.max.x && max.y <= outer.max.y;
  }
  // True when the interiors intersect (rectangles that only touch do not overlap).
  bool overlaps(const LabelRect& o) const {
    return min.x < o.max.x && o.min.x < max.x && min.y < o.max.y && o.min.y < max.y;
  }
};

// A segment on screen (window pixels): a label's own edge or halfedge arrow, which its box must not cross.
struct LabelSegment {
  glm::dvec2 a{0.0};
  glm::dvec2 b{0.0};
};

// Where a label's text comes from: the element's id (`format_id`) or a lesson's label (LessonMarks::labels).
enum class LabelSource { Id, Lesson };

struct LabelRequest {
  ElementRef element;
  std::string text;
  LabelSource source = LabelSource::Id;
  glm::dvec2 anchor{0.0};     // the point the label belongs to (window pixels)
  glm::dvec2 direction{0.0};  // where the label prefers to sit from the anchor (any length; zero: on the anchor)
  glm::dvec2 text_size{0.0};  // the text's size in pixels, without padding
  int priority = 0;           // higher is placed first
  std::optional<LabelSegment> keep_clear;  // no candidate box may cross it
};

struct PlacedLabel {
  ElementRef element;
  std::string text;
  LabelSource source = LabelSource::Id;
  LabelRect rect;            // the whole box, padding included
  glm::dvec2 text_min{0.0};  // where the text's top-left corner goes
  size_t request = 0;        // index of the request it answers
};

// What one placement drew: the placed labels in placement order (priority, then request order) and how many
// requests found no free place.
struct LabelPlacement {
  std::vector<PlacedLabel> placed;
  size_t dropped = 0;
};

struct LabelPlacementOptions {
  glm::dvec2 padding{3.0, 1.0};  // box around the text, each side
  double gap = 3.0;              // between the anchor and a box set beside it
  double spacing = 1.0;          // kept free between two boxes
};

LabelPlacement place_labels(std::span<const LabelRequest> requests, const LabelRect& bounds,
                            const LabelPlacementOptions& options = {});

}  // namespace meshedit
