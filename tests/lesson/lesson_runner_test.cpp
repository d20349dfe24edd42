// LessonRunner on a HeadlessHost: steps run in order, the scene calls reach the host, waits block until the
// right event, Back and reload rebuild the scene, and every kind of failure (syntax error, runtime error,
// runaway loop, missing file, host exception) becomes error() with file:line while the runner keeps working.
// Lesson files are written to the test's scratch folder as "lesson.lua", so messages read "lesson.lua:LINE:".
//
// Map of this file (each part starts at its `// ---- name` banner):
//   helpers                Strings, State, write_lesson, small_budget
//   steps, say, the scene  steps in order and what each said, the title, the scene calls reaching the host (show,
//                          highlight, label, camera, view), curves and patches, current_mesh and selection
//   waits                  wait_for a key, a click, a selection, a condition or a button; animate
//   navigation and reload  Back, Next past a waiting step, go_to, reload keeping the step index
//   errors                 syntax errors on load and reload, runtime errors, errors in conditions and animations,
//                          misused calls, scene calls at the top level, no steps, a missing file
//   limits                 the instruction and memory budgets, a lesson's own memory error, a budget for each resume
//   the host and print     ThrowingHost, ReentrantHost: a host exception, calls back into the runner; print's callback
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/mesh_build.h"
#include "core/palette.h"
#include "core/primitives.h"
#include "lesson/headless_host.h"
#include "lesson/lesson_runner.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

// ---- helpers ---------------------------------------------------------------------------------------

using Strings = std::vector<std::string>;
using State = LessonRunner::StepState;

std::filesystem::path write_lesson(const std::filesystem::path& dir, const std::string& text,
                                   const std::string& name = "lesson.lua") {
  const auto path = dir / name;
  std::ofstream(path) << text;
  return path;
}

LuaLimits small_budget(uint64_t instructions) {
  LuaLimits limits = LessonRunner::default_limits();
  limits.instructions = instructions;
  return limits;
}

// ---- steps, say, the scene -------------------------------------------------------------------------

TEST(LessonRunner, RunsStepsInOrderAndKeepsWhatEachSaid) {
  const auto dir = testing::scratch_dir();
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(write_lesson(dir, R"lua(lesson { title = "Order", summary = "Three steps." }
step("One", function() say("first") say("**second**") end)
step("Two", function() say("third") end)
step("Three", function() say(3) end)
)lua")))
      << runner.error();
  EXPECT_EQ(runner.title(), "Order");
  EXPECT_EQ(runner.summary(), "Three steps.");
  EXPECT_EQ(runner.step_titles(), (Strings{"One", "Two", "Three"}));
  EXPECT_EQ(runner.current_step(), 0u);
  EXPECT_EQ(runner.step_state(), State::Finished);
  EXPECT_EQ(runner.said(), (Strings{"first", "**second**"}));
  EXPECT_EQ(runner.waiting_for().kind, LessonWait::Kind::None);
  runner.next();
  EXPECT_EQ(runner.current_step(), 1u);
  EXPECT_EQ(runner.said(), (Strings{"third"}));
  runner.next();
  EXPECT_EQ(runner.said(), (Strings{"3"}));
  runner.next();  // at the last step: nothing happens
  EXPECT_EQ(runner.current_step(), 2u);
  EXPECT_EQ(runner.said(), (Strings{"3"}));
  EXPECT_EQ(runner.error(), "");
}

TEST(LessonRunner, TitleDefaultsToTheFileStem) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(write_lesson(testing::scratch_dir(), "step('A', function() end)\n", "flip_intro.lua")));
  EXPECT_EQ(runner.title(), "flip_intro");
  EXPECT_EQ(runner.summary(), "");
}

TEST(LessonRunner, SceneCallsReachTheHost) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(write_lesson(testing::scratch_dir(), R"lua(local cube = meshedit.cube()
step("Scene", function()
  show(cube)
  highlight(cube:edge(7))
  highlight("v0", "red")
  highlight({cube:face(1), "h3"}, "#00ff80")
  highlight("e2", {0, 0, 1})
  label(cube:vertex(0), "apex")
  camera "fit"
  camera { yaw = 30, pitch = 20, distance = 4, target = {0, 0, 1} }
end)
)lua")))
      << runner.error();
  EXPECT_EQ(runner.step_state(), State::Finished) << runner.error();
  // No colour: the palette's lesson highlight; a name: the palette's swatch; "#rrggbb" and {r, g, b}: as given.
  const std::string default_colour = colour_hex(palette_for(Theme::Dark).lesson_highlight);
  EXPECT_EQ(host.calls(),
            (Strings{"clear_annotations", "show_mesh (8 vertices, 18 edges, 12 faces)",
                     "highlight e7 " + default_colour, "highlight v0 " + colour_hex(kDarkSwatches.vermillion),
                     "highlight f1 #00ff80", "highlight h3 #00ff80", "highlight e2 #0000ff", "label v0 \"apex\"",
                     "camera fit", "camera yaw=30 pitch=20 distance=4 target=(0, 0, 1)"}));
  ASSERT_EQ(host.highlights().size(), 5u);
  EXPECT_EQ(host.highlights().at(ElementRef(EdgeId(7))), palette_for(Theme::Dark).lesson_highlight);
  EXPECT_EQ(host.labels().at(ElementRef(VertexId(0))), "apex");
  ASSERT_EQ(host.camera_requests().size(), 2u);
  EXPECT_TRUE(host.camera_requests()[0].fit);
  EXPECT_EQ(*host.camera_requests()[1].yaw_degrees, 30.0);
  EXPECT_EQ(*host.camera_requests()[1].target, glm::dvec3(0, 0, 1));
  ASSERT_NE(host.screen_mesh(), nullptr);
  EXPECT_EQ(host.screen_mesh()->num_faces(), 12u);
}

