// The window's Catmull-Clark and linear subdivision actions (Subdivide menu), beside Loop's in document_actions.h:
// each scheme at once, and each one phase per call (core/subdivision_phases.h).
//
// Invariants, as for every document action: every change is one undoable step through apply_operation, labelled
// "Catmull-Clark subdivision", "Linear subdivision" or the phase's label ("Catmull-Clark 2/3: ..."); a refusal
// changes nothing but the message (a Warning with the core's reason); the selection keeps what survives (original
// vertices keep their ids; every original edge and face is replaced, so they are deselected); a whole subdivision
// resets the Loop stepper, since its next phase would start again anyway. No action throws std::bad_alloc (the labels
// are made when the program starts; the points of phase 1 are computed before anything changes, and running out of
// memory there does nothing).
#pragma once

#include <cstdint>
#include <string>

#include "core/check.h"
#include "core/subdivision_phases.h"
#include "document/mesh_document.h"
#include "document/selection.h"

namespace meshedit {

Check catmull_clark_all(MeshDocument& doc, Selection& selection);
Check linear_subdivide_all(MeshDocument& doc, Selection& selection);

// One scheme one phase per call: its phases (which runs next, what phase 1 computed), trusted only while the
// document shows the mesh the last phase left (same generation and version).
struct SubdivisionStepper {
  explicit SubdivisionStepper(SubdivisionScheme scheme) : phases(scheme) {}
  SubdivisionPhases phases;
  uint64_t generation = 0;
  uint64_t version = 0;
};

// One phase: phase 1 computes the points (changes and records nothing), each later phase is an undoable step with
// its own diff (Catmull-Clark: 2 replaces every face by quads with nothing moved, 3 moves every vertex to its point;
// linear: 2 splits every face). If the mesh changed since the last phase (an undo, another edit), the call starts
// again at phase 1 and says so.
Check subdivision_step(MeshDocument& doc, Selection& selection, SubdivisionStepper& stepper);
// The label of the phase the next subdivision_step runs ("Catmull-Clark 2/3: ..."); allocates nothing.
const std::string& next_phase_label(const MeshDocument& doc, const SubdivisionStepper& stepper);

}  // namespace meshedit
