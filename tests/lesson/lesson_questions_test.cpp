// choose, pick and answer on a LessonRunner with a HeadlessHost: the right answer returns its value, each wrong answer
// keeps the step waiting with its own feedback (or a default naming it), the hint appears only after a try, what is
// answered stays in the step's blocks, Back asks again from scratch, and every bad argument is a `lesson.lua:N:` error.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "lesson/headless_host.h"
#include "lesson/lesson_runner.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

using Strings = std::vector<std::string>;
using State = LessonRunner::StepState;

std::filesystem::path write_lesson(const std::string& text) {
  const auto path = testing::scratch_dir() / "lesson.lua";
  std::ofstream(path) << text;
  return path;
}

constexpr const char* kChoose = R"lua(step("Choose", function()
  local got = choose {
    "Which halfedge is h1.next after the flip?",
    options = { "h2", "h6", "h4" },
    answer = "h4",
    feedback = { h2 = "h2 is h1.next before the flip.", h4 = "It is the other triangle's outer halfedge." },
    hint = "Look at the other triangle.",
  }
  say("got " .. got)
end)
)lua";

TEST(LessonQuestions, ChooseReturnsTheRightOptionAndAnswersEachWrongOne) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(write_lesson(kChoose))) << runner.error();
  const LessonWait& wait = runner.waiting_for();
  ASSERT_EQ(wait.kind, LessonWait::Kind::Choice) << runner.error();
  EXPECT_EQ(wait.question, "Which halfedge is h1.next after the flip?");
  EXPECT_EQ(wait.options, (Strings{"h2", "h6", "h4"}));
  EXPECT_EQ(wait.where, "lesson.lua:2");
  EXPECT_EQ(wait.tries, 0);
  EXPECT_EQ(wait.feedback, "");
  EXPECT_FALSE(wait.hint_shown());  // not before a try
  EXPECT_EQ(runner.judgements(), 0u);

  EXPECT_FALSE(runner.deliver(LessonEvent::choice("h9")));  // not an option
  EXPECT_FALSE(runner.deliver(LessonEvent::button("h4")));  // a button is not a choice
  EXPECT_FALSE(runner.deliver(LessonEvent::value("h4")));   // nor is typed text
  EXPECT_EQ(runner.judgements(), 0u);

  EXPECT_TRUE(runner.deliver(LessonEvent::choice("h2")));
  EXPECT_EQ(runner.step_state(), State::Waiting);
  EXPECT_EQ(runner.waiting_for().kind, LessonWait::Kind::Choice);
  EXPECT_EQ(runner.waiting_for().tries, 1);
  EXPECT_EQ(runner.waiting_for().feedback, "h2 is h1.next before the flip.");
  EXPECT_TRUE(runner.waiting_for().hint_shown());
  EXPECT_EQ(runner.waiting_for().hint, "Look at the other triangle.");
  EXPECT_FALSE(runner.last_judgement().right);
  EXPECT_EQ(runner.last_judgement().given, "h2");

  EXPECT_TRUE(runner.deliver(LessonEvent::choice("h6")));  // no feedback of its own: the default names it
  EXPECT_EQ(runner.waiting_for().tries, 2);
  EXPECT_EQ(runner.waiting_for().feedback, "h6 is not the answer.");
  EXPECT_EQ(runner.said(), Strings{});

  EXPECT_TRUE(runner.deliver(LessonEvent::choice("h4")));
  EXPECT_EQ(runner.step_state(), State::Finished) << runner.error();
  EXPECT_EQ(runner.said(), Strings{"got h4"});
  EXPECT_EQ(runner.judgements(), 3u);
  ASSERT_EQ(runner.answered().size(), 1u);
  EXPECT_EQ(runner.answered()[0].question, "Which halfedge is h1.next after the flip?");
  EXPECT_EQ(runner.answered()[0].given, "h4");
  EXPECT_TRUE(runner.answered()[0].right);
  EXPECT_EQ(runner.answered()[0].feedback, "It is the other triangle's outer halfedge.");
  // The step shows the question answered, then what it said after.
  ASSERT_EQ(runner.blocks().size(), 2u);
  EXPECT_EQ(runner.blocks()[0].kind, LessonBlock::Kind::Answered);
  EXPECT_EQ(runner.blocks()[1].kind, LessonBlock::Kind::Text);
}

