// run_lesson_headless in process: the welcome lesson with its answers file passes every step; every shipped lesson
// has the student act in two thirds of its steps; scripted edits
// reach the mesh the lesson reads; a wait with no answer, a Lua error and a bad answers file fail with one
// line naming the file, line and step.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/loop_subdivision.h"
#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/primitives.h"
#include "core/value_format.h"
#include "exercise/exercise_registry.h"
#include "exercise/scripted_exercise.h"
#include "lesson/lesson_headless.h"
#include "lesson/lesson_runner.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

std::filesystem::path write_file(const std::filesystem::path& dir, const std::string& name, const std::string& text) {
  const auto path = dir / name;
  std::ofstream(path) << text;
  return path;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(LessonHeadless, TheWelcomeLessonPassesWithItsAnswers) {
  const auto source = testing::source_dir();
  std::ostringstream out;
  const auto answers = source / "tests" / "lesson" / "lessons" / "welcome_answers.lua";
  const HeadlessOutcome outcome = run_lesson_headless(source / "lessons" / "welcome.lua", answers, out);
  EXPECT_EQ(outcome.failure, "");
  EXPECT_EQ(outcome.steps, 5u);
  EXPECT_EQ(outcome.passed, 5u);
  const std::string text = out.str();
  EXPECT_EQ(text.rfind("Welcome to MeshEdit (welcome.lua, 5 steps)\n", 0), 0u) << text;
  EXPECT_TRUE(contains(text, "\nstep 3/5: Pick a vertex\n")) << text;
  EXPECT_TRUE(contains(text, "  > key W\n")) << text;
  EXPECT_TRUE(contains(text, "  > click v0\n")) << text;
  // The lesson read the clicked vertex from the mesh on screen: v0 of the cube has degree 6.
  EXPECT_TRUE(contains(text, "  You picked v0. 6 edges meet there")) << text;
  // The flip of step 5 is the core's: e11 of the cube, the front square's diagonal v5-v0, joins the triangles'
  // other corners after.
  HalfedgeMesh cube = build_halfedge_mesh(make_cube());
  ASSERT_TRUE(flip(cube, EdgeId(11)).ok());
  const HalfedgeId h = cube.halfedge(EdgeId(11));
  EXPECT_TRUE(contains(text, "the diagonal of the front square, joins v5 and v0.")) << text;
  EXPECT_TRUE(contains(text, "  > selection e11\n  > flip e11\n  > key F\n")) << text;
  EXPECT_TRUE(contains(text, "e11 now joins " + format_id(cube.vertex(h)) + " and " +
                                 format_id(cube.vertex(cube.twin(h))) + ": it turned inside its two triangles"))
      << text;
  EXPECT_FALSE(contains(text, "**")) << "markdown is printed as plain text";
  EXPECT_FALSE(contains(text, "not awaited")) << text;
  EXPECT_EQ(text.substr(text.size() - std::string("\n5 steps passed\n").size()), "\n5 steps passed\n");
}

constexpr const char* kFlipLesson = R"lua(lesson { title = "Flip" }
step("Show", function() show(meshedit.cube()) say("A cube.") end)
step("Flip it", function()
  wait_for { selection = "e7" }
  wait_for { key = "F" }
  local h = current_mesh():edge(7).halfedge
  say("e7 now joins " .. tostring(h.vertex) .. " and " .. tostring(h.twin.vertex))
end)
)lua";

// Every shipped lesson asks the student to act in at least two thirds of its steps: run headless with its answers
// and the correct solutions, a step the student acts in has an answer line ("  > ...") in the transcript; a step
// that only shows (its Continue pressed by the run itself) has none.
TEST(LessonHeadless, EveryLessonWaitsForTheStudentInTwoThirdsOfItsSteps) {
  const auto source = testing::source_dir();
  ASSERT_EQ(load_exercise_folder(source / "scripts" / "exercises"), std::vector<std::string>{});  // as the CLI does
  size_t lessons = 0;
  for (const auto& entry : std::filesystem::directory_iterator(source / "lessons")) {
    if (entry.path().extension() != ".lua") continue;
    const auto answers = source / "tests" / "lesson" / "lessons" / (entry.path().stem().string() + "_answers.lua");
    ASSERT_TRUE(std::filesystem::exists(answers)) << entry.path() << " has no answers file";
    std::ostringstream out;
    const HeadlessOutcome outcome = run_lesson_headless(entry.path(), answers, out, LessonRunner::default_limits(),
                                                        source / "tests" / "exercise" / "solutions");
    const std::string text = out.str();
    ASSERT_EQ(outcome.failure, "") << text;
    size_t acted = 0;
    for (size_t at = text.find("\nstep "); at != std::string::npos;) {
      const size_t next = text.find("\nstep ", at + 1);
      const std::string body = text.substr(at, next == std::string::npos ? std::string::npos : next - at);
      acted += body.find("\n  > ") != std::string::npos ? 1 : 0;
      at = next;
    }
    EXPECT_GE(acted * 3, outcome.steps * 2)
        << entry.path().filename() << ": the student acts in " << acted << " of " << outcome.steps << " steps\n"
        << text;
    ++lessons;
  }
  EXPECT_GE(lessons, 9u);
}

