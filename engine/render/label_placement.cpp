// Greedy label placement over a uniform grid of placed boxes (see label_placement.h).
#include "render/label_placement.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <glm/geometric.hpp>

namespace meshedit {
namespace {

constexpr double kCellSize = 64.0;  // pixels; a few labels per cell

// The placed boxes, bucketed by the grid cells they cover, for overlap queries near a candidate.
class BoxGrid {
 public:
  explicit BoxGrid(const LabelRect& bounds) : origin_(bounds.min) {
    columns_ = std::max(1, int(std::ceil(bounds.width() / kCellSize)));
    rows_ = std::max(1, int(std::ceil(bounds.height() / kCellSize)));
    cells_.resize(size_t(columns_) * size_t(rows_));
  }

  bool free(const LabelRect& box, const std::vector<LabelRect>& placed) const {
    bool clear = true;
    visit(box, [&](std::vector<uint32_t>& cell) {
      for (uint32_t i : cell) {
        if (placed[i].overlaps(box)) clear = false;
      }
    });
    return clear;
  }

  void add(const LabelRect& box, uint32_t index) {
    visit(box, [&](std::vector<uint32_t>& cell) { cell.push_back(index); });
  }

 private:
  template <class Fn>
  void visit(const LabelRect& box, Fn&& fn) const {
    const int x0 = cell_of(box.min.x - origin_.x, columns_), x1 = cell_of(box.max.x - origin_.x, columns_);
    const int y0 = cell_of(box.min.y - origin_.y, rows_), y1 = cell_of(box.max.y - origin_.y, rows_);
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) fn(cells_[size_t(y) * size_t(columns_) + size_t(x)]);
    }
  }
  static int cell_of(double offset, int count) { return std::clamp(int(std::floor(offset / kCellSize)), 0, count - 1); }

  glm::dvec2 origin_;
  int columns_ = 1, rows_ = 1;
  mutable std::vector<std::vector<uint32_t>> cells_;
};

glm::dvec2 turned(const glm::dvec2& d, double degrees) {
  const double a = degrees * (3.14159265358979323846 / 180.0);
  const double c = std::cos(a), s = std::sin(a);
  return {d.x * c - d.y * s, d.x * s + d.y * c};
}

// Boxes start on whole pixels, so the text is drawn crisp.
LabelRect box_at(const glm::dvec2& centre, const glm::dvec2& half) {
  const glm::dvec2 min = glm::floor(centre - half + 0.5);
  return {min, min + 2.0 * half};
}

// The box of half-size `half` beside `anchor` in unit direction u: `distance` pixels beyond the anchor, measured to
// the box's nearest side (the box's support along u), so the anchor stays outside it.
LabelRect box_beside(const glm::dvec2& anchor, const glm::dvec2& u, const glm::dvec2& half, double distance) {
  const double support = std::abs(u.x) * half.x + std::abs(u.y) * half.y;
  return box_at(anchor + u * (distance + support), half);
}

// The candidate boxes of one label, best first (the order label_placement.h describes).
std::vector<LabelRect> candidates(const LabelRequest& request, const glm::dvec2& half,
                                  const LabelPlacementOptions& options) {
  std::vector<LabelRect> boxes;
  const glm::dvec2& a = request.anchor;
  const double length = glm::length(request.direction);
  if (length > 1e-9 && std::isfinite(length)) {
    const glm::dvec2 u = request.direction / length;
    const glm::dvec2 side(-u.y, u.x);  // across the preferred direction (along an edge, for an edge's label)
    const double near = options.gap;
    const double far = options.gap + 2.0 * half.y;
    // One box further across: the box's width measured across, and the gap.
    const double slide = 2.0 * (std::abs(side.x) * half.x + std::abs(side.y) * half.y) + options.gap;
    for (double degrees : {0.0, 45.0, -45.0}) boxes.push_back(box_beside(a, turned(u, degrees), half, near));
    for (double steps : {1.0, -1.0, 2.0, -2.0}) boxes.push_back(box_beside(a + side * (steps * slide), u, half, near));
    for (double degrees : {90.0, -90.0}) boxes.push_back(box_beside(a, turned(u, degrees), half, near));
    for (double degrees : {0.0, 45.0, -45.0}) boxes.push_back(box_beside(a, turned(u, degrees), half, far));
    for (double degrees : {180.0, 135.0, -135.0}) boxes.push_back(box_beside(a, turned(u, degrees), half, near));
    for (double steps : {1.0, -1.0}) boxes.push_back(box_beside(a - side * (steps * slide), -u, half, near));
    return boxes;
  }
  boxes.push_back(box_at(a, half));
  boxes.push_back(box_at(a + glm::dvec2(0.0, -1.6 * half.y), half));
  boxes.push_back(box_at(a + glm::dvec2(0.0, 1.6 * half.y), half));
  boxes.push_back(box_at(a + glm::dvec2(-1.2 * half.x, 0.0), half));
  boxes.push_back(box_at(a + glm::dvec2(1.2 * half.x, 0.0), half));
  for (int i = 0; i < 8; ++i) boxes.push_back(box_beside(a, turned({0.0, -1.0}, 45.0 * i), half, options.gap));
  return boxes;
}

bool finite(const glm::dvec2& p) { return std::isfinite(p.x) && std::isfinite(p.y); }

// Whether the segment meets the box (touching counts), by clipping it to the box's four sides (Liang-Barsky).
bool crosses(const LabelRect& box, const LabelSegment& segment) {
  const glm::dvec2 d = segment.b - segment.a;
  double enter = 0.0, leave = 1.0;
  // Keeps the part of the segment where p * t <= q.
  auto clip = [&](double p, double q) {
    if (p == 0.0) return q >= 0.0;
    const double t = q / p;
    if (p < 0.0) enter = std::max(enter, t);
    else leave = std::min(leave, t);
    return enter <= leave;
  };
  return clip(-d.x, segment.a.x - box.min.x) && clip(d.x, box.max.x - segment.a.x) &&
         clip(-d.y, segment.a.y - box.min.y) && clip(d.y, box.max.y - segment.a.y);
}

}  // namespace

LabelPlacement place_labels(std::span<const LabelRequest> requests, const LabelRect& bounds,
                            const LabelPlacementOptions& options) {
  LabelPlacement result;
  std::vector<size_t> order(requests.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return requests[a].priority > requests[b].priority; });

  BoxGrid grid(bounds);
  std::vector<LabelRect> placed;  // as tested: each box grown by half the spacing on every side
  const glm::dvec2 margin(options.spacing * 0.5);
  for (size_t index : order) {
    const LabelRequest& request = requests[index];
    const glm::dvec2 half = glm::max(request.text_size, glm::dvec2(0.0)) * 0.5 + options.padding;
    bool done = false;
    if (finite(request.anchor) && finite(half)) {
      for (const LabelRect& box : candidates(request, half, options)) {
        const LabelRect spaced{box.min - margin, box.max + margin};
        if (!box.inside(bounds) || !grid.free(spaced, placed)) continue;
        if (request.keep_clear && crosses(box, *request.keep_clear)) continue;
        grid.add(spaced, uint32_t(placed.size()));
        placed.push_back(spaced);
        result.placed.push_back({request.element, request.text, request.source, box, box.min + options.padding, index});
        done = true;
        break;
      }
    }
    if (!done) ++result.dropped;
  }
  return result;
}

}  // namespace meshedit
