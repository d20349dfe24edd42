// The mesh edits of the command table (document/command_table.h): flip, split, collapse, triangulate and every
// subdivision, whole or one phase at a time. run_mesh_edit is the one function that runs each of them, wherever it is
// started from: the window's menus, keys and scripted verbs (app/commands.cpp) and the headless lesson driver's
// answers (lesson/lesson_headless.h).
//
// Invariants: each edit is the document action of document_actions.h or subdivision_actions.h (one undoable step, a
// sentence in doc.message, the selection kept to live elements, no std::bad_alloc); flip, split and collapse act on
// the selected edge (or the selected halfedge's edge). MeshEditState holds what lasts between edits: Loop's weights
// and the Catmull-Clark and linear steppers (Loop's own stepper is the document's: MeshDocument::loop).
#pragma once

#include <optional>
#include <string>

#include "core/check.h"
#include "core/loop_subdivision.h"
#include "core/subdivision_phases.h"
#include "document/command_table.h"
#include "document/mesh_document.h"
#include "document/selection.h"
#include "document/subdivision_actions.h"

namespace meshedit {

struct MeshEditState {
  LoopWeights loop_weights = LoopWeights::Course;  // Subdivide > Loop's original weights (beta) turns Loop's on
  SubdivisionStepper catmull_clark{SubdivisionScheme::CatmullClark};
  SubdivisionStepper linear{SubdivisionScheme::Linear};
};

// Whether run_mesh_edit runs `id` (Flip, Split, Collapse, Triangulate, Loop ... LinearPhase).
bool is_mesh_edit(CommandId id);
// Runs the edit; a command that is not a mesh edit is refused (Check::no) with nothing done.
Check run_mesh_edit(CommandId id, MeshDocument& doc, Selection& selection, MeshEditState& state);

// The command of `scheme`, whole or its next phase (Linear, CatmullClarkPhase...).
CommandId subdivide_command(SubdivisionScheme scheme, bool one_phase);
// The label of the phase the next one-phase edit of `scheme` runs ("Loop 2/4: split every original edge"); allocates
// nothing.
const std::string& next_phase_label(SubdivisionScheme scheme, const MeshDocument& doc, const MeshEditState& state);
// When the next one-phase edit of `scheme` starts again at phase 1 because the mesh changed since the last phase:
// that last phase; else nullopt.
std::optional<int> stale_phase(SubdivisionScheme scheme, const MeshDocument& doc, const MeshEditState& state);

}  // namespace meshedit