TEST(LessonRunner, ViewTurnsPartsOfTheMeshViewOnAndOff) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(write_lesson(testing::scratch_dir(), R"lua(step("View", function()
  view { halfedges = true, labels = false }
  view { wireframe = false, vertices = true }
end)
step("Wrong type", function()
  view { halfedges = 1 }
end)
step("Unknown part", function()
  view { arrows = true }
end)
)lua")))
      << runner.error();
  ASSERT_EQ(runner.step_state(), State::Finished) << runner.error();
  EXPECT_EQ(host.calls(),
            (Strings{"clear_annotations", "view halfedges=on labels=off", "view wireframe=off vertices=on"}));
  runner.next();
  EXPECT_EQ(runner.step_state(), State::Failed);
  EXPECT_NE(runner.error().find("view: halfedges must be true or false"), std::string::npos) << runner.error();
  EXPECT_EQ(runner.error().rfind("lesson.lua:6: ", 0), 0u) << runner.error();  // the lesson's line
  runner.next();
  EXPECT_EQ(runner.step_state(), State::Failed);
  EXPECT_NE(runner.error().find("arrows"), std::string::npos) << runner.error();
}

TEST(LessonRunner, ShowTakesTheUpAxisOfAMeshReadFromAFile) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(write_lesson(testing::scratch_dir(), R"lua(step("Up", function()
  show(meshedit.cube(), { up = "y" })
  show(meshedit.cube())
end)
step("Not an axis", function()
  show(meshedit.cube(), { up = "w" })
end)
step("Unknown option", function()
  show(meshedit.cube(), { upright = true })
end)
)lua")))
      << runner.error();
  ASSERT_EQ(runner.step_state(), State::Finished) << runner.error();
  EXPECT_EQ(host.calls(), (Strings{"clear_annotations", "show_mesh (8 vertices, 18 edges, 12 faces) Y up",
                                   "show_mesh (8 vertices, 18 edges, 12 faces)"}));
  runner.next();
  EXPECT_EQ(runner.step_state(), State::Failed);
  EXPECT_NE(runner.error().find("show: up must be \"x\", \"y\" or \"z\""), std::string::npos) << runner.error();
  EXPECT_NE(runner.error().find("got 'w'"), std::string::npos) << runner.error();
  EXPECT_EQ(runner.error().rfind("lesson.lua:6: ", 0), 0u) << runner.error();
  runner.next();
  EXPECT_EQ(runner.step_state(), State::Failed);
  EXPECT_NE(runner.error().find("upright"), std::string::npos) << runner.error();
}

TEST(LessonRunner, ShowTakesTheLessonsOwnMeshObject) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(write_lesson(testing::scratch_dir(), R"lua(step("Show", function()
  local m = meshedit.tetrahedron()
  show(m)
  m:vertex(0).position = {x = 5, y = 6, z = 7}
end)
)lua")));
  ASSERT_EQ(runner.step_state(), State::Finished) << runner.error();
  ASSERT_NE(host.shown_mesh(), nullptr);
  // The host got the script's mesh itself (the later move shows there), and copied the screen mesh at show.
  EXPECT_EQ(host.shown_mesh()->position(VertexId(0)), glm::dvec3(5, 6, 7));
  EXPECT_NE(host.screen_mesh()->position(VertexId(0)), glm::dvec3(5, 6, 7));
}

