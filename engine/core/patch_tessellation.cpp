// Patch tessellation with welding (contract and numbering in patch_tessellation.h).
//
// Three passes: sample and weld through a grid hash, emit grid triangles dropping those welding made
// degenerate, then split each vertex whose triangles form more than one fan (fans join only through
// edges a half-edge mesh can twin), so surfaces that merely touch, stack on one edge or disagree on
// orientation come apart instead of making the half-edge builder refuse the whole mesh.
#include "core/patch_tessellation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string>
#include <unordered_map>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "core/finite.h"
#include "core/mesh_error.h"

namespace meshedit {
namespace {

constexpr double kRelativeWeldTolerance = 1e-9;

struct CellKey {
  int64_t x, y, z;
  friend bool operator==(const CellKey& a, const CellKey& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }
};

struct CellKeyHash {
  size_t operator()(const CellKey& k) const noexcept {
    uint64_t h = static_cast<uint64_t>(k.x) * 0x9E3779B97F4A7C15ull;
    h ^= static_cast<uint64_t>(k.y) * 0xC2B2AE3D27D4EB4Full + (h << 6) + (h >> 2);
    h ^= static_cast<uint64_t>(k.z) * 0x165667B19E3779F9ull + (h << 6) + (h >> 2);
    return static_cast<size_t>(h);
  }
};

// Merges points closer than `tolerance` to an earlier kept point. Cells are `tolerance` wide and measured
// from the bounding box's minimum corner, so cell coordinates stay below 1/kRelativeWeldTolerance and fit
// int64 whatever the model's offset from the origin.
class Welder {
 public:
  Welder(const glm::dvec3& origin, double tolerance)
      : origin_(origin), tolerance_(tolerance), cell_size_(tolerance > 0.0 ? tolerance : 1.0) {}

  // The lowest id within tolerance, or a new vertex.
  uint32_t add(const glm::dvec3& p, std::vector<glm::dvec3>& positions) {
    if (!finite(p)) return push(p, positions);
    const CellKey key = cell_of(p);
    uint32_t best = kInvalidIndex;
    for (int64_t dx = -1; dx <= 1; ++dx) {
      for (int64_t dy = -1; dy <= 1; ++dy) {
        for (int64_t dz = -1; dz <= 1; ++dz) {
          auto found = cells_.find({key.x + dx, key.y + dy, key.z + dz});
          if (found == cells_.end()) continue;
          for (uint32_t i = found->second.head; i != kInvalidIndex && i < best; i = next_in_cell_[i]) {
            const glm::dvec3 d = positions[i] - p;
            if (glm::dot(d, d) <= tolerance_ * tolerance_) best = i;
          }
        }
      }
    }
    if (best != kInvalidIndex) return best;
    const uint32_t id = push(p, positions);
    // Appending keeps each cell's list in ascending id order, so the scan above can stop early.
    auto [cell, inserted] = cells_.try_emplace(key, Cell{id, id});
    if (!inserted) {
      next_in_cell_[cell->second.tail] = id;
      cell->second.tail = id;
    }
    return id;
  }

 private:
  // Clamped so that a bounding box too large for its own diagonal (tolerance 0, cell 1) cannot overflow
  // the cast; clamped points share a cell and are still compared exactly.
  CellKey cell_of(const glm::dvec3& p) const {
    const glm::dvec3 c = glm::clamp(glm::floor((p - origin_) / cell_size_), -kCellLimit, kCellLimit);
    return {static_cast<int64_t>(c.x), static_cast<int64_t>(c.y), static_cast<int64_t>(c.z)};
  }
  static constexpr double kCellLimit = 1e18;
  uint32_t push(const glm::dvec3& p, std::vector<glm::dvec3>& positions) {
    positions.push_back(p);
    next_in_cell_.push_back(kInvalidIndex);
    return static_cast<uint32_t>(positions.size() - 1);
  }

