// The registry of exercises by name and the Exercise handle's own functions (exercise_registry.h, exercises.h).
#include "exercise/exercise_registry.h"

#include <algorithm>
#include <system_error>

#include "exercise/scripted_exercise.h"
#include "script/lua_runtime.h"

namespace meshedit {
namespace {

bool names(const ExerciseInfo& info, std::string_view name) {
  return name == info.name || name == info.file || name == info.function;
}

}  // namespace

std::shared_ptr<const ScriptedExercise> Exercise::definition() const { return slot_ ? slot_->definition : nullptr; }

Exercise ExerciseRegistry::add(std::shared_ptr<const ScriptedExercise> definition) {
  const std::string name = definition->info().name;
  for (ExerciseSlot& slot : slots_) {
    if (name != slot.definition->info().name) continue;
    slot.definition = std::move(definition);
    return Exercise(ExerciseKind::Scripted, &slot);
  }
  for (const Exercise builtin : builtin_exercises()) {
    if (names(builtin.info(), name)) throw ScriptError("'" + name + "' is a built-in exercise; choose another name");
  }
  slots_.push_back(ExerciseSlot{std::move(definition)});
  return Exercise(ExerciseKind::Scripted, &slots_.back());
}

std::optional<Exercise> ExerciseRegistry::find(std::string_view name) const {
  for (const Exercise builtin : builtin_exercises()) {
    if (names(builtin.info(), name)) return builtin;
  }
  for (const ExerciseSlot& slot : slots_) {
    if (names(slot.definition->info(), name)) return Exercise(ExerciseKind::Scripted, &slot);
  }
  return std::nullopt;
}

std::string ExerciseRegistry::unknown_name_error(std::string_view name) const {
  std::string known;
  for (const Exercise builtin : builtin_exercises())
    known += (known.empty() ? "" : ", ") + std::string(builtin.info().name);
  for (const ExerciseSlot& slot : slots_) known += ", " + std::string(slot.definition->info().name);
  return "no exercise is called '" + std::string(name) + "'; the exercises are " + known;
}

std::vector<Exercise> ExerciseRegistry::scripted() const {
  std::vector<Exercise> out;
  for (const ExerciseSlot& slot : slots_) out.push_back(Exercise(ExerciseKind::Scripted, &slot));
  return out;
}

std::string ExerciseRegistry::reload_if_changed(Exercise exercise) {
  const std::shared_ptr<const ScriptedExercise> current = exercise.definition();
  if (!current || file_stamp(current->path()) == current->stamp()) return "";
  try {
    std::shared_ptr<ScriptedExercise> loaded = ScriptedExercise::load(current->path());
    if (std::string(loaded->info().name) != current->info().name) {
      return loaded->path().filename().string() + ": the exercise's name changed from '" + current->info().name +
             "' to '" + loaded->info().name + "'; open it again to register it under its new name";
    }
    add(std::move(loaded));
  } catch (const ScriptError& e) {
    return e.what();
  }
  return "";
}

std::vector<std::string> ExerciseRegistry::load_folder(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> files;
  std::error_code ec;
  for (const auto& item : std::filesystem::directory_iterator(folder, ec)) {
    if (item.path().extension() == ".lua" && item.is_regular_file(ec)) files.push_back(item.path());
  }
  std::sort(files.begin(), files.end());
  std::vector<std::string> errors;
  for (const std::filesystem::path& file : files) {
    try {
      add(ScriptedExercise::load(file));
    } catch (const ScriptError& e) {
      errors.push_back(e.what());
    }
  }
  return errors;
}

ExerciseRegistry& exercise_registry() {
  static ExerciseRegistry registry;
  return registry;
}

Exercise register_scripted_exercise(std::shared_ptr<const ScriptedExercise> definition) {
  return exercise_registry().add(std::move(definition));
}

std::optional<Exercise> find_exercise(std::string_view name) { return exercise_registry().find(name); }

std::vector<std::string> load_exercise_folder(const std::filesystem::path& folder) {
  return exercise_registry().load_folder(folder);
}

}  // namespace meshedit