TEST(LessonRunner, ShowsCurvesAndPatchesFromPointLists) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(write_lesson(testing::scratch_dir(), R"lua(step("Curve", function()
  show({ {0, 0}, {x = 1, y = 2}, {2, 2, 0}, {3, 0} })
end)
step("Patches", function()
  local p = {}
  for row = 0, 3 do for col = 0, 3 do p[#p + 1] = {col, row, row * col} end end
  show({p, p})
end)
step("Bad curve", function() show({ {0, 0, 1}, {1, 1} }) end)
step("Bad patch", function() show({ { {0, 0, 0} } }) end)
)lua")));
  ASSERT_EQ(runner.step_state(), State::Finished) << runner.error();
  ASSERT_TRUE(host.shown_curve());
  EXPECT_EQ(host.shown_curve()->control_points, (std::vector<glm::dvec2>{{0, 0}, {1, 2}, {2, 2}, {3, 0}}));
  runner.next();
  ASSERT_EQ(runner.step_state(), State::Finished) << runner.error();
  ASSERT_EQ(host.shown_patches().size(), 2u);
  EXPECT_EQ(host.shown_patches()[1].at(3, 2), glm::dvec3(2, 3, 6));
  EXPECT_FALSE(host.shown_curve());
  runner.next();
  EXPECT_EQ(runner.error(), "lesson.lua:9: show: curves are drawn in 2D, but point 1 has z = 1");
  runner.next();
  EXPECT_EQ(runner.error(), "lesson.lua:10: show: patch 1 needs 16 control points (4 rows of 4), got 1");
}

TEST(LessonRunner, CurrentMeshAndSelectionReadTheHost) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(write_lesson(testing::scratch_dir(), R"lua(step("Nothing yet", function()
  say(tostring(current_mesh()) .. " " .. tostring(selection()))
end)
step("Read", function()
  local m = current_mesh()
  local s = selection()
  say(m:num_faces() .. " " .. tostring(s) .. " " .. type(s) .. " " .. s.mesh:num_faces())
end)
)lua")));
  EXPECT_EQ(runner.said(), (Strings{"nil nil"}));
  host.set_current_mesh(std::make_shared<HalfedgeMesh>(build_halfedge_mesh(make_grid(2, 1))));
  host.set_selection(ElementRef(EdgeId(3)));
  runner.next();
  EXPECT_EQ(runner.said(), (Strings{"4 e3 userdata 4"})) << runner.error();
}

// ---- waits -----------------------------------------------------------------------------------------

TEST(LessonRunner, WaitForKeyBlocksUntilThatKey) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(write_lesson(testing::scratch_dir(), R"lua(step("Keys", function()
  say("before")
  local key = wait_for { key = "F" }
  say("after " .. key)
end)
)lua")));
  EXPECT_EQ(runner.step_state(), State::Waiting);
  const LessonWait& wait = runner.waiting_for();
  EXPECT_EQ(wait.kind, LessonWait::Kind::Key);
  EXPECT_EQ(wait.name, "F");
  EXPECT_EQ(wait.where, "lesson.lua:3");
  EXPECT_EQ(wait.hint, "Press F");
  EXPECT_EQ(wait.describe(), "key F");
  EXPECT_FALSE(runner.deliver(LessonEvent::key("G")));
  EXPECT_FALSE(runner.deliver(LessonEvent::key("shift+F")));
  EXPECT_FALSE(runner.deliver(LessonEvent::click(ElementRef(VertexId(0)))));
  EXPECT_FALSE(runner.deliver(LessonEvent::button("F")));
  runner.update(1.0);
  EXPECT_EQ(runner.step_state(), State::Waiting);
  EXPECT_EQ(runner.said(), (Strings{"before"}));
  EXPECT_TRUE(runner.deliver(LessonEvent::key("f")));  // key names ignore case
  EXPECT_EQ(runner.step_state(), State::Finished);
  EXPECT_EQ(runner.said(), (Strings{"before", "after f"}));
  EXPECT_EQ(runner.waiting_for().kind, LessonWait::Kind::None);
  EXPECT_FALSE(runner.deliver(LessonEvent::key("F")));  // nothing waits any more
}

TEST(LessonRunner, WaitForClickMeetsOnlyAClickOfThatKind) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(write_lesson(testing::scratch_dir(), R"lua(step("Click", function()
  show(meshedit.cube())
  local v = wait_for { click = "vertex", hint = "Click a corner" }
  say(tostring(v) .. " " .. type(v) .. " " .. v.mesh:num_vertices())
  local e = wait_for { click = "e7" }
  say(tostring(e))
end)
)lua")));
  ASSERT_EQ(runner.step_state(), State::Waiting) << runner.error();
  EXPECT_EQ(runner.waiting_for().hint, "Click a corner");
  EXPECT_EQ(runner.waiting_for().describe(), "a click on a vertex");
  EXPECT_FALSE(runner.deliver(LessonEvent::click(ElementRef(EdgeId(3)))));
  EXPECT_FALSE(runner.deliver(LessonEvent::selection(ElementRef(VertexId(2)))));
  EXPECT_TRUE(runner.deliver(LessonEvent::click(ElementRef(VertexId(2)))));
  EXPECT_EQ(runner.said(), (Strings{"v2 userdata 8"}));
  EXPECT_EQ(runner.waiting_for().describe(), "a click on e7");
  EXPECT_EQ(runner.waiting_for().hint, "Click e7");
  EXPECT_FALSE(runner.deliver(LessonEvent::click(ElementRef(EdgeId(6)))));
  EXPECT_TRUE(runner.deliver(LessonEvent::click(ElementRef(EdgeId(7)))));
  EXPECT_EQ(runner.step_state(), State::Finished);
  EXPECT_EQ(runner.said(), (Strings{"v2 userdata 8", "e7"}));
}