TEST(LessonHeadless, ScriptedEditsChangeTheMeshTheLessonReads) {
  const auto dir = testing::scratch_dir();
  std::ostringstream out;
  const HeadlessOutcome outcome =
      run_lesson_headless(write_file(dir, "flip.lua", kFlipLesson),
                          testing::source_dir() / "tests" / "lesson" / "lessons" / "flip_answers.lua", out);
  ASSERT_EQ(outcome.failure, "") << out.str();
  EXPECT_EQ(outcome.passed, 2u);
  // What core's flip gives on the same cube.
  HalfedgeMesh cube = build_halfedge_mesh(make_cube());
  ASSERT_TRUE(flip(cube, EdgeId(7)).ok());
  const HalfedgeId h = cube.halfedge(EdgeId(7));
  const std::string expected =
      "  e7 now joins " + format_id(cube.vertex(h)) + " and " + format_id(cube.vertex(cube.twin(h))) + "\n";
  EXPECT_TRUE(contains(out.str(), "  > selection e7\n  > flip e7\n  > key F\n" + expected)) << out.str();
}

TEST(LessonHeadless, AWaitWithoutAnswerFailsNamingFileLineAndStep) {
  const auto dir = testing::scratch_dir();
  std::ostringstream out;
  const HeadlessOutcome outcome = run_lesson_headless(write_file(dir, "lesson.lua", R"lua(step("Look", function() end)
step("Flip it", function()
  wait_for { key = "F" }
end)
)lua"),
                                                      std::nullopt, out);
  EXPECT_EQ(outcome.failure, "lesson.lua:3: step 2 'Flip it': waiting for key F (no scripted answer)");
  EXPECT_EQ(outcome.passed, 1u);
  EXPECT_EQ(outcome.steps, 2u);
  EXPECT_TRUE(contains(out.str(), "\n1 of 2 steps passed\n")) << out.str();
}

TEST(LessonHeadless, WaitsThatNeedNoAnswerGoOnByThemselves) {
  const auto dir = testing::scratch_dir();
  std::ostringstream out;
  const HeadlessOutcome outcome = run_lesson_headless(
      write_file(dir, "lesson.lua", R"lua(step("Auto", function()
  wait_for { button = "Continue" }
  wait_for { condition = function() return true end }
  animate(2, function(t) end)
  say("through")
end)
step("Stray answers", function()
  wait_for { key = "F" }
end)
)lua"),
      write_file(dir, "answers.lua", "return { [2] = { {key = 'X'}, {key = 'F'} }, [1] = {} }\n"), out);
  EXPECT_EQ(outcome.failure, "") << out.str();
  EXPECT_TRUE(contains(out.str(), "  > button Continue (pressed)\n  through\n  done\n")) << out.str();
  EXPECT_TRUE(contains(out.str(), "  > key X (not awaited: the step waits for key F)\n  > key F\n")) << out.str();
  EXPECT_TRUE(contains(out.str(), "\n2 steps passed\n")) << out.str();
}

TEST(LessonHeadless, ALuaErrorInAStepFailsWithItsLine) {
  const auto dir = testing::scratch_dir();
  std::ostringstream out;
  const HeadlessOutcome outcome = run_lesson_headless(write_file(dir, "lesson.lua", R"lua(step("Broken", function()
  say("about to")
  local m = meshedit.cube()
  m:nonsense()
end)
)lua"),
                                                      std::nullopt, out);
  EXPECT_EQ(outcome.failure.rfind("lesson.lua:4: step 1 'Broken': ", 0), 0u) << outcome.failure;
  EXPECT_EQ(outcome.passed, 0u);
}

TEST(LessonHeadless, ALessonThatDoesNotLoadFails) {
  const auto dir = testing::scratch_dir();
  std::ostringstream out;
  const HeadlessOutcome outcome = run_lesson_headless(dir / "missing.lua", std::nullopt, out);
  EXPECT_EQ(outcome.failure, "cannot open " + (dir / "missing.lua").string());
  EXPECT_EQ(outcome.steps, 0u);
}

