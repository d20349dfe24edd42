// Point-set comparison for peer_bench (see peer_match.h): a sorted grid of the other contender's vertices,
// looked up from each of ours, with a one-to-one check so two of ours cannot claim the same vertex.
#include "bench/peer_match.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <tuple>

#include <glm/geometric.hpp>

namespace meshedit::bench {
namespace {

struct Cell {
  int64_t x, y, z;
  auto operator<=>(const Cell&) const = default;
};

// Points sorted by grid cell; `in(cell)` lists the indices of the points in it.
class Grid {
 public:
  Grid(const std::vector<glm::dvec3>& points, double cell_size) : size_(cell_size) {
    entries_.reserve(points.size());
    for (size_t i = 0; i < points.size(); ++i) entries_.push_back({cell_of(points[i]), static_cast<uint32_t>(i)});
    std::sort(entries_.begin(), entries_.end(),
              [](const Entry& a, const Entry& b) { return std::tie(a.cell, a.index) < std::tie(b.cell, b.index); });
  }
  Cell cell_of(const glm::dvec3& p) const {
    return {int64_t(std::floor(p.x / size_)), int64_t(std::floor(p.y / size_)), int64_t(std::floor(p.z / size_))};
  }
  template <class Fn>
  void for_each_in(const Cell& cell, Fn&& fn) const {
    auto it = std::lower_bound(entries_.begin(), entries_.end(), cell,
                               [](const Entry& e, const Cell& c) { return e.cell < c; });
    for (; it != entries_.end() && it->cell == cell; ++it) fn(it->index);
  }

 private:
  struct Entry {
    Cell cell;
    uint32_t index;
  };
  double size_;
  std::vector<Entry> entries_;
};

std::string point_text(const glm::dvec3& p) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.12g, %.12g, %.12g)", p.x, p.y, p.z);
  return text;
}

}  // namespace

MatchReport match_vertices(const VertexData& ours, const VertexData& theirs, const MatchOptions& options) {
  MatchReport report;
  if (!options.skip && ours.position.size() != theirs.position.size()) {
    report.problem =
        std::to_string(theirs.position.size()) + " vertices instead of " + std::to_string(ours.position.size());
    return report;
  }
  double scale = 0.0;
  for (const glm::dvec3& p : ours.position) scale = std::max(scale, glm::length(p));
  scale = std::max(scale, 1e-300);
  const double tol = options.position_tolerance * scale;
  const double cell = std::max(1000.0 * tol, 1e-12 * scale);  // >= 2 tol: a match is at most one cell over
  const Grid grid(theirs.position, cell);

  std::vector<unsigned char> used(theirs.position.size(), 0);
  size_t failures = 0;
  auto fail = [&](const std::string& message) {
    if (failures++ == 0) report.problem = message;
  };
  for (size_t i = 0; i < ours.position.size(); ++i) {
    if (options.skip && (*options.skip)[i]) continue;
    ++report.compared;
    const glm::dvec3& p = ours.position[i];
    const Cell lo = grid.cell_of(p - glm::dvec3(tol)), hi = grid.cell_of(p + glm::dvec3(tol));
    double best = 1e300;
    uint32_t best_index = 0;
    for (int64_t x = lo.x; x <= hi.x; ++x)
      for (int64_t y = lo.y; y <= hi.y; ++y)
        for (int64_t z = lo.z; z <= hi.z; ++z)
          grid.for_each_in({x, y, z}, [&](uint32_t j) {
            const double d = glm::length(theirs.position[j] - p);
            if (d < best) best = d, best_index = j;
          });
    if (best > tol) {
      char text[160];
      std::snprintf(text, sizeof text, "no vertex within %g x |p|max of ours %s (nearest at %.3g x |p|max)",
                    options.position_tolerance, point_text(p).c_str(), best / scale);
      fail(text);
      continue;
    }
    report.max_position_error = std::max(report.max_position_error, best / scale);
    if (used[best_index]++) {
      fail("two of ours match its vertex " + point_text(theirs.position[best_index]));
      continue;
    }
    if (ours.on_boundary[i] != theirs.on_boundary[best_index]) {
      fail(std::string("vertex ") + point_text(p) + (ours.on_boundary[i] ? " is" : " is not") +
           " on the boundary in ours but not there");
      continue;
    }
    const double normal_error = glm::length(ours.normal[i] - theirs.normal[best_index]);
    report.max_normal_error = std::max(report.max_normal_error, normal_error);
    if (!(normal_error <= options.normal_tolerance)) {
      char text[160];
      std::snprintf(text, sizeof text, "normal at %s differs from ours by %.3g", point_text(p).c_str(), normal_error);
      fail(text);
    }
  }
  if (failures > 1) report.problem += " (and " + std::to_string(failures - 1) + " more vertices)";
  report.ok = failures == 0;
  return report;
}

std::vector<unsigned char> near_boundary(const VertexData& ours, double radius) {
  std::vector<glm::dvec3> rim;
  for (size_t i = 0; i < ours.position.size(); ++i)
    if (ours.on_boundary[i]) rim.push_back(ours.position[i]);
  std::vector<unsigned char> near(ours.position.size(), 0);
  if (rim.empty()) return near;
  const Grid grid(rim, radius);
  for (size_t i = 0; i < ours.position.size(); ++i) {
    const glm::dvec3& p = ours.position[i];
    const Cell c = grid.cell_of(p);
    for (int64_t dx = -1; dx <= 1 && !near[i]; ++dx)
      for (int64_t dy = -1; dy <= 1 && !near[i]; ++dy)
        for (int64_t dz = -1; dz <= 1 && !near[i]; ++dz)
          grid.for_each_in({c.x + dx, c.y + dy, c.z + dz}, [&](uint32_t j) {
            if (glm::length(rim[j] - p) <= radius) near[i] = 1;
          });
  }
  return near;
}

double longest_edge(const PolygonMesh& triangles) {
  double longest = 0.0;
  for (size_t f = 0; f < triangles.num_faces(); ++f) {
    const auto c = triangles.face(f);
    for (size_t k = 0; k < c.size(); ++k) {
      const double d = glm::length(triangles.positions[c[k]] - triangles.positions[c[(k + 1) % c.size()]]);
      longest = std::max(longest, d);
    }
  }
  return longest;
}

}  // namespace meshedit::bench