TEST(LessonRunner, WaitForSelectionIsMetByAnEventOrByTheSelectionItself) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(write_lesson(testing::scratch_dir(), R"lua(step("Select", function()
  show(meshedit.cube())
  local e = wait_for { selection = "e7" }
  say("got " .. tostring(e))
  local any = wait_for { selection = "face" }
  say("then " .. tostring(any))
end)
)lua")));
  EXPECT_EQ(runner.waiting_for().describe(), "the selection of e7");
  EXPECT_EQ(runner.waiting_for().hint, "Select e7");
  EXPECT_FALSE(runner.deliver(LessonEvent::selection(ElementRef(EdgeId(6)))));
  host.set_selection(ElementRef(EdgeId(6)));
  runner.update(0.0);
  EXPECT_EQ(runner.said(), Strings{});
  host.set_selection(ElementRef(EdgeId(7)));  // the student selected it by walking, or it was already selected
  runner.update(0.0);
  EXPECT_EQ(runner.said(), (Strings{"got e7"}));
  EXPECT_EQ(runner.waiting_for().describe(), "the selection of a face");
  EXPECT_TRUE(runner.deliver(LessonEvent::selection(ElementRef(FaceId::face(4)))));
  EXPECT_EQ(runner.said(), (Strings{"got e7", "then f4"}));
  EXPECT_EQ(runner.step_state(), State::Finished);
}

TEST(LessonRunner, WaitForConditionIsCheckedEachUpdate) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(write_lesson(testing::scratch_dir(), R"lua(step("Condition", function()
  local checks = 0
  local value = wait_for { condition = function() checks = checks + 1; return checks >= 3 and "ready" end }
  say(value .. " after " .. checks)
  wait_for { condition = function() return true end }
  say("no wait")
  wait_for { condition = function() return selection() ~= nil end, hint = "Select anything" }
  say("selected")
end)
)lua")));
  EXPECT_EQ(runner.waiting_for().kind, LessonWait::Kind::Condition);
  EXPECT_EQ(runner.waiting_for().describe(), "a condition");
  EXPECT_FALSE(runner.deliver(LessonEvent::key("F")));  // events do not satisfy a condition wait
  runner.update(0.016);
  EXPECT_EQ(runner.said(), Strings{});
  runner.update(0.016);  // the third check is true; the second condition is true at once
  EXPECT_EQ(runner.said(), (Strings{"ready after 3", "no wait"}));
  EXPECT_EQ(runner.waiting_for().hint, "Select anything");
  runner.update(0.016);
  EXPECT_EQ(runner.step_state(), State::Waiting);
  host.set_selection(ElementRef(VertexId(1)));
  runner.update(0.016);
  EXPECT_EQ(runner.step_state(), State::Finished);
  EXPECT_EQ(runner.said(), (Strings{"ready after 3", "no wait", "selected"}));
}

TEST(LessonRunner, WaitForButtonNeedsThatLabel) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(write_lesson(testing::scratch_dir(), R"lua(step("Button", function()
  say("pressed " .. wait_for { button = "Continue" })
end)
)lua")));
  EXPECT_EQ(runner.waiting_for().describe(), "the Continue button");
  EXPECT_EQ(runner.waiting_for().hint, "Press Continue");
  EXPECT_FALSE(runner.deliver(LessonEvent::button("continue")));  // labels are exact
  EXPECT_FALSE(runner.deliver(LessonEvent::key("Continue")));
  EXPECT_TRUE(runner.deliver(LessonEvent::button("Continue")));
  EXPECT_EQ(runner.said(), (Strings{"pressed Continue"}));
}