TEST(LessonHeadless, AnAnswersPathThatIsNoFileIsAnErrorNamingIt) {
  const auto dir = testing::scratch_dir();
  const auto lesson = write_file(dir, "lesson.lua", "step('A', function() end)\n");
  std::ostringstream out;
  const auto fails_with = [&](const std::filesystem::path& answers, const std::string& why) {
    try {
      run_lesson_headless(lesson, answers, out);
      ADD_FAILURE() << "no error for " << answers;
    } catch (const ScriptError& e) {
      EXPECT_EQ(std::string(e.what()), answers.string() + ": " + why);
    }
  };
  fails_with(dir / "missing.lua", "cannot open: No such file or directory");
  fails_with(dir, "cannot open: Is a directory");              // it would read as an empty chunk
  fails_with("/dev/zero", "cannot open: not a regular file");  // it would never end
}

TEST(LessonHeadless, ABadAnswersFileIsAnError) {
  const auto dir = testing::scratch_dir();
  const auto lesson = write_file(dir, "lesson.lua", "step('A', function() end)\n");
  std::ostringstream out;
  const auto fails_with = [&](const std::string& answers, const std::string& message) {
    try {
      run_lesson_headless(lesson, write_file(dir, "answers.lua", answers), out);
      ADD_FAILURE() << "no error for " << answers;
    } catch (const ScriptError& e) {
      EXPECT_EQ(std::string(e.what()), message);
    }
  };
  fails_with("return { [1] = { {press = 'F'} } }\n",
             "answers.lua: step 1, answer 1: unknown answer 'press' (use key, click, selection, button, flip, split, "
             "collapse, subdivide, subdivide_phase, loop_phase, triangulate, open_repaired, choose, answer, curve_t, "
             "patch_uv, curve_click or your_turn)");
  fails_with("return { [1] = { {subdivide = 'butterfly'} } }\n",
             "answers.lua: step 1, answer 1: subdivide must be true or \"loop\", \"catmull-clark\" or \"linear\", got "
             "'butterfly'");
  fails_with("return { [1] = { {triangulate = 'yes'} } }\n", "answers.lua: step 1, answer 1: write triangulate = true");
  fails_with("return { [1] = { {your_turn = 'yes'} } }\n",
             "answers.lua: step 1, answer 1: your_turn must be \"right\" or \"wrong\", got 'yes'");
  fails_with("return { [1] = { {your_turn = 'right', feedback = 'twin'} } }\n",
             "answers.lua: step 1, answer 1: feedback goes with your_turn = \"wrong\"");
  fails_with(
      "return { [1] = { {key = 'F', feedback = 'no'} } }\n",
      "answers.lua: step 1, answer 1: feedback goes with a wrong choose, click, answer, curve_click or your_turn");
  fails_with("return { [1] = { {curve_click = {1}} } }\n",
             "answers.lua: step 1, answer 1: curve_click must be {x, y}, the point clicked in the curve view");
  fails_with("return { [1] = { {answer = {1}} } }\n",
             "answers.lua: step 1, answer 1: answer must be a number, a text as typed (\"3/8\") or {x, y[, z]}");
  fails_with("return { [1] = { {curve_t = 'half'} } }\n",
             "answers.lua: step 1, answer 1: curve_t must be a number from 0 to 1");
  fails_with("return { [1] = { {loop_phase = 1} } }\n", "answers.lua: step 1, answer 1: write loop_phase = true");
  fails_with("return 3\n", "answers.lua: must return a table of answers per step, like { [2] = { {key = \"F\"} } }");
  fails_with("return { ['A'] = { {key = 'F', click = 'v0'} } }\n",
             "answers.lua: step 'A', answer 1: give exactly one answer per table");
  fails_with("return {\n  [1] = { {key = 'F'} \n}\n",
             "answers.lua:4: '}' expected (to close '{' at line 1) near <eof>");
}

TEST(LessonHeadless, ARefusedScriptedEditFails) {
  const auto dir = testing::scratch_dir();
  std::ostringstream out;
  const HeadlessOutcome outcome = run_lesson_headless(
      write_file(dir, "lesson.lua", "step('Flip', function() show(meshedit.cube()) wait_for { key = 'F' } end)\n"),
      write_file(dir, "answers.lua", "return { { {flip = 'v3'} } }\n"), out);
  EXPECT_EQ(outcome.failure, "step 1 'Flip': answer flip = \"v3\": expected an edge id like e7");
}

