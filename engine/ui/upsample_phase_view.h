// The Exercises tab's phases of a student's upsample: jump the replay to the previous or next phase, the phase of
// the write shown, and a table of the four phases with yours and the reference's mesh at each phase boundary
// (counts of vertices, edges and faces, and how many positions and halfedges differ from the reference's).
//
// Invariants:
// - update_upsample_phases computes the phases and the boundary meshes once per run (ExercisePanelState::
//   phases_serial); a run that is not a mine upsample with recorded writes has none. It never throws: a recording
//   that does not replay, or memory running out, leaves the phases without their table and says why.
// - Drawing changes the document only through ExerciseSession (start_replay, replay_step).
#pragma once

#include "document/exercise_session.h"
#include "document/mesh_document.h"
#include "ui/exercise_panel.h"

namespace meshedit {

void update_upsample_phases(const ExerciseRun& run, ExercisePanelState& state);
// The buttons, the current phase and the table; nothing when state has no phases.
void draw_upsample_phases(ExerciseSession& session, ExercisePanelState& state, MeshDocument& doc);

}  // namespace meshedit
