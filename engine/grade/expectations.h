// The `expect` table suites check results with. Every expectation is a C++ function that records into a
// TestRecorder (C++ memory of the grading process), never into Lua state, and the comparisons themselves run
// in C++ (validate(), mesh_compare.h): student code cannot reach, replace or fake any of it.
//
// Suite API (each records one check and returns true when it passed; `message` is optional and starts the
// recorded text):
//   expect(value, message)                    passes when value is neither nil nor false (= expect.truthy)
//   expect.truthy(value, message)  expect.falsy(value, message)  expect.is_nil(value, message)
//   expect.equal(actual, expected, message)   deep equality of plain values, tables (raw), vec3s, element
//                                             handles (same mesh, kind and id) and meshes (the same mesh)
//   expect.near(actual, expected, tolerance, message)
//                                             numbers, points (vec3 or {x, y, z}) by distance, and lists of
//                                             those item by item (lengths must match)
//   expect.valid(mesh, message)               validate() finds nothing; else the first violations, by element
//   expect.mesh_equal(yours, reference, tolerance, message)
//                                             equal up to renumbering (compare_meshes)
//   expect.same_pointers(yours, reference, tolerance, message)
//                                             equal pointer for pointer, same ids (compare_meshes_exact)
//   expect.counts(mesh, {vertices=, edges=, faces=, halfedges=, boundaries=}, message)
//   expect.pass(message)  expect.fail(message)
//   expect.score(fraction, message)           the test's share of its points, in [0, 1] (overrides the
//                                             pass/fail count; the last call wins)
//   expect.exercise(name, input, returned, yours, message)
//                                             the window's own check of one exercise (exercise_expectation.h):
//                                             the failure message is the window's diagnosis
// Failure messages say what was expected and what was found, naming elements ("h3.next") and list positions
// ("[2]: expected (0.5, 0, 0), got (0.25, 0, 0), 0.25 away (tolerance 1e-09)").
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "grade/grade_types.h"
#include "script/touch_recorder.h"

struct lua_State;

namespace meshedit {

class TestRecorder {
 public:
  explicit TestRecorder(TestRun& run) : run_(run) {}
  // A check: passed or not, what it checked and found, and how much of that is the headline (CheckResult).
  bool record(bool passed, std::string message, size_t headline = 0,
              std::optional<FailingCase> failing_case = std::nullopt);
  void set_fraction(double fraction) { run_.fraction = fraction; }
  TestRun& run() { return run_; }

  // What the student's latest call given `mesh` touched of it (the host notes each call's); expect.exercise reads it.
  void note_touches(const std::shared_ptr<const HalfedgeMesh>& mesh, const TouchCount& count);
  // That count for `mesh`, or none when no student call was given it in this test.
  std::optional<TouchCount> touches_of(const HalfedgeMesh* mesh) const;

 private:
  TestRun& run_;
  std::vector<std::pair<std::weak_ptr<const HalfedgeMesh>, TouchCount>> touches_;
};

// Pushes a new `expect` table. Its functions find the recorder through *current, which the host sets for
// the duration of a test and clears afterwards: an `expect` kept past its test raises an error instead of
// writing to a finished test.
void push_expect_table(lua_State* L, TestRecorder* const* current);

// The recorder of the test running now, for a check registered by push_expect_table (it reads the closure's
// first upvalue); raises "expect can only be used while a test runs" between tests.
TestRecorder& current_recorder(lua_State* L);

// "message: detail", or whichever of the two is not empty.
std::string join_message(const std::string& message, const std::string& detail);

// The first three items joined by "; ", then "; ... (N in all)" when total is larger.
std::string first_items(const std::vector<std::string>& items, size_t total);

// How the checks print a value: "nil", "true", "3", "0.5", "\"text\"", "(1, 2, 3)", "h37", "a mesh (8
// vertices, 18 edges, 12 faces)", "{1, 2, 3}".
std::string describe_value(lua_State* L, int index);

}  // namespace meshedit