TEST(LessonQuestions, BackAsksAgainWithNoTriesNoFeedbackAndNoAnswers) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(write_lesson(std::string(kChoose) + "step('Two', function() say('two') end)\n")));
  runner.deliver(LessonEvent::choice("h2"));
  runner.deliver(LessonEvent::choice("h4"));
  runner.next();
  runner.back();
  EXPECT_EQ(runner.current_step(), 0u);
  EXPECT_EQ(runner.waiting_for().kind, LessonWait::Kind::Choice);
  EXPECT_EQ(runner.waiting_for().tries, 0);
  EXPECT_EQ(runner.waiting_for().feedback, "");
  EXPECT_FALSE(runner.waiting_for().hint_shown());
  EXPECT_TRUE(runner.answered().empty());
  EXPECT_TRUE(runner.blocks().empty());
  EXPECT_EQ(runner.judgements(), 0u);
}

TEST(LessonQuestions, PickComparesTheClickedElementAndSaysWhyNot) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(write_lesson(R"lua(local grid = meshedit.grid(1, 1)
step("By id", function()
  show(grid)
  local got = pick { "Click h4", answer = grid:halfedge(4), feedback = { h2 = "h2 is h1.next before." } }
  say(tostring(got) .. " on a mesh of " .. got.mesh:num_faces() .. " faces")
end)
step("By function", function()
  show(grid)
  local got = pick {
    "Click any vertex",
    answer = function(e)
      if e.kind == "vertex" then return true, "any vertex will do" end
      return false, "a " .. e.kind .. " is not a vertex"
    end,
    hint = "The dots at the corners.",
  }
  say("vertex " .. tostring(got))
end)
step("Feedback function", function()
  show(grid)
  pick { "Click e2", answer = "e2", feedback = function(e) if e.kind == "edge" then return "another edge" end end }
end)
)lua")))
      << runner.error();
  ASSERT_EQ(runner.waiting_for().kind, LessonWait::Kind::Pick) << runner.error();
  EXPECT_FALSE(runner.deliver(LessonEvent::selection(ElementRef(HalfedgeId(4)))));  // a pick takes clicks only
  EXPECT_TRUE(runner.deliver(LessonEvent::click(ElementRef(HalfedgeId(2)))));
  EXPECT_EQ(runner.waiting_for().feedback, "h2 is h1.next before.");
  EXPECT_TRUE(runner.deliver(LessonEvent::click(ElementRef(FaceId::face(0)))));
  EXPECT_EQ(runner.waiting_for().feedback, "Not f0: look again.");
  EXPECT_EQ(runner.waiting_for().tries, 2);
  EXPECT_TRUE(runner.deliver(LessonEvent::click(ElementRef(HalfedgeId(4)))));
  EXPECT_EQ(runner.said(), Strings{"h4 on a mesh of 2 faces"});  // a handle on a copy of the mesh on screen

  runner.next();
  EXPECT_FALSE(runner.waiting_for().hint_shown());
  runner.deliver(LessonEvent::click(ElementRef(EdgeId(1))));
  EXPECT_EQ(runner.waiting_for().feedback, "a edge is not a vertex");  // the answer function's reason
  EXPECT_TRUE(runner.waiting_for().hint_shown());
  runner.deliver(LessonEvent::click(ElementRef(VertexId(3))));
  EXPECT_EQ(runner.said(), Strings{"vertex v3"});
  EXPECT_EQ(runner.answered().at(0).feedback, "any vertex will do");  // the function's reason for a right answer

  runner.next();
  runner.deliver(LessonEvent::click(ElementRef(EdgeId(1))));
  EXPECT_EQ(runner.waiting_for().feedback, "another edge");
  runner.deliver(LessonEvent::click(ElementRef(VertexId(1))));  // the function gives nothing: the default
  EXPECT_EQ(runner.waiting_for().feedback, "Not v1: look again.");
  runner.deliver(LessonEvent::click(ElementRef(EdgeId(2))));
  EXPECT_EQ(runner.step_state(), State::Finished) << runner.error();
}

