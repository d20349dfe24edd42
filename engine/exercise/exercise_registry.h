// The exercises a process knows by name: the six built-in ones and those defined in Lua (scripted_exercise.h), each
// an Exercise handle (exercises.h). Lookup by name is where an unknown name becomes an error that names it.
//
//   ExerciseRegistry& registry = exercise_registry();
//   const Exercise collapse = registry.add(ScriptedExercise::load("scripts/exercises/collapse.lua"));
//   if (const std::optional<Exercise> e = registry.find("colapse"); !e) error(registry.unknown_name_error("colapse"));
//
// Invariants:
// - The built-in exercises are in every registry from its construction; their names cannot be taken.
// - add gives each scripted name one handle, distinct from every other, kept when the same name is added again (a
//   reloaded file replaces its definition: handles already given out see the new one). A handle stays valid while its
//   registry lives; slots never move.
// - find takes a name, a file name or a function name ("flip", "flip.lua", "flip_edge"), the built-in ones first, and
//   gives nullopt for anything else: never a fallback. unknown_name_error says which name and which names there are.
// - exercise_registry() is the process's registry, which the window, the CLI, lessons and grading share (an
//   exercise{} file registered once is known to all of them). Like every registry it is for one thread at a time:
//   nothing in it is locked.
#pragma once

#include <deque>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "exercise/exercises.h"

namespace meshedit {

// A scripted name's place in its registry: what its handles point at.
struct ExerciseSlot {
  std::shared_ptr<const ScriptedExercise> definition;
};

class ExerciseRegistry {
 public:
  ExerciseRegistry() = default;
  ExerciseRegistry(const ExerciseRegistry&) = delete;
  ExerciseRegistry& operator=(const ExerciseRegistry&) = delete;

  // Registers `definition` under its name and returns its handle (the same handle when the name was registered
  // before). Throws ScriptError when the name is a built-in exercise's.
  Exercise add(std::shared_ptr<const ScriptedExercise> definition);
  // The exercise with this name, file name or function name; nullopt when there is none.
  std::optional<Exercise> find(std::string_view name) const;
  // "no exercise is called 'colapse'; the exercises are curve, patch, normals, flip, split, upsample, collapse".
  std::string unknown_name_error(std::string_view name) const;
  // The scripted exercises, in the order their names were first registered.
  std::vector<Exercise> scripted() const;

  // A registered exercise whose file changed since it was loaded is loaded again and registered under the same handle.
  // Returns "" (unchanged, reloaded, or a built-in exercise) or the error that kept the old definition in place.
  std::string reload_if_changed(Exercise exercise);
  // Loads and registers every NAME.lua in `folder` (by name order). Returns one error per file that failed to load
  // ("collapse.lua:12: exercise: takes must be ..."); a missing folder is no error.
  std::vector<std::string> load_folder(const std::filesystem::path& folder);

 private:
  std::deque<ExerciseSlot> slots_;  // a deque: a slot (what handles point at) never moves
};

// The process's registry (see the invariants).
ExerciseRegistry& exercise_registry();

// The process registry's add, find and load_folder.
Exercise register_scripted_exercise(std::shared_ptr<const ScriptedExercise> definition);
std::optional<Exercise> find_exercise(std::string_view name);
std::vector<std::string> load_exercise_folder(const std::filesystem::path& folder);

}  // namespace meshedit
