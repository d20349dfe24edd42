// The "Exercises" panel: choose an exercise, run the student's function ("mine") or the reference on the
// selection (an exercise on points or a patch: on a fixture, its input and both results as text tables,
// exercise_values_view.h), read the report (verdict, differences, notes, validation of mine, print output, errors with
// file:line), compare the changed pointers side by side, and replay the student's writes one by one; for upsample,
// phase by phase (upsample_phases.h), beside the reference's mesh at each phase boundary (upsample_phase_states.h).
//
// Invariants:
// - The panel draws and forwards clicks; every change to the document goes through ExerciseSession.
// - The side-by-side rows and an upsample's phases are computed once per run (ExerciseRun::serial), not per frame;
//   at most kMaxPointerRows are kept; the write list is clipped (ImGuiListClipper), so a long recording costs
//   O(rows on screen) per frame.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/halfedge_mesh.h"
#include "document/exercise_session.h"
#include "document/mesh_document.h"
#include "document/selection.h"
#include "exercise/upsample_phase_states.h"
#include "exercise/upsample_phases.h"
#include "ui/exercise_values_view.h"

namespace meshedit {

// One changed field in the side-by-side table: its value before the run, in mine and in the reference.
struct PointerRow {
  ElementRef element;
  std::string field;
  std::string before;
  std::string mine;
  std::string reference;
  bool differs() const { return mine != reference; }
};

// Every field that mine or the reference changed (from the run's input), but those of elements both deleted: the rows
// where mine and the reference differ first, each group in the order of core diff(); rows only one side changed show
// the unchanged value on the other. Empty for runs without both meshes.
std::vector<PointerRow> pointer_rows(const ExerciseRun& run, size_t max_rows);

struct ExercisePanelState {
  static constexpr size_t kMaxPointerRows = 5000;
  bool open = false;
  bool follow_replay = true;  // scroll the write list to the current write
  uint64_t rows_serial = 0;   // the run the cached rows belong to
  std::vector<PointerRow> rows;
  std::vector<ValueRow> value_rows;      // an exercise on points or a patch: its results side by side (same run)
  uint64_t phases_serial = 0;            // the run the phases belong to
  std::optional<UpsamplePhases> phases;  // a mine upsample run with recorded writes
  std::optional<UpsamplePhaseStates> phase_states;
  std::string phases_error;  // why the phase states could not be made
  size_t writes_drawn = 0;   // rows of the write list drawn in the last frame (tests)
  float run_mine_x = -1.0f;  // where "Run mine" (Stop while it runs) was drawn last frame, its centre (tests click it)
  float run_mine_y = -1.0f;
  float next_phase_x = -1.0f;  // where "next phase" was drawn in the last frame, its centre (tests click it)
  float next_phase_y = -1.0f;
  // Scroll the panel, once, so the next run's changed-pointers table ends in sight (the lesson's your_turn sets it).
  bool bring_table_into_view = false;
};

// Draws the "Exercises" window (nothing when state.open is false).
// The same contents drawn into the current window or tab (state.open is the caller's to honour).
void draw_exercise_panel_contents(ExerciseSession& session, ExercisePanelState& state, MeshDocument& doc,
                                  Selection& selection);
void draw_exercise_panel(ExerciseSession& session, ExercisePanelState& state, MeshDocument& doc, Selection& selection);

}  // namespace meshedit