TEST(LessonQuestions, APickOnTheCurveJudgesTheTOfTheCurvePointNearestTheClick) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(write_lesson(R"lua(local c = meshedit.curve { {0, 0, 0}, {1, 2, 0}, {3, 2, 0}, {4, 0, 0} }
step("By t", function()
  show(c)
  local t = pick {
    "Click C(0.25)", on = "curve", answer = 0.25, hint = "Near P0.",
    feedback = function(t, p) if t > 0.4 then return string.format("C(%.1f) at (%g, %g)", t, p.x, p.y) end end,
  }
  say(string.format("t = %.3f", t))
end)
step("By function", function()
  show(c)
  pick { "Click the top", on = "curve", answer = function(t) return math.abs(t - 0.5) < 0.01, "the top" end }
end)
)lua")))
      << runner.error();
  ASSERT_EQ(runner.waiting_for().kind, LessonWait::Kind::CurvePick) << runner.error();
  EXPECT_FALSE(runner.deliver(LessonEvent::click(ElementRef(VertexId(0)))));  // a click on the mesh is no answer
  EXPECT_TRUE(runner.deliver(LessonEvent::curve_click({2.0, 1.5}, 0.05)));    // C(0.5)
  EXPECT_EQ(runner.waiting_for().feedback, "C(0.5) at (2, 1.5)");
  EXPECT_EQ(runner.waiting_for().tries, 1);
  EXPECT_TRUE(runner.waiting_for().hint_shown());
  EXPECT_TRUE(runner.deliver(LessonEvent::curve_click({1.5, 1.8}, 0.05)));  // 0.27 from the curve: not counted
  EXPECT_EQ(runner.waiting_for().feedback, "That click is beside the curve: click on the curve itself.");
  EXPECT_EQ(runner.waiting_for().tries, 1);
  EXPECT_TRUE(runner.deliver(LessonEvent::curve_click({0.33, 0.54}, 0.05)));  // near C(0.1): the default names it
  EXPECT_EQ(runner.waiting_for().feedback, "That is C(0.10), the point of the curve at t = 0.10.");
  EXPECT_EQ(runner.waiting_for().tries, 2);
  EXPECT_TRUE(runner.deliver(LessonEvent::curve_click({0.92, 1.13}, 0.05)));  // within 0.04 of t = 0.25
  EXPECT_EQ(runner.step_state(), State::Finished) << runner.error();
  ASSERT_EQ(runner.said().size(), 1U);
  EXPECT_EQ(runner.said()[0].substr(0, 7), "t = 0.2");
  ASSERT_EQ(runner.answered().size(), 1U);
  EXPECT_EQ(runner.answered()[0].given, "C(0.25)");

  runner.next();
  EXPECT_TRUE(runner.deliver(LessonEvent::curve_click({2.0, 1.5}, 0.05)));
  EXPECT_EQ(runner.step_state(), State::Finished) << runner.error();
  EXPECT_EQ(runner.answered().at(0).feedback, "the top");  // the answer function's reason for a right click
}

TEST(LessonQuestions, AnswerReadsANumberOrAPointWithinTheTolerance) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(write_lesson(R"lua(step("Number", function()
  local value = answer {
    "What is B1(0.5)?", number = 0.375, tolerance = 1e-3,
    feedback = function(v) if math.abs(v - 0.125) < 1e-9 then return "that is B0(0.5)" end end,
    hint = "3 t (1 - t)^2",
  }
  say(string.format("%.4f %s", value, math.type(value)))
end)
step("Point", function()
  local p = answer { "Where is C(0.5)?", point = { 2, 1.5 }, tolerance = 0.01 }
  say(tostring(p))
end)
)lua")))
      << runner.error();
  ASSERT_EQ(runner.waiting_for().kind, LessonWait::Kind::Answer) << runner.error();
  EXPECT_EQ(runner.waiting_for().components, 1u);
  EXPECT_FALSE(runner.deliver(LessonEvent::choice("0.375")));

  EXPECT_TRUE(runner.deliver(LessonEvent::value("three eighths")));  // not a number: told how, not counted
  EXPECT_EQ(runner.waiting_for().feedback, "Type a number, like 0.25 or 3/8.");
  EXPECT_EQ(runner.waiting_for().tries, 0);
  EXPECT_FALSE(runner.waiting_for().hint_shown());

  EXPECT_TRUE(runner.deliver(LessonEvent::value("1/8")));
  EXPECT_EQ(runner.waiting_for().feedback, "that is B0(0.5)");
  EXPECT_EQ(runner.waiting_for().tries, 1);
  EXPECT_TRUE(runner.waiting_for().hint_shown());
  EXPECT_TRUE(runner.deliver(LessonEvent::value("0.377")));  // 0.002 off: outside 1e-3
  EXPECT_EQ(runner.waiting_for().feedback, "0.377 is not the answer.");
  EXPECT_TRUE(runner.deliver(LessonEvent::value(" 0.3755 ")));
  EXPECT_EQ(runner.step_state(), State::Finished) << runner.error();
  EXPECT_EQ(runner.said(), Strings{"0.3755 float"});  // the value typed, as a number
  EXPECT_EQ(runner.answered().at(0).given, " 0.3755 ");

  runner.next();
  EXPECT_EQ(runner.waiting_for().components, 2u);
  runner.deliver(LessonEvent::value("2"));
  EXPECT_EQ(runner.waiting_for().feedback, "Type a point as x, y, like 0.5, 1.");
  runner.deliver(LessonEvent::value("(2, 1.6)"));
  EXPECT_EQ(runner.waiting_for().feedback, "(2, 1.6) is not the answer.");
  runner.deliver(LessonEvent::value("{2; 1.505}"));
  EXPECT_EQ(runner.step_state(), State::Finished) << runner.error();
  EXPECT_EQ(runner.said(), Strings{"(2, 1.505, 0)"});  // a vec3 with z = 0
}

