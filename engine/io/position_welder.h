// PositionWelder: one vertex per distinct position, in order of first appearance, for formats that
// store each triangle's corners separately (STL). Positions compare exactly, bit for bit, except that
// +0 and -0 are the same coordinate. weld_repeated_positions applies the same rule to a mesh already read, for
// formats whose vertices are a renderer's (glTF, PLY from a modeller): there a vertex is repeated wherever a normal,
// a texture coordinate or a colour changes, and MeshEdit keeps positions only.
#pragma once

#include <cstdint>
#include <cstring>
#include <unordered_map>
#include <vector>

#include "core/polygon_mesh.h"

namespace meshedit {

class PositionWelder {
 public:
  explicit PositionWelder(PolygonMesh& mesh) : mesh_(mesh) {}

  // The index of the vertex at `p`, added to the mesh if no earlier corner had this position.
  uint32_t vertex_at(const glm::dvec3& p) {
    const Key key{bits(p.x), bits(p.y), bits(p.z)};
    const auto [it, added] = index_.try_emplace(key, static_cast<uint32_t>(mesh_.positions.size()));
    if (added) mesh_.positions.push_back(p);
    return it->second;
  }

 private:
  struct Key {
    uint64_t x, y, z;
    bool operator==(const Key& other) const { return x == other.x && y == other.y && z == other.z; }
  };
  struct KeyHash {
    size_t operator()(const Key& k) const {
      uint64_t h = k.x * 0x9e3779b97f4a7c15ull;
      h ^= (k.y + 0x632be59bd9b4e019ull + (h << 6) + (h >> 2));
      h ^= (k.z + 0x85ebca6b2f4a7c13ull + (h << 6) + (h >> 2));
      return static_cast<size_t>(h ^ (h >> 29));
    }
  };

  static uint64_t bits(double value) {
    if (value == 0) value = 0;  // -0 becomes +0
    uint64_t out = 0;
    std::memcpy(&out, &value, sizeof out);
    return out;
  }

  PolygonMesh& mesh_;
  std::unordered_map<Key, uint32_t, KeyHash> index_;
};

// Joins the vertices of `mesh` that share a position, keeping the first of each (the rest renumbered in order of first
// appearance) and pointing the faces' corners at it; a corner out of range stays out of range, for the builder to
// name. Returns how many vertices were joined; with none, the mesh is untouched.
inline size_t weld_repeated_positions(PolygonMesh& mesh) {
  PolygonMesh welded;
  PositionWelder welder(welded);
  std::vector<uint32_t> joined_to(mesh.positions.size());
  for (size_t i = 0; i < mesh.positions.size(); ++i) joined_to[i] = welder.vertex_at(mesh.positions[i]);
  const size_t joined = mesh.positions.size() - welded.positions.size();
  if (joined == 0) return 0;
  for (uint32_t& corner : mesh.indices) {
    if (corner < joined_to.size()) corner = joined_to[corner];
  }
  mesh.positions = std::move(welded.positions);
  return joined;
}

}  // namespace meshedit
