// The actions the app binds to keys and buttons: pointer navigation, flip, split, collapse, Loop subdivision
// (whole or one phase per press), triangulation, undo and redo.
//
// Invariants:
// - Every action leaves a sentence in doc.message (what happened, or why nothing did).
// - Every action leaves `selection` pointing at live elements only: the selected element stays selected when
//   it survives the edit (flip and split keep the edge's id), collapse selects the surviving vertex, and an
//   element an undo removed is deselected.
// - Edits go through apply_operation(), so a refusal changes nothing but the message. A flip, split or collapse is
//   labelled by edge_edit_label ("flip e5": document/edge_edit_label.h), which the window reads back to animate it.
// - No action throws std::bad_alloc: the document layer's rule of docs/ARCHITECTURE.md (Memory running out). When
//   memory runs out, an action is either not done (mesh, history, selection and Loop stepper as they were; an Error
//   that says memory ran out when it would have been done) or done as the document keeps it (mesh_document.h:
//   recorded, or kept without its record). Nor do the questions asked before acting: edge_for_operation refuses
//   with kMemoryRanOut as its reason when memory runs out building its answer, and next_loop_phase_label allocates
//   nothing.
#pragma once

#include <optional>
#include <string>

#include "core/check.h"
#include "core/loop_subdivision.h"
#include "document/mesh_document.h"
#include "document/selection.h"

namespace meshedit {

// The edge the local operations act on: the selected edge, or the edge of the selected halfedge.
// Refused with a sentence when nothing, or something else, is selected or when the pointer is broken; with
// kMemoryRanOut when memory runs out building that sentence.
OpResult<EdgeId> edge_for_operation(const HalfedgeMesh& mesh, ElementRef selected);

// N/T/V/E/F/H: moves selection.selected along the pointer; on refusal keeps it and says why. Returns success.
bool navigate_selection(MeshDocument& doc, Selection& selection, NavStep step);
// Selects `element` (a link, a row, the status bar's culprit) if it exists; says why not otherwise. Dead
// elements may be selected (their rows and stale fields are shown greyed), missing ones may not.
bool select_element(MeshDocument& doc, Selection& selection, ElementRef element);

Check flip_selected(MeshDocument& doc, Selection& selection);      // F; keeps the edge selected
Check split_selected(MeshDocument& doc, Selection& selection);     // S; keeps the edge (now the half m-b)
Check collapse_selected(MeshDocument& doc, Selection& selection);  // selects the surviving vertex
// L: all four phases as one undoable step.
Check loop_subdivide_all(MeshDocument& doc, Selection& selection, LoopWeights weights = LoopWeights::Course);
// Edit > Triangulate: every face of more than three corners split into triangles (core/triangulate.h), as one
// undoable step. The mesh is rebuilt, so ids change and the selection is cleared.
Check triangulate_all(MeshDocument& doc, Selection& selection);
// One phase per call (1 compute, 2 split, 3 flip, 4 move), each of 2-4 its own undoable step with its own
// diff; phase 1 changes nothing and records nothing. If the mesh changed since the last phase (an undo,
// another edit), the next call starts again at phase 1 and says so. doc.loop.next_phase tells which is next.
Check loop_subdivide_step(MeshDocument& doc, Selection& selection, LoopWeights weights = LoopWeights::Course);
// A sentence for the phase the next loop_subdivide_step() runs ("Loop 2/4: split every original edge"): one of the
// labels made when the program starts, so asking allocates nothing.
const std::string& next_loop_phase_label(const MeshDocument& doc);

bool undo_edit(MeshDocument& doc, Selection& selection);  // Ctrl+Z
bool redo_edit(MeshDocument& doc, Selection& selection);  // Ctrl+Y

}  // namespace meshedit