// Waits for Shift+L four times and says, after each, the counts and where v0 and the first new vertex are.
constexpr const char* kPhaseLesson = R"lua(
local function where(m, i) return i < m:num_vertices() and tostring(m:vertex(i).position) or "-" end
step("Phases", function()
  show(meshedit.cube())
  for phase = 1, 4 do
    wait_for { key = "shift+L" }
    local m = current_mesh()
    say("after " .. phase .. ": " .. m:num_vertices() .. " " .. m:num_edges() .. " " .. m:num_faces()
      .. " v0 " .. where(m, 0) .. " v8 " .. where(m, 8) .. " valid " .. tostring(m:validate()))
  end
end)
)lua";

// What the core's phases give on a cube after `phases` of them, as kPhaseLesson says it.
std::string core_after(int phases) {
  HalfedgeMesh m = build_halfedge_mesh(make_cube());
  OpResult<LoopState> state = loop_compute_positions(m);
  EXPECT_TRUE(state.ok());
  if (phases >= 2) loop_split_edges(m, state.value);
  if (phases >= 3) loop_flip_edges(m, state.value);
  if (phases >= 4) loop_commit_positions(m, state.value);
  const auto where = [&](uint32_t i) {
    return i < m.num_vertices() ? format_position(m.position(VertexId(i))) : std::string("-");
  };
  return "after " + std::to_string(phases) + ": " + std::to_string(m.num_vertices()) + " " +
         std::to_string(m.num_edges()) + " " + std::to_string(m.num_faces()) + " v0 " + where(0) + " v8 " + where(8) +
         " valid true";
}

TEST(LessonHeadless, LoopPhaseAnswersStepThroughTheCoresFourPhases) {
  const auto dir = testing::scratch_dir();
  std::ostringstream out;
  const HeadlessOutcome outcome =
      run_lesson_headless(write_file(dir, "phases.lua", kPhaseLesson),
                          write_file(dir, "answers.lua",
                                     "local p = { {loop_phase = true}, {key = 'shift+L'} }\n"
                                     "return { { p[1], p[2], p[1], p[2], p[1], p[2], p[1], p[2] } }\n"),
                          out);
  ASSERT_EQ(outcome.failure, "") << out.str();
  const std::string text = out.str();
  size_t at = 0;  // each phase, its key and what the lesson saw, in order
  for (int phase = 1; phase <= 4; ++phase) {
    static const char* const names[] = {"", "compute new positions", "split every original edge",
                                        "flip new edges joining an old and a new vertex",
                                        "move every vertex to its new position"};
    const std::string answer =
        "  > loop phase " + std::to_string(phase) + "/4: " + names[phase] + "\n  > key shift+L\n";
    at = text.find(answer, at);
    ASSERT_NE(at, std::string::npos) << answer << text;
    at = text.find("  " + core_after(phase) + "\n", at);
    ASSERT_NE(at, std::string::npos) << core_after(phase) << "\n" << text;
  }
  // Phase 1 moves nothing; phase 4 moves v0 to the course weights' (-0.3125, ...).
  EXPECT_TRUE(contains(core_after(1), "8 18 12 v0 (-0.5, -0.5, -0.5) v8 - valid true"));
  EXPECT_TRUE(contains(core_after(4), "26 72 48 v0 (-0.3125, -0.3125, -0.3125)"));
  EXPECT_FALSE(contains(text, "not awaited")) << text;
}

TEST(LessonHeadless, AnEditBetweenLoopPhasesStartsThemAgain) {
  const auto dir = testing::scratch_dir();
  std::ostringstream out;
  // Phases 1 and 2, then a flip: the next loop_phase is phase 1 of the flipped mesh, and it changes nothing.
  const HeadlessOutcome outcome = run_lesson_headless(
      write_file(dir, "phases.lua", kPhaseLesson),
      write_file(
          dir, "answers.lua",
          "return { { {loop_phase = true}, {key = 'shift+L'}, {loop_phase = true}, {key = 'shift+L'},\n"
          "  {flip = 'e30'}, {loop_phase = true}, {key = 'shift+L'}, {loop_phase = true}, {key = 'shift+L'} } }\n"),
      out);
  ASSERT_EQ(outcome.failure, "") << out.str();
  const std::string text = out.str();
  EXPECT_TRUE(contains(text,
                       "  > flip e30\n  (the mesh changed after Loop phase 2; starting again)\n"
                       "  > loop phase 1/4: compute new positions\n"))
      << text;
  EXPECT_TRUE(contains(text, "after 3: 26 72 48")) << text;    // phase 1 of the new run: still the split cube's counts
  EXPECT_TRUE(contains(text, "after 4: 98 288 192")) << text;  // its phase 2 splits the 72 edges of the flipped mesh
}

}  // namespace
}  // namespace meshedit

