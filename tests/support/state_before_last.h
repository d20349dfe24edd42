// The state before a document's last change, as a mesh, for tests that check it exactly: the copy `last.before` when
// the document keeps one (a listed whole-mesh change), otherwise the document's mesh with `last.patch` applied
// backward (a local change keeps only its patch). nullopt when `last` has neither.
#pragma once

#include <optional>

#include "core/halfedge_mesh.h"
#include "core/mesh_patch.h"
#include "document/mesh_document.h"

namespace meshedit::testing {

inline std::optional<HalfedgeMesh> state_before_last(const MeshDocument& doc) {
  if (doc.last.before) return *doc.last.before;
  if (!doc.last.patch) return std::nullopt;
  HalfedgeMesh before = doc.mesh;
  doc.last.patch->apply(before, false);
  return before;
}

}  // namespace meshedit::testing