TEST(LessonRunner, AnimateCallsItsFunctionFromZeroToOneAsTimePasses) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(write_lesson(testing::scratch_dir(), R"lua(step("Animate", function()
  local ts = {}
  animate(1, function(t) ts[#ts + 1] = string.format("%g", t) end)
  say(table.concat(ts, " "))
  animate(0, function(t) say("instant " .. t) end)
end)
)lua")));
  ASSERT_EQ(runner.waiting_for().kind, LessonWait::Kind::Animation) << runner.error();
  EXPECT_EQ(runner.waiting_for().seconds, 1.0);
  EXPECT_EQ(runner.waiting_for().where, "lesson.lua:3");
  EXPECT_FALSE(runner.deliver(LessonEvent::button("Continue")));
  runner.update(0.25);
  EXPECT_EQ(runner.waiting_for().elapsed, 0.25);
  runner.update(0.25);
  runner.update(0.25);
  EXPECT_EQ(runner.step_state(), State::Waiting);
  runner.update(0.5);  // past the end: t is clamped to 1
  EXPECT_EQ(runner.step_state(), State::Finished) << runner.error();
  EXPECT_EQ(runner.said(), (Strings{"0 0.25 0.5 0.75 1", "instant 1"}));
}

// ---- navigation and reload -------------------------------------------------------------------------

TEST(LessonRunner, BackRerunsThePreviousStepWithTheHostCleared) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(write_lesson(testing::scratch_dir(), R"lua(local runs = 0
step("First", function()
  runs = runs + 1
  show(meshedit.cube())
  highlight("e7", "red")
  say("first, run " .. runs)
  wait_for { key = "N" }
  say("walked")
end)
step("Second", function()
  highlight("v0", "blue")
  label("v0", "here")
  say("second")
end)
)lua")));
  EXPECT_TRUE(runner.deliver(LessonEvent::key("N")));
  EXPECT_EQ(runner.said(), (Strings{"first, run 1", "walked"}));
  runner.next();
  EXPECT_EQ(runner.current_step(), 1u);
  EXPECT_EQ(host.highlights().size(), 1u);
  EXPECT_EQ(host.highlights().count(ElementRef(VertexId(0))), 1u);
  EXPECT_EQ(host.labels().size(), 1u);
  host.clear_calls();
  runner.back();
  EXPECT_EQ(runner.current_step(), 0u);
  EXPECT_EQ(host.calls(), (Strings{"clear_annotations", "show_mesh (8 vertices, 18 edges, 12 faces)",
                                   "highlight e7 " + colour_hex(kDarkSwatches.vermillion)}));
  EXPECT_EQ(host.highlights().size(), 1u);
  EXPECT_EQ(host.highlights().count(ElementRef(EdgeId(7))), 1u);
  EXPECT_TRUE(host.labels().empty());
  EXPECT_EQ(runner.said(), (Strings{"first, run 2"}));  // from its start: waiting again
  EXPECT_EQ(runner.step_state(), State::Waiting);
  runner.back();  // at the first step, Back runs it again
  EXPECT_EQ(runner.current_step(), 0u);
  EXPECT_EQ(runner.said(), (Strings{"first, run 3"}));
  runner.go_to(7);  // clamped to the last step
  EXPECT_EQ(runner.current_step(), 1u);
  runner.restart_step();
  EXPECT_EQ(runner.said(), (Strings{"second"}));
}

TEST(LessonRunner, NextSkipsAStepThatIsStillWaiting) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(write_lesson(testing::scratch_dir(), R"lua(step("Wait", function() wait_for { key = "F" } end)
step("After", function() say("here") end)
)lua")));
  EXPECT_EQ(runner.step_state(), State::Waiting);
  runner.next();
  EXPECT_EQ(runner.step_state(), State::Finished);
  EXPECT_EQ(runner.said(), (Strings{"here"}));
  EXPECT_FALSE(runner.deliver(LessonEvent::key("F")));
}

TEST(LessonRunner, ReloadKeepsTheStepIndex) {
  const auto dir = testing::scratch_dir();
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(write_lesson(dir, R"lua(step("A", function() say("a") end)
step("B", function() say("b") end)
step("C", function() say("c") end)
)lua")));
  runner.next();
  runner.next();
  ASSERT_EQ(runner.current_step(), 2u);
  write_lesson(dir, R"lua(step("A", function() say("a") end)
step("B", function() say("b") end)
step("C, edited", function() say("c, edited") end)
step("D", function() say("d") end)
)lua");
  ASSERT_TRUE(runner.reload()) << runner.error();
  EXPECT_EQ(runner.current_step(), 2u);
  EXPECT_EQ(runner.step_titles(), (Strings{"A", "B", "C, edited", "D"}));
  EXPECT_EQ(runner.said(), (Strings{"c, edited"}));
  write_lesson(dir, R"lua(step("A", function() say("a") end)
step("B only", function() say("b only") end)
)lua");
  ASSERT_TRUE(runner.reload());
  EXPECT_EQ(runner.current_step(), 1u);  // clamped: step 3 is gone
  EXPECT_EQ(runner.said(), (Strings{"b only"}));
}

// ---- errors ----------------------------------------------------------------------------------------

TEST(LessonRunner, ASyntaxErrorOnReloadKeepsTheOldLessonRunning) {
  const auto dir = testing::scratch_dir();
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(write_lesson(dir, R"lua(step("A", function() say("a") end)
step("B", function() say("b") end)
)lua")));
  runner.next();
  write_lesson(dir, R"lua(step("A", function() say("a") end)
step("B", function()
  say("b"
end)
)lua");
  EXPECT_FALSE(runner.reload());
  EXPECT_EQ(runner.error(), "lesson.lua:4: ')' expected (to close '(' at line 3) near 'end'");
  EXPECT_TRUE(runner.loaded());
  EXPECT_EQ(runner.current_step(), 1u);
  runner.back();  // the old version still runs, and the load error stays visible
  EXPECT_EQ(runner.current_step(), 0u);
  EXPECT_EQ(runner.said(), (Strings{"a"}));
  EXPECT_EQ(runner.error(), "lesson.lua:4: ')' expected (to close '(' at line 3) near 'end'");
  write_lesson(dir, R"lua(step("A", function() say("a, fixed") end)
step("B", function() say("b") end)
)lua");
  EXPECT_TRUE(runner.reload());
  EXPECT_EQ(runner.error(), "");
  EXPECT_EQ(runner.said(), (Strings{"a, fixed"}));
}

TEST(LessonRunner, ASyntaxErrorOnFirstLoadLeavesNothingLoaded) {
  HeadlessHost host;
  LessonRunner runner(host);
  EXPECT_FALSE(runner.load(write_lesson(testing::scratch_dir(), "step('A', function()\n  say 'a' +\nend)\n")));
  EXPECT_EQ(runner.error(), "lesson.lua:2: unexpected symbol near '+'");
  EXPECT_FALSE(runner.loaded());
  EXPECT_EQ(runner.step_state(), State::Empty);
  EXPECT_EQ(runner.step_count(), 0u);
  runner.next();
  runner.back();
  runner.update(0.1);
  EXPECT_FALSE(runner.deliver(LessonEvent::key("F")));
  EXPECT_TRUE(runner.said().empty());
  EXPECT_EQ(runner.title(), "");
}

TEST(LessonRunner, ARuntimeErrorInAStepGivesFileLineAndTheRunnerGoesOn) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(write_lesson(testing::scratch_dir(), R"lua(step("Fine", function() say("fine") end)
step("Broken", function()
  say("about to fail")
  local x = nil
  x.y = 1
end)
step("After", function() say("after") end)
)lua")));
  runner.next();
  EXPECT_EQ(runner.step_state(), State::Failed);
  EXPECT_EQ(runner.error(), "lesson.lua:5: attempt to index a nil value (local 'x')");
  EXPECT_EQ(runner.said(), (Strings{"about to fail"}));  // what it said before failing stays
  EXPECT_EQ(runner.waiting_for().kind, LessonWait::Kind::None);
  runner.next();
  EXPECT_EQ(runner.step_state(), State::Finished);
  EXPECT_EQ(runner.error(), "");
  EXPECT_EQ(runner.said(), (Strings{"after"}));
  runner.back();
  EXPECT_EQ(runner.error(), "lesson.lua:5: attempt to index a nil value (local 'x')");
  runner.back();
  EXPECT_EQ(runner.step_state(), State::Finished);
  EXPECT_EQ(runner.said(), (Strings{"fine"}));
}

TEST(LessonRunner, ErrorsInConditionsAnimationsAndAfterAWaitPointAtTheirLine) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(write_lesson(testing::scratch_dir(), R"lua(step("Condition", function()
  wait_for { condition = function() return nil + 1 end }
end)
step("Animation", function()
  animate(1, function(t) if t > 0 then error("frame " .. t) end end)
end)
step("After a wait", function()
  wait_for { key = "F" }
  undefined_function()
end)
)lua")));
  EXPECT_EQ(runner.error(), "lesson.lua:2: attempt to perform arithmetic on a nil value");
  runner.next();
  EXPECT_EQ(runner.step_state(), State::Waiting);
  runner.update(0.5);
  EXPECT_EQ(runner.error(), "lesson.lua:5: frame 0.5");
  runner.next();
  runner.deliver(LessonEvent::key("F"));
  EXPECT_EQ(runner.error(), "lesson.lua:9: attempt to call a nil value (global 'undefined_function')");
}

TEST(LessonRunner, MisusedCallsNameTheCallAndTheLine) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(write_lesson(testing::scratch_dir(), R"lua(step("Empty wait", function() wait_for {} end)
step("Two waits", function() wait_for { key = "F", button = "Go" } end)
step("Typo", function() wait_for { keys = "F" } end)
step("Bad click", function() wait_for { click = "corner" } end)
step("Bad colour", function() highlight("e1", "mauve") end)
step("Bad element", function() label("x7", "no") end)
step("Nested step", function() step("inner", function() end) end)
step("Own coroutine", function() in_own_coroutine(function() wait_for { key = "F" } end) end)
step("Stray yield", function() coroutine.yield() end)
step("Bad show", function() show(42) end)
function in_own_coroutine(f) error(select(2, coroutine.resume(coroutine.create(f))), 0) end
)lua")));
  const Strings expected = {
      "lesson.lua:1: wait_for: say what to wait for: key, command, click, selection, condition or button",
      "lesson.lua:2: wait_for: wait for one thing at a time (key, command, click, selection, condition or button)",
      "lesson.lua:3: wait_for: unknown field 'keys' (fields: key, command, click, selection, condition, button, hint)",
      "lesson.lua:4: wait_for: click must be an element kind (vertex, halfedge, edge, face, boundary), an id like "
      "\"e7\", an element or \"any\"; got 'corner'",
      "lesson.lua:5: unknown colour 'mauve' (use red, green, blue, yellow, orange, magenta, pink, cyan, purple, "
      "white, grey, gray, black, \"#rrggbb\" or {r, g, b} from 0 to 1)",
      "lesson.lua:6: label: 'x7' is not an element id (like v3, h12, e7, f2, b0)",
      "lesson.lua:7: step() can only be used at the top level of a lesson file, not inside a step",
      "lesson.lua:8: wait_for() works in the step itself, not inside a coroutine of your own",
      "lesson.lua:9: coroutine.yield stopped the step; wait with wait_for or animate",
      "lesson.lua:10: show: expected a mesh, a curve (a list of points) or patches (a list of 16-point lists), "
      "got number",
  };
  for (size_t i = 0; i < expected.size(); ++i) {
    runner.go_to(i);
    EXPECT_EQ(runner.step_state(), State::Failed) << "step " << i + 1;
    EXPECT_EQ(runner.error(), expected[i]) << "step " << i + 1;
  }
}

TEST(LessonRunner, SceneCallsAtTheTopLevelAreLoadErrors) {
  HeadlessHost host;
  LessonRunner runner(host);
  EXPECT_FALSE(runner.load(write_lesson(testing::scratch_dir(), "local m = meshedit.cube()\nshow(m)\n")));
  EXPECT_EQ(runner.error(), "lesson.lua:2: show() can only be used inside a step: step(\"title\", function() ... end)");
  EXPECT_TRUE(host.calls().empty());
}

TEST(LessonRunner, AFileWithoutStepsIsALoadError) {
  HeadlessHost host;
  LessonRunner runner(host);
  EXPECT_FALSE(runner.load(write_lesson(testing::scratch_dir(), "lesson { title = 'Empty' }\n")));
  EXPECT_EQ(runner.error(), "lesson.lua: no steps (a lesson defines them with step(\"title\", function() ... end))");
  EXPECT_FALSE(runner.loaded());
}

TEST(LessonRunner, AMissingFileIsALoadError) {
  const auto dir = testing::scratch_dir();
  HeadlessHost host;
  LessonRunner runner(host);
  EXPECT_FALSE(runner.load(dir / "nope.lua"));
  EXPECT_EQ(runner.error(), "cannot open " + (dir / "nope.lua").string());
  EXPECT_FALSE(runner.loaded());
  EXPECT_FALSE(runner.reload());  // still missing
  EXPECT_EQ(runner.error(), "cannot open " + (dir / "nope.lua").string());
  write_lesson(dir, "step('Now here', function() say('found') end)\n", "nope.lua");
  EXPECT_TRUE(runner.reload());
  EXPECT_EQ(runner.said(), (Strings{"found"}));
}

// ---- limits ----------------------------------------------------------------------------------------

TEST(LessonRunner, AnEndlessLoopInAStepStopsWithTheBudgetMessage) {
  HeadlessHost host;
  LessonRunner runner(host, small_budget(1'000'000));
  ASSERT_TRUE(runner.load(write_lesson(testing::scratch_dir(), R"lua(step("Endless", function()
  say("spinning")
  while true do pcall(function() while true do end end) end
end)
step("Endless condition", function()
  wait_for { condition = function() while true do end end }
end)
step("After", function() say("still working") end)
)lua")));
  EXPECT_EQ(runner.step_state(), State::Failed);
  EXPECT_EQ(runner.error(), "lesson.lua:3: instruction budget exceeded (1000000 instructions)");
  runner.next();
  EXPECT_EQ(runner.error(), "lesson.lua:6: instruction budget exceeded (1000000 instructions)");
  runner.next();
  EXPECT_EQ(runner.step_state(), State::Finished);
  EXPECT_EQ(runner.said(), (Strings{"still working"}));
}

TEST(LessonRunner, AMemoryHogStopsAtItsLineAndTheNextStepStillRuns) {
  HeadlessHost host;
  LuaLimits limits = LessonRunner::default_limits();
  limits.memory_bytes = size_t(32) << 20;
  LessonRunner runner(host, limits);
  ASSERT_TRUE(runner.load(write_lesson(testing::scratch_dir(), R"lua(step("Hog", function()
  local t = {}
  while true do pcall(function() t[#t + 1] = string.rep("x", 100000) .. #t end) end
end)
step("After", function() say("recovered") end)
)lua")));
  EXPECT_EQ(runner.step_state(), State::Failed);
  EXPECT_EQ(runner.error(), "lesson.lua:3: memory limit exceeded (32 MB)");
  runner.next();
  EXPECT_EQ(runner.step_state(), State::Finished) << runner.error();
  EXPECT_EQ(runner.said(), (Strings{"recovered"}));
}

// A lesson may say the words "memory ran out" itself: that is the lesson's error, not memory running out (the runner
// tells them apart by where the error was caught, never by its text).
TEST(LessonRunner, ALessonsOwnMemoryRanOutErrorIsNotOutOfMemory) {
  HeadlessHost host;
  LessonRunner runner(host);
  const auto dir = testing::scratch_dir();
  ASSERT_TRUE(runner.load(write_lesson(dir, R"lua(lesson { title = "Says it" }
step("Says", function() error("memory ran out") end)
)lua")));
  EXPECT_EQ(runner.step_state(), State::Failed);
  EXPECT_EQ(runner.error(), "lesson.lua:2: memory ran out");
  EXPECT_FALSE(runner.out_of_memory());
  EXPECT_FALSE(runner.load(write_lesson(dir, "error('memory ran out')\n", "loading.lua")));
  EXPECT_EQ(runner.error(), "loading.lua:1: memory ran out");
  EXPECT_FALSE(runner.out_of_memory());
  EXPECT_EQ(runner.title(), "Says it");  // the lesson that ran goes on
}

TEST(LessonRunner, EachResumeHasItsOwnBudget) {
  HeadlessHost host;
  LessonRunner runner(host, small_budget(1'000'000));
  // Each stretch costs about 600k instructions: three of them exceed one budget, but never one resume's.
  ASSERT_TRUE(runner.load(write_lesson(testing::scratch_dir(), R"lua(local function burn() for i = 1, 600000 do end end
step("Long", function()
  burn()
  wait_for { key = "A" }
  burn()
  wait_for { key = "B" }
  burn()
  say("done")
end)
)lua")));
  EXPECT_TRUE(runner.deliver(LessonEvent::key("A")));
  EXPECT_TRUE(runner.deliver(LessonEvent::key("B")));
  EXPECT_EQ(runner.step_state(), State::Finished) << runner.error();
  EXPECT_EQ(runner.said(), (Strings{"done"}));
}

// ---- the host and print ----------------------------------------------------------------------------

class ThrowingHost : public HeadlessHost {
 public:
  void show_mesh(std::shared_ptr<HalfedgeMesh>, std::optional<UpAxis>) override {
    throw std::runtime_error("no GPU today");
  }
};

TEST(LessonRunner, AHostExceptionBecomesAStepError) {
  ThrowingHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(write_lesson(testing::scratch_dir(), R"lua(step("Show", function()
  show(meshedit.cube())
end)
)lua")));
  EXPECT_EQ(runner.step_state(), State::Failed);
  EXPECT_EQ(runner.error(), "lesson.lua:2: no GPU today");
}

// A host that calls back into the runner from a host call: the runner ignores it.
class ReentrantHost : public HeadlessHost {
 public:
  LessonRunner* runner = nullptr;
  bool delivered = true;
  void highlight(ElementRef element, glm::vec3 colour) override {
    HeadlessHost::highlight(element, colour);
    delivered = runner->deliver(LessonEvent::key("F"));
    runner->next();
  }
};

TEST(LessonRunner, CallsFromInsideAHostCallAreIgnored) {
  ReentrantHost host;
  LessonRunner runner(host);
  host.runner = &runner;
  ASSERT_TRUE(runner.load(write_lesson(testing::scratch_dir(), R"lua(step("A", function()
  highlight("v1")
  say("a")
end)
step("B", function() say("b") end)
)lua")));
  EXPECT_FALSE(host.delivered);
  EXPECT_EQ(runner.current_step(), 0u);
  EXPECT_EQ(runner.said(), (Strings{"a"}));
}

TEST(LessonRunner, PrintGoesToTheCallback) {
  HeadlessHost host;
  LessonRunner runner(host);
  Strings printed;
  runner.set_print([&](const std::string& line) { printed.push_back(line); });
  ASSERT_TRUE(runner.load(write_lesson(testing::scratch_dir(), R"lua(print("loading", 1)
step("A", function() print("in step") end)
)lua")));
  EXPECT_EQ(printed, (Strings{"loading\t1", "in step"}));
}

}  // namespace
}  // namespace meshedit
