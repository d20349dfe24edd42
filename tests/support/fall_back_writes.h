// The writes a ChangeJournal cannot follow slot by slot, each of which makes it fall back to a snapshot
// (change_journal.h): direct array access, assignment, being moved from (the mesh's noexcept move), a move there and
// back, swap. The journal tests run every one, with memory for the snapshot and without (failing_snapshots.h), so a
// new way of falling back is added here once.
#pragma once

#include <utility>
#include <vector>

#include "core/mesh_build.h"
#include "core/mesh_storage.h"
#include "core/primitives.h"

namespace meshedit::testing {

struct FallBackWrite {
  const char* name;
  void (*write)(HalfedgeMesh&);
};

inline const std::vector<FallBackWrite>& fall_back_writes() {
  static const std::vector<FallBackWrite> writes = {
      {"direct array access (view)", [](HalfedgeMesh& m) { MeshStorage::view(m).position[0] = glm::dvec3(9); }},
      {"direct array access (arrays)", [](HalfedgeMesh& m) { MeshStorage::arrays(m).h_alive.set(2, false); }},
      {"assigning a new mesh", [](HalfedgeMesh& m) { m = build_halfedge_mesh(make_cube()); }},
      {"copy-assigning a mesh",
       [](HalfedgeMesh& m) {
         const HalfedgeMesh cube = build_halfedge_mesh(make_cube());
         m = cube;
       }},
      {"being moved from", [](HalfedgeMesh& m) { HalfedgeMesh taken = std::move(m); }},
      {"a move there and back",
       [](HalfedgeMesh& m) {
         HalfedgeMesh taken = std::move(m);
         taken.set_position(VertexId(2), {1, 2, 3});
         m = std::move(taken);
       }},
      {"swap",
       [](HalfedgeMesh& m) {
         HalfedgeMesh other = build_halfedge_mesh(make_cube());
         std::swap(m, other);
       }},
  };
  return writes;
}

}  // namespace meshedit::testing
