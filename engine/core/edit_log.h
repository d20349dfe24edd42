// RecordedEdit: one change a script made to a mesh (a pointer write, a new or deleted element, a core
// operation), with the script line that made it; apply_edit and replay make the same changes again on a copy.
// The app replays a student's operation write by write with these; the script layer's undo replays them too.
//
// Invariants:
// - Applying the edits of a recording in order to a copy of the mesh as it was when the recording began gives
//   a mesh same_as the recorded one, ids included: a creation says which id it made and must get that id
//   again, and operations are the core's deterministic ones.
// - apply_edit never reads or writes outside the mesh's arrays: an edit that does not fit (an element not
//   allocated yet, a value of the wrong kind, a creation that would get another id, a refused operation, an
//   unknown field) throws MeshError naming the element, having changed nothing.
// - Values are stored ids, dead or not: replaying a script that broke the mesh breaks the copy the same way.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>

#include <glm/vec3.hpp>

#include "core/halfedge_mesh.h"

namespace meshedit {

enum class EditKind : uint8_t {
  Set,        // one field of one element: "next" "twin" "vertex" "edge" "face" (halfedges), "halfedge"
              // (vertices, edges, faces, boundary loops), "position" (vertices)
  Create,     // a new element, appended; field "alive"; a vertex starts at value.position
  Delete,     // an element marked dead; field "alive"
  Operation,  // field "flip" "split" "collapse" (element = the edge), "loop_subdivide", "catmull_clark",
              // "linear_subdivide", "triangulate", or "restore" "undo" "redo" "subdivision phase" (the mesh was
              // replaced by `state`)
};

// "set", "new", "delete", "operation".
const char* edit_kind_name(EditKind kind);

// The value of one field: an id for pointer fields (invalid = null), a position for "position".
struct EditValue {
  ElementRef element;
  glm::dvec3 position{0.0};
};

struct RecordedEdit {
  EditKind what = EditKind::Set;
  ElementRef element;  // the element written, created or deleted; the edge of flip/split/collapse
  std::string field;
  EditValue before;  // Set: the value the field had (shown, not needed to apply)
  EditValue value;   // Set: the value written; Create: a vertex's position; Operation: what the core returned
  std::shared_ptr<const HalfedgeMesh> state;  // restore/undo/redo: the mesh as it became
  std::string where;                          // "flip.lua:12", the script line that made the edit; empty when unknown
};

// The before/after text of an edit for tables and the replay panel: "h7", "-" (null), "(0.5, 0, 1)";
// for Create/Delete "-", "alive" or "dead"; for an operation "-" before and the returned id after.
std::string format_edit_before(const RecordedEdit& edit);
std::string format_edit_after(const RecordedEdit& edit);
// One line: "h3.next = h7 (was h4)", "new v9 at (0.5, 0, 0)", "new h12", "delete h7", "flip e3",
// "split e3 -> v9", "loop_subdivide", "restore".
std::string describe(const RecordedEdit& edit);

// Makes the edit on `mesh` (see the invariants). A Set or Create bumps mesh.version() like any write.
void apply_edit(HalfedgeMesh& mesh, const RecordedEdit& edit);

// A copy of `before` with the first min(count, edits.size()) edits applied; throws MeshError like apply_edit.
HalfedgeMesh replay(const HalfedgeMesh& before, std::span<const RecordedEdit> edits, size_t count);

}  // namespace meshedit
