// The Exercises tab's view of a scripted exercise on points or a patch (scripted_exercise.h), where there is no mesh to
// show: the fixture chooser, the input as text (each control point, a patch row by row, the args) and what yours and
// the reference returned, side by side, one row per item, the rows that differ shaded.
//
// Invariants:
// - The rows are made from the run alone (value_rows), once per run (ExerciseRun::serial), so drawing costs the rows
//   on screen; at most kMaxValueRows are kept.
// - A row differs exactly when compare_values (value_compare.h) finds its two items apart within the definition's
//   tolerance, or one side has no item there.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "document/exercise_session.h"

namespace meshedit {

inline constexpr size_t kMaxValueRows = 2000;

// One row of the side-by-side table: "point 3", "(1, 2, 0)", "(1.5, 2, 0)".
struct ValueRow {
  std::string what;
  std::string mine;
  std::string reference;
  bool differs = false;
};

// Rows for what the run returned: one per item when both returned lists (as many as the longer list has, "(none)" on
// the shorter side), else one row "returned" (two empty lists too). A reference-only run fills `reference` alone.
std::vector<ValueRow> value_rows(const ExerciseRun& run);
// The run's input as text: "P0 (0, 0, 0)" per control point, or "row 0: (..) (..) (..) (..)" per patch row, then
// "args: 0.5, 0.5" when it has args.
std::vector<std::string> value_input_lines(const ExerciseRun& run);

// Draws the fixture chooser of the active exercise (nothing for an exercise on a mesh).
void draw_value_fixture_chooser(ExerciseSession& session);
// Draws the input and the side-by-side table of `rows` (the caller keeps them per run).
void draw_value_tables(const ExerciseRun& run, const std::vector<ValueRow>& rows);

}  // namespace meshedit
