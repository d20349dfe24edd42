// The values of an exercise on points or a patch (scripted_exercise.h, takes = "points" or "patch"): what the
// function is given after its input (a fixture's args) and what it returns, a number, a point (vec3) or a list of
// those, to any depth. Reading them from Lua, pushing them back, describing them for messages, and reading the input
// itself (control points, a patch) from a definition's or a lesson's table.
//
//   ExerciseValue v = read_exercise_value(L, -1);   // {vec3(0, 0, 0), vec3(3, 0, 0)}: a list of 2 points
//   describe(v) == "a list of 2 points";  push_exercise_value(L, v);  // a fresh list of two fresh vec3
//
// Invariants:
// - Reading runs no code of the value's owner: tables are read raw (lua_rawlen, lua_rawgeti, and vec3_bindings.h's
//   raw to_vec3), so a student's metatable never runs outside the limits.
// - A table is a point when to_vec3 reads it (a vec3, {x, y, z} or {x =, y =, z =} of numbers); any other table is the
//   list of its items 1..#t (raw length). A table nested deeper than kMaxValueDepth (a cyclic one too), or one past
//   kMaxValueItems values in all, reads as Kind::Other, never an error.
// - Anything else (a string, a boolean, a function, a mesh) is Kind::Other with its description ("a string").
// - Pushing makes fresh tables: points are vec3 values (vec3_bindings.h), lists plain tables; Other pushes nil.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/bezier.h"

struct lua_State;

namespace meshedit {

inline constexpr size_t kMaxValueDepth = 8;
inline constexpr size_t kMaxValueItems = 100000;

struct ExerciseValue {
  enum class Kind { Nil, Number, Point, List, Other };
  Kind kind = Kind::Nil;
  double number = 0.0;               // Number
  glm::dvec3 point{0.0};             // Point
  std::vector<ExerciseValue> items;  // List
  std::string other;                 // Other: what it is ("a string", "a table nested deeper than 8 levels")

  static ExerciseValue of_number(double x);
  static ExerciseValue of_point(const glm::dvec3& p);
  static ExerciseValue of_list(std::vector<ExerciseValue> items);
  static ExerciseValue of_points(const std::vector<glm::dvec3>& points);
};

// The value at `index` (see the invariants for what a table is).
ExerciseValue read_exercise_value(lua_State* L, int index);
void push_exercise_value(lua_State* L, const ExerciseValue& value);

// "nil", "the number 0.5", "(1, 2, 0)", "a list of 3 points", "a list of 2 numbers", "a list of 2 lists",
// "a list of 3 values", "an empty list", or Other's description.
std::string describe(const ExerciseValue& value);
// The value written out: "0.5", "(1, 2, 0)", "{(0, 0, 0), (1, 0, 0)}", "nil"; Other's description in brackets.
std::string value_text(const ExerciseValue& value);
// "point", "number", "list" or "value": the word a message uses for one item.
const char* item_word(const ExerciseValue& value);

// Input readers, for a definition's fixtures and a lesson's your_turn. Each returns "" or what is wrong, worded to
// follow the field's name ("must be ...", "point 3 must be a point {x, y} or {x, y, z}, got string").
// A non-empty list of points, each a vec3 or a table {x, y} / {x, y, z} (z = 0 when left out).
std::string read_control_points(lua_State* L, int index, std::vector<glm::dvec3>& out);
// A patch: a meshedit.patch value, a list of 16 points row by row (points[4 * row + col + 1]), a list of 4 rows of
// 4 points, or {points = 16 points}, as student code receives one.
std::string read_patch_points(lua_State* L, int index, BezierPatch& out);
// A list of values (numbers, points, lists of them), passed after the input as written: a table of numbers that is
// also a point ({0.5, 0.5, 0}) is a point.
std::string read_argument_values(lua_State* L, int index, std::vector<ExerciseValue>& out);

}  // namespace meshedit
