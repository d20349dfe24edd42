// The exercise registry (exercise_registry.h): built-in handles, scripted handles a registry hands out, and an
// unknown name as an error that names it and the known ones.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "exercise/exercise_registry.h"
#include "exercise/exercises.h"
#include "exercise/scripted_exercise.h"
#include "script/lua_runtime.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

std::shared_ptr<ScriptedExercise> definition(const char* name) {
  return ScriptedExercise::load(testing::source_dir() / "scripts" / "exercises" / name);
}

TEST(ExerciseRegistry, ABuiltInHandleHasItsKindAndInfo) {
  EXPECT_EQ(Exercise::FlipEdge.kind(), ExerciseKind::FlipEdge);
  EXPECT_FALSE(Exercise::FlipEdge.scripted());
  EXPECT_EQ(Exercise::FlipEdge.definition(), nullptr);
  EXPECT_STREQ(Exercise::FlipEdge.info().name, "flip");
  EXPECT_STREQ(Exercise::FlipEdge.info().function, "flip_edge");
  EXPECT_STREQ(exercise_info(Exercise::Upsample).file, "upsample.lua");
  const ExerciseRegistry registry;
  EXPECT_EQ(registry.find("split_edge"), Exercise::SplitEdge);
  EXPECT_NE(Exercise::FlipEdge, Exercise::SplitEdge);
  EXPECT_TRUE(registry.scripted().empty());
}

TEST(ExerciseRegistry, AnUnknownNameIsAnErrorNamingItAndTheKnownOnes) {
  ExerciseRegistry registry;
  EXPECT_FALSE(registry.find("colapse").has_value());
  EXPECT_EQ(registry.unknown_name_error("colapse"),
            "no exercise is called 'colapse'; the exercises are curve, patch, normals, flip, split, upsample");
  registry.add(definition("collapse.lua"));
  EXPECT_EQ(registry.unknown_name_error("colapse"),
            "no exercise is called 'colapse'; the exercises are curve, patch, normals, flip, split, upsample, "
            "collapse");
  EXPECT_FALSE(registry.find("").has_value());
}

TEST(ExerciseRegistry, ScriptedRegistrationGivesDistinctHandlesKeptOnReregistration) {
  ExerciseRegistry registry;
  const Exercise collapse = registry.add(definition("collapse.lua"));
  const Exercise hodograph = registry.add(definition("hodograph.lua"));
  EXPECT_EQ(collapse.kind(), ExerciseKind::Scripted);
  EXPECT_EQ(hodograph.kind(), ExerciseKind::Scripted);
  EXPECT_NE(collapse, hodograph);
  EXPECT_STREQ(collapse.info().name, "collapse");
  EXPECT_STREQ(hodograph.definition()->info().name, "hodograph");
  EXPECT_TRUE(is_mesh_exercise(collapse));
  EXPECT_FALSE(is_mesh_exercise(hodograph));
  EXPECT_EQ(registry.find("collapse_edge"), collapse);
  EXPECT_EQ(registry.find("hodograph.lua"), hodograph);

  const std::shared_ptr<ScriptedExercise> again = definition("collapse.lua");
  EXPECT_EQ(registry.add(again), collapse);  // the same name keeps its handle, with the new definition
  EXPECT_EQ(collapse.definition(), again);
  EXPECT_EQ(registry.scripted(), (std::vector<Exercise>{collapse, hodograph}));

  ExerciseRegistry other;  // another registry's handle for the same name is another handle
  EXPECT_NE(other.add(definition("collapse.lua")), collapse);
  EXPECT_FALSE(other.find("hodograph").has_value());
}

}  // namespace
}  // namespace meshedit