TEST(LessonQuestions, AnErrorInTheLessonsFeedbackFailsTheStepAtItsLine) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(write_lesson(R"lua(step("Broken feedback", function()
  answer { "x?", number = 1, feedback = function(v)
    return v.nope
  end }
end)
)lua")));
  runner.deliver(LessonEvent::value("2"));
  EXPECT_EQ(runner.step_state(), State::Failed);
  EXPECT_EQ(runner.error(), "lesson.lua:3: attempt to index a number value (local 'v')");
}

TEST(LessonQuestions, BadArgumentsNameTheCallAndTheLessonLine) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(write_lesson(R"lua(step("1", function() choose { options = { "a", "b" }, answer = "a" } end)
step("2", function() choose { "q", options = { "a", "b" }, answer = "c" } end)
step("3", function() choose { "q", options = { "a" }, answer = "a" } end)
step("4", function() choose { "q", options = { "a", "b" }, answer = "a", feedback = { c = "no" } } end)
step("5", function() choose { "q", options = { "a", "b" }, answer = "a", hints = "x" } end)
step("6", function() pick { "q", answer = "x7" } end)
step("7", function() pick { "q", answer = "h1", feedback = { hh1 = "x" } } end)
step("8", function() answer { "q" } end)
step("9", function() answer { "q", number = 1, point = { 1, 2 } } end)
step("10", function() answer { "q", number = 1, tolerance = -1 } end)
step("11", function() choose "which?" end)
step("12", function() choose { "q", options = { "a", "a" }, answer = "a" } end)
step("13", function() pick { "q", on = "patch", answer = 0.5 } end)
step("14", function() pick { "q", on = "curve", answer = 1.5 } end)
step("15", function() pick { "q", on = "curve", answer = 0.5, feedback = { h1 = "x" } } end)
step("16", function() pick { "q", on = "curve", answer = 0.5, tolerance = "wide" } end)
)lua")));
  const Strings expected = {
      "lesson.lua:1: choose: the question comes first, as text: choose{ \"Which ...?\", ... }, got nil",
      "lesson.lua:2: choose: the answer 'c' is not one of the options (a, b)",
      "lesson.lua:3: choose: give at least two options",
      "lesson.lua:4: choose: feedback for 'c', which is not one of the options (a, b)",
      "lesson.lua:5: choose: unknown field 'hints' (fields: [1], options, answer, feedback, hint)",
      "lesson.lua:6: pick: answer must be an element, an id like \"h4\" or function(element) return ok, why end; got "
      "'x7'",
      "lesson.lua:7: pick: feedback keys are element ids like \"h1\", got 'hh1'",
      "lesson.lua:8: answer: say what the answer is: number = 0.375 or point = {x, y[, z]}",
      "lesson.lua:9: answer: give number = ... or point = {x, y[, z]}, not both",
      "lesson.lua:10: answer: tolerance must be a number >= 0, got number",
      "lesson.lua:11: choose: expected a table like choose{ \"the question\", ... }, got string",
      "lesson.lua:12: choose: the option 'a' is given twice",
      "lesson.lua:13: pick: on must be \"curve\" (a click on the curve view), or left out for a click on the mesh; "
      "got 'patch'",
      "lesson.lua:14: pick on the curve: answer must be the t of the point, from 0 to 1, or function(t, point) return "
      "ok, why end; got 1.5",
      "lesson.lua:15: pick on the curve: feedback must be function(t, point) return text end, got table",
      "lesson.lua:16: pick on the curve: tolerance must be a number >= 0 (in t), got string",
  };
  for (size_t i = 0; i < expected.size(); ++i) {
    runner.go_to(i);
    EXPECT_EQ(runner.step_state(), State::Failed) << "step " << i + 1;
    EXPECT_EQ(runner.error(), expected[i]) << "step " << i + 1;
  }
}

TEST(LessonQuestions, AQuestionAtTheTopLevelIsALoadError) {
  HeadlessHost host;
  LessonRunner runner(host);
  EXPECT_FALSE(
      runner.load(write_lesson("choose { 'q', options = {'a', 'b'}, answer = 'a' }\n"
                               "step('A', function() end)\n")));
  EXPECT_EQ(runner.error(),
            "lesson.lua:1: choose{} can only be used inside a step: step(\"title\", function() ... end)");
}

}  // namespace
}  // namespace meshedit
