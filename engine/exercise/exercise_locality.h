// The "constant amount of work" check of flip_edge and split_edge: a flip or a split rewrites a fixed handful of
// pointers at its edge, however big the mesh, so a student's function that reads or writes much more than that (a
// loop over mesh:halfedges() to find the faces, a mesh:copy() or mesh:validate() of the whole mesh) is wrong, even
// when the mesh it leaves is right. compare() (exercises.h) runs this check, so the Exercises tab, the lessons'
// your_turn and the grader's expect.exercise say the same words.
//
//   const std::string why = locality_failure(Exercise::FlipEdge, input, report.mine, report.reference);
//   // "your flip_edge touched 33907 elements of a mesh of 11200 faces (it wrote 9 of them and only read the
//   // rest); ..."
//
// What is counted: the distinct elements of the input mesh that "mine" touched, read or written (TouchCount,
// touch_recorder.h: every handle the student's code got, every element it changed, the whole mesh for a call that
// reads all of it). Elements, never time: the count is the same on every machine.
//
// The bound, and why: a correct flip touches the two triangles at e (6 halfedges, their 4 twins, 5 edges, 4
// vertices, 2 faces: 21 elements); a correct split those and the 12 it creates (1 vertex, 3 edges, 6 halfedges, 2
// faces): 33. kLocalElements = 64 leaves room for a solution that reads more of the same neighbourhood. A solution may
// also walk around a corner of the two triangles (the flip's "are c and d already joined?" walks c's neighbours), and
// such a walk touches at most kPerCornerDegree elements per halfedge around the corner, so the bound adds that many
// per unit of the corners' degrees: a correct flip or split meets it on any mesh, a pole of degree 64 included.
//
// Invariants:
// - Only a mesh of at least kMinFaces faces is checked: there a loop over any kind of element (faces, vertices or
//   halfedges) touches more than the bound of any edge of low degree, so a failure is never a borderline one, and a
//   small mesh (the lessons' diamonds, a cube) never fails for its size.
// - A run that was not counted (no TouchCount) or did not run passes: the check only adds a failure, never hides one.
// - The message names the count, the mesh's size, what the reference changes (counted from the reference's mesh, at
//   run time) and what to do instead, in the exercises' words ("your flip_edge", "the reference").
#pragma once

#include <cstddef>
#include <string>

#include "exercise/exercises.h"

namespace meshedit {

inline constexpr size_t kLocalElements = 64;
inline constexpr size_t kPerCornerDegree = 6;
inline constexpr size_t kMinFaces = 1024;

// Whether runs of `exercise` are held to a bound: flip and split.
bool has_locality_bound(Exercise exercise);

// The most elements a run on `input` (a mesh and its edge) may touch: kLocalElements plus kPerCornerDegree times the
// sum of the degrees of the corners of the faces at the edge.
size_t locality_bound(const ExerciseInput& input);

// Why `mine` did more than a constant amount of work on `input`, or empty when it kept to the bound, the mesh is too
// small to tell (fewer than kMinFaces faces), or the run was not counted.
std::string locality_failure(Exercise exercise, const ExerciseInput& input, const ExerciseOutcome& mine,
                             const ExerciseOutcome& reference);

}  // namespace meshedit