  glm::dvec3 origin_;
  double tolerance_;
  double cell_size_;
  struct Cell {
    uint32_t head, tail;  // first and last kept point in the cell
  };
  std::unordered_map<CellKey, Cell, CellKeyHash> cells_;
  std::vector<uint32_t> next_in_cell_;  // per kept point: the next kept point in the same cell
};

using Triangle = std::array<uint32_t, 3>;

uint32_t find_root(std::vector<uint32_t>& parent, uint32_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// For each corner edge (triangle f, edge k from corner k to corner k+1): does it join exactly two
// triangles that use it in opposite directions? Only such edges can become a twin pair.
std::vector<uint8_t> manifold_edges(const std::vector<Triangle>& triangles) {
  struct Use {
    uint32_t lo, hi, corner_edge;
    bool forward;  // lo -> hi
  };
  std::vector<Use> uses;
  uses.reserve(triangles.size() * 3);
  for (uint32_t f = 0; f < triangles.size(); ++f) {
    for (uint32_t k = 0; k < 3; ++k) {
      const uint32_t a = triangles[f][k], b = triangles[f][(k + 1) % 3];
      uses.push_back({std::min(a, b), std::max(a, b), f * 3 + k, a < b});
    }
  }
  std::sort(uses.begin(), uses.end(), [](const Use& x, const Use& y) {
    return x.lo != y.lo ? x.lo < y.lo : x.hi != y.hi ? x.hi < y.hi : x.corner_edge < y.corner_edge;
  });
  std::vector<uint8_t> good(uses.size(), 0);
  for (size_t first = 0, last = 0; first < uses.size(); first = last) {
    last = first + 1;
    while (last < uses.size() && uses[last].lo == uses[first].lo && uses[last].hi == uses[first].hi) ++last;
    if (last - first == 2 && uses[first].forward != uses[first + 1].forward) {
      good[uses[first].corner_edge] = good[uses[first + 1].corner_edge] = 1;
    }
  }
  return good;
}

// Gives every fan of a vertex beyond the first its own copy of the vertex. Two triangles around v are in
// the same fan when a chain of manifold edges (v, w) joins them. Returns the number of copies made.
//
// One pass is enough: a manifold edge's two triangles share both its ends, so they keep sharing them and
// the edge stays manifold; edges that were not manifold only lose triangles.
size_t split_fans(std::vector<glm::dvec3>& positions, std::vector<Triangle>& triangles) {
  const std::vector<uint8_t> good = manifold_edges(triangles);
  const size_t num_vertices = positions.size();
  std::vector<uint32_t> start(num_vertices + 1, 0);
  for (const Triangle& t : triangles) {
    for (uint32_t v : t) ++start[v + 1];
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<uint32_t> incident(start.back());  // (triangle * 3 + corner), ascending per vertex
  {
    std::vector<uint32_t> fill(start.begin(), start.end() - 1);
    for (uint32_t f = 0; f < triangles.size(); ++f) {
      for (uint32_t c = 0; c < 3; ++c) incident[fill[triangles[f][c]]++] = f * 3 + c;
    }
  }

  size_t copies = 0;
  std::vector<std::pair<uint32_t, uint32_t>> spokes;  // (other end w of a manifold edge, local triangle)
  std::vector<uint32_t> parent, fan_vertex;
  for (uint32_t v = 0; v < num_vertices; ++v) {
    const uint32_t first = start[v], count = start[v + 1] - start[v];
    if (count < 2) continue;
    spokes.clear();
    for (uint32_t k = 0; k < count; ++k) {
      const uint32_t f = incident[first + k] / 3, c = incident[first + k] % 3;
      if (good[f * 3 + c]) spokes.emplace_back(triangles[f][(c + 1) % 3], k);            // edge v -> next
      if (good[f * 3 + (c + 2) % 3]) spokes.emplace_back(triangles[f][(c + 2) % 3], k);  // edge prev -> v
    }
    std::sort(spokes.begin(), spokes.end());
    parent.resize(count);
    std::iota(parent.begin(), parent.end(), 0u);
    for (size_t s = 1; s < spokes.size(); ++s) {
      if (spokes[s].first != spokes[s - 1].first) continue;
      const uint32_t a = find_root(parent, spokes[s].second), b = find_root(parent, spokes[s - 1].second);
      parent[std::max(a, b)] = std::min(a, b);  // a fan's root is its lowest triangle
    }
    fan_vertex.assign(count, kInvalidIndex);
    fan_vertex[0] = v;
    for (uint32_t k = 0; k < count; ++k) {
      const uint32_t root = find_root(parent, k);
      if (fan_vertex[root] == kInvalidIndex) {
        fan_vertex[root] = static_cast<uint32_t>(positions.size());
        positions.push_back(positions[v]);
        ++copies;
      }
      const uint32_t f = incident[first + k] / 3, c = incident[first + k] % 3;
      triangles[f][c] = fan_vertex[root];
    }
  }
  return copies;
}

}  // namespace

PolygonMesh tessellate_patches(std::span<const BezierPatch> patches, int resolution, TessellationReport* report) {
  return tessellate_patches(
      patches, resolution, [&](size_t p, double u, double v) { return evaluate_patch(patches[p], u, v); }, report);
}

PolygonMesh tessellate_patches(std::span<const BezierPatch> patches, int resolution, const PatchSampler& sample,
                               TessellationReport* report) {
  if (resolution < 1 || resolution > kMaxPatchResolution) {
    throw MeshError("patch resolution " + std::to_string(resolution) + " is outside 1.." +
                    std::to_string(kMaxPatchResolution));
  }
  const auto n = static_cast<uint32_t>(resolution);
  const uint32_t side = n + 1;
  // Vertex ids and corner indices are uint32_t (and kInvalidIndex is reserved).
  if (patches.size() * 6 * size_t(n) * n >= size_t(kInvalidIndex)) {
    throw MeshError(std::to_string(patches.size()) + " patches at resolution " + std::to_string(resolution) +
                    " would make more triangles than a mesh can index");
  }

  // Sample first: the weld tolerance depends on the bounding box of everything.
  std::vector<glm::dvec3> samples;
  samples.reserve(patches.size() * side * side);
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (size_t index = 0; index < patches.size(); ++index) {
    for (uint32_t j = 0; j <= n; ++j) {
      for (uint32_t i = 0; i <= n; ++i) {
        const glm::dvec3 p = sample(index, double(i) / n, double(j) / n);
        samples.push_back(p);
        if (finite(p)) {
          lo = glm::min(lo, p);
          hi = glm::max(hi, p);
        }
      }
    }
  }
  const bool any_finite = lo.x <= hi.x;
  double diagonal = any_finite ? glm::length(hi - lo) : 0.0;
  if (!std::isfinite(diagonal)) diagonal = 0.0;  // finite corners whose difference overflows
  Welder welder(any_finite ? lo : glm::dvec3(0.0), kRelativeWeldTolerance * diagonal);

  PolygonMesh mesh;
  std::vector<uint32_t> ids(samples.size());
  for (size_t s = 0; s < samples.size(); ++s) ids[s] = welder.add(samples[s], mesh.positions);
  const size_t welded = mesh.positions.size();

  std::vector<Triangle> triangles;
  triangles.reserve(patches.size() * 2 * n * n);
  size_t degenerate = 0;
  auto emit = [&](uint32_t a, uint32_t b, uint32_t c) {
    if (a == b || b == c || a == c) {
      ++degenerate;
      return;
    }
    triangles.push_back({a, b, c});
  };
  for (size_t p = 0; p < patches.size(); ++p) {
    const size_t base = p * side * side;
    auto id = [&](uint32_t i, uint32_t j) { return ids[base + size_t(j) * side + i]; };
    for (uint32_t j = 0; j < n; ++j) {
      for (uint32_t i = 0; i < n; ++i) {
        const uint32_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
        emit(a, b, c);
        emit(a, c, d);
      }
    }
  }

  const size_t copies = split_fans(mesh.positions, triangles);

  mesh.indices.reserve(triangles.size() * 3);
  mesh.face_offsets.reserve(triangles.size() + 1);
  for (const Triangle& t : triangles) mesh.add_face({t[0], t[1], t[2]});

  if (report) {
    report->samples = samples.size();
    report->welded_vertices = welded;
    report->degenerate_triangles = degenerate;
    report->vertex_splits = copies;
  }
  return mesh;
}

}  // namespace meshedit