namespace meshedit {
namespace {

TEST(LessonHeadlessQuestions, TheAskingDemoPassesNamingEachMistakeWithItsFeedback) {
  const auto lessons = testing::source_dir() / "tests" / "lesson" / "lessons";
  std::ostringstream out;
  const HeadlessOutcome outcome =
      run_lesson_headless(lessons / "asking_demo.lua", lessons / "asking_demo_answers.lua", out);
  const std::string text = out.str();
  EXPECT_EQ(outcome.failure, "");
  EXPECT_EQ(outcome.passed, 4u);
  EXPECT_TRUE(contains(text,
                       "  ? Which halfedge is h1.next after the flip? (h2 | h6 | h4)\n"
                       "  > choose h2: wrong: h2 is h1.next now, before the flip: h2 lies along e2, and the flip "
                       "moves e2.\n"
                       "  hint: After a flip each face is one old outer halfedge, one more outer halfedge and "
                       "the new diagonal.\n"
                       "  > choose h6: wrong: h6 is h0's twin on the boundary: it is in no face, and h1 keeps "
                       "its face.\n"
                       "  > choose h4: right: After the flip h1 goes on to h4, the outer halfedge of the other "
                       "triangle.\n"))
      << text;
  EXPECT_TRUE(contains(text, "  > click f0: wrong: That is a face: click one of the arrows inside the faces.\n"))
      << text;
  EXPECT_TRUE(contains(text, "  > click h4: right\n  You clicked h4.\n")) << text;
  EXPECT_TRUE(contains(text, "  [live] Selected: nothing. Each blue arrow is a face normal.\n")) << text;
  // The live text follows the curve's t when an answer moves it.
  EXPECT_TRUE(contains(text,
                       "  [live] t = 0.50, C(t) = (2.000, 1.500)\n"
                       "  [plot Bernstein weights: B0, B1, B2, B3 for x from 0 to 1, marker at 0.5]\n"))
      << text;
  EXPECT_TRUE(contains(text, "  > curve t = 0.25\n  [live] t = 0.25, C(t) = (0.906, 1.125)\n")) << text;
  EXPECT_TRUE(contains(text, "  > answer three eighths: wrong: Type a number, like 0.25 or 3/8.\n")) << text;
  EXPECT_TRUE(contains(text, "  > answer 0.375: right\n  Yes: B1(0.5) = 0.375.\n")) << text;
  EXPECT_TRUE(contains(text, "  > answer 2, 1.25: wrong: 2, 1.25 is not the answer.\n")) << text;
}

TEST(LessonHeadlessQuestions, AnAnswerThatShouldBeWrongButIsNotFailsTheRun) {
  const auto dir = testing::scratch_dir();
  const auto lesson = write_file(dir, "lesson.lua", R"lua(step("Q", function()
  choose { "Which?", options = { "a", "b", "c" }, answer = "b", feedback = { a = "a is the first" } }
end)
)lua");
  const auto fails_with = [&](const std::string& answers, const std::string& failure) {
    std::ostringstream out;
    const HeadlessOutcome outcome = run_lesson_headless(lesson, write_file(dir, "answers.lua", answers), out);
    EXPECT_EQ(outcome.failure, failure) << out.str();
    EXPECT_EQ(outcome.passed, 0u);
  };
  fails_with("return { { {choose = 'b', feedback = 'first'} } }\n",
             "lesson.lua:2: step 1 'Q': answer choose = \"b\" should be judged wrong with feedback containing "
             "'first', but it was judged right");
  fails_with("return { { {choose = 'c', feedback = 'first'} } }\n",
             "lesson.lua:2: step 1 'Q': answer choose = \"c\" should be judged wrong with feedback containing "
             "'first', but its feedback was 'c is not the answer.'");
  fails_with("return { { {key = 'F'}, {choose = 'a', feedback = 'first'} } }\n",
             "lesson.lua:2: step 1 'Q': waiting for a choice (a, b, c) in 'Which?' (no scripted answer)");
  fails_with("return { { {answer = 1, feedback = 'first'} } }\n",
             "lesson.lua:2: step 1 'Q': answer answer = \"1\" should be judged wrong with feedback containing "
             "'first', but no question judged it");
}

}  // namespace
}  // namespace meshedit
