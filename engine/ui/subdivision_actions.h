// The window's Catmull-Clark and linear subdivision actions (Subdivide menu), beside Loop's in document_actions.h:
// each scheme at once, and Catmull-Clark one phase per call (core/catmull_clark.h).
//
// Invariants, as for every document action: every change is one undoable step through apply_operation, labelled
// "Catmull-Clark subdivision", "Linear subdivision" or the phase's label; a refusal changes nothing but the message
// (a Warning with the core's reason); the selection keeps what survives (original vertices keep their ids; every
// original edge and face is replaced, so they are deselected); a whole subdivision resets the Loop stepper, since its
// next phase would start again anyway. No action throws std::bad_alloc (the labels are made when the program starts;
// the points of phase 1 are computed before anything changes, and running out of memory there does nothing).
#pragma once

#include <cstdint>
#include <string>

#include "core/catmull_clark.h"
#include "core/check.h"
#include "ui/mesh_document.h"
#include "ui/selection.h"

namespace meshedit {

Check catmull_clark_all(MeshDocument& doc, Selection& selection);
Check linear_subdivide_all(MeshDocument& doc, Selection& selection);

// Catmull-Clark one phase per call: which phase runs next and the points phase 1 computed, trusted only while the
// document shows the mesh the last phase left (same generation and version).
struct CatmullClarkStepper {
  int next_phase = 1;  // 1..3
  CatmullClarkState state;
  uint64_t generation = 0;
  uint64_t version = 0;
};

// One phase: 1 computes the points (changes and records nothing), 2 replaces every face by quads with nothing moved,
// 3 moves every vertex to its point; 2 and 3 are each an undoable step with its own diff. If the mesh changed since
// the last phase (an undo, another edit), the call starts again at phase 1 and says so.
Check catmull_clark_step(MeshDocument& doc, Selection& selection, CatmullClarkStepper& stepper);
// The label of the phase the next catmull_clark_step runs ("Catmull-Clark 2/3: ..."); allocates nothing.
const std::string& next_catmull_clark_phase_label(const MeshDocument& doc, const CatmullClarkStepper& stepper);

}  // namespace meshedit
