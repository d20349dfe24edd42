// expect.exercise: the window's check of one exercise, as a grading expectation. The suite calls the student's
// function itself and hands over what it needs; the comparison and its diagnosis are exercises.h's compare(), the
// code the Exercises panel runs, so a failure in grading reads like the window ("f0.halfedge is h0, but h0.face is
// f1", "your normal ... is the average of the faces' unit normals").
//
//   local before, mine = mesh:copy(), mesh:copy()
//   local result = student.flip_edge(mine, mine:edge(id))
//   expect.exercise("flip_edge", {mesh = before, edge = id}, result, mine, "flip_edge(e2) of a 1x1 grid")
//
// Arguments: the exercise (its function, name or file: "flip_edge", "flip", "flip.lua"); the input, as a table
// {points =, t =} (evaluate_step), {patch =, u =, v =} (evaluate; a patch or {points = 16 points}), {mesh =, vertex =}
// (vertex_normal), {mesh =, edge =} (flip_edge, split_edge), {mesh =} (upsample), {mesh =, element =} or {mesh =} (a
// scripted exercise registered in this process, scripted_exercise.h, by what it takes; on points or a patch
// {control = points, args =} or {patch =, args =}), with the mesh as it was before the call and the element as a
// handle or an id; what the student's function returned; the mesh it worked on (the mesh exercises; nil otherwise);
// an optional message.
//
// Invariants:
// - The reference is run_reference (the core), on a copy of the input mesh: the suite's meshes are not changed.
// - One check is recorded: passed when compare() finds the answer equal to the reference's; its message is the
//   optional message, then the window's differences, the likely mistake first (the first three, "... (N in all)").
//   A failed check on a mesh carries its input as a case the window can open (failing_case.h).
// - The locality bound of a flip or a split (exercise/exercise_locality.h) is checked on what the student's latest call
//   given `yours` touched of it, as the test's recorder noted it; a mesh no student call was given is not held to it.
// - Values are read raw (read_returned_value): a student's value runs no code in the suite's state.
// - A malformed call (an unknown exercise, an input without its fields, an element that is not alive) is the
//   suite's mistake: a Lua error, never a failed check.
#pragma once

struct lua_State;

namespace meshedit {

// The lua_CFunction behind expect.exercise (register it in the expect table: it reads the recorder from there).
int expect_exercise(lua_State* L);

}  // namespace meshedit
