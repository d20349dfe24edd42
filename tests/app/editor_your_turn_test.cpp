// The lesson panel's "Show mine vs reference" in the window (EditorApp on a surfaceless EGL context, its frames run
// through a headless ImGui, the button clicked where the panel drew it): lesson 4's last step runs a buggy flip.lua
// (tests/grading/students/flip_forgets_faces.lua) and waits; the button puts the your_turn's diamond in the document
// with the student's flip applied (f0.halfedge left on h2, now in f1), selects e, and the Exercises tab, brought to the
// front, holds mine on e with the lesson's first difference. A curve your_turn turns the curve view's "mine" on for its
// points and t. With no wrong your_turn waiting, the app refuses and changes nothing. Skipped where no EGL context can
// be made.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <thread>

#include "app/editor_app.h"
#include "exercise/exercises.h"
#include "render/gl_test_support.h"
#include "support/imgui_harness.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;
constexpr int kWidth = 1280, kHeight = 800;

class EditorYourTurn : public testing::GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    if (IsSkipped()) return;
    app_ = std::make_unique<EditorApp>();
    student_ = testing::scratch_dir() / "student";
    fs::create_directories(student_);
    app_->exercises().set_folder(student_);  // the lesson's student folder follows the Exercises tab's
  }
  void TearDown() override { app_.reset(); }  // its GL objects go while the context is current

  void student_file(const std::string& fixture, const std::string& as) {
    fs::copy_file(testing::source_dir() / "tests" / "grading" / "students" / (fixture + ".lua"), student_ / as,
                  fs::copy_options::overwrite_existing);
  }
  void draw() { app_->frame(kWidth, kHeight, 16.0f); }
  void frames(int count) {
    for (int i = 0; i < count; ++i) harness_.frame([&] { draw(); });
  }
  // Frames until the lesson's your_turn has its verdict (the student's code runs beside the frames), at most 10 s.
  void until_verdict() {
    for (int i = 0; i < 10000 && app_->lesson().student_code_running(); ++i) {
      frames(1);
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    frames(3);  // the panel brings the verdict into sight
  }
  // Frames until the curve or patch view's "mine" has no call of the student's code running, at most 10 s.
  void until_mine() {
    for (int i = 0; i < 10000 && app_->view().bezier_mine().running(); ++i) {
      frames(1);
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    frames(2);  // the view takes the last call and starts no other
  }
  // Clicks the your_turn's button where the lesson panel drew it in the last frame.
  void click_show_mine() {
    const UiProbe::Item* button = app_->panels().probe().find("lesson-show-mine");
    ASSERT_NE(button, nullptr) << "the lesson panel drew no \"" << kShowMineButton << "\" button";
    harness_.click(button->center(), [&] { draw(); });
  }
  // The first line of a your_turn's diagnosis: the first difference it names.
  static std::string first_line(const std::string& text) { return text.substr(0, text.find('\n')); }

  ui_testing::ImGuiHarness harness_{ImVec2(kWidth, kHeight)};
  std::unique_ptr<EditorApp> app_;
  fs::path student_;
};

TEST_F(EditorYourTurn, LessonFoursButtonRunsTheBuggyFlipOnTheDiamondInTheExercisesTab) {
  student_file("flip_forgets_faces", "flip.lua");
  ASSERT_TRUE(app_->open(testing::source_dir() / "lessons" / "4_edge_flip.lua")) << app_->lesson().error();
  frames(2);
  LessonRunner& lesson = app_->lesson();
  lesson.go_to(6);  // "Before and after, pointer by pointer": a question, then the your_turn
  ASSERT_TRUE(lesson.deliver(LessonEvent::value("4"))) << lesson.error();
  until_verdict();
  ASSERT_EQ(lesson.waiting_for().kind, LessonWait::Kind::YourTurn) << lesson.error();
  ASSERT_EQ(lesson.your_turns().size(), 1u);
  const YourTurnVerdict verdict = lesson.your_turns().back();
  ASSERT_FALSE(verdict.right);
  ASSERT_EQ(verdict.exercise, Exercise::FlipEdge);
  ASSERT_TRUE(verdict.exercise_input.mesh);
  EXPECT_EQ(app_->panels().probe().find("exercises-tab"), nullptr);  // the Exercises tab is not open yet

  // The diamond as the lesson rigged it, by the diagram's names: h0 = e.halfedge, f0.halfedge = h2.
  const HalfedgeMesh& input = *verdict.exercise_input.mesh;
  const EdgeId e(verdict.exercise_input.element.index);
  const HalfedgeId h0 = input.halfedge(e), h1 = input.twin(h0), h2 = input.next(h0);
  const FaceId f0 = input.face(h0), f1 = input.face(h1);
  ASSERT_EQ(input.halfedge(f0), h2);

  click_show_mine();
  frames(1);
  app_->exercises().wait_for_run(app_->document(), app_->selection());  // the student's code runs on its own thread
  frames(1);

  // The document: the your_turn's diamond with the student's flip applied, as the student's file gives it.
  const HalfedgeMesh& shown = app_->document().mesh;
  ASSERT_EQ(shown.num_vertices(), input.num_vertices());
  for (VertexId v : input.vertices()) EXPECT_EQ(shown.position(v), input.position(v)) << format_id(v);
  auto code = load_student_file(student_ / "flip.lua");
  const ExerciseReport expected = check_exercise(*code, verdict.exercise, verdict.exercise_input);
  ASSERT_TRUE(expected.mine.mesh);
  EXPECT_TRUE(shown.same_as(*expected.mine.mesh));
  EXPECT_EQ(shown.halfedge(f0), h2);  // the bug: f0 keeps h2, which the flip moved into f1
  EXPECT_EQ(shown.face(h2), f1);
  EXPECT_EQ(shown.next(h0), input.next(input.next(h0)));  // h0.next = h3: the flip itself happened
  EXPECT_EQ(app_->selection().selected, ElementRef(e));

  // The Exercises tab: in front, its last run mine on e, wrong, with the lesson's first difference.
  EXPECT_NE(app_->panels().probe().find("exercises-tab"), nullptr);
  const std::optional<ExerciseRun>& run = app_->exercises().last_run();
  ASSERT_TRUE(run.has_value());
  EXPECT_TRUE(run->mine);
  EXPECT_EQ(run->exercise, Exercise::FlipEdge);
  EXPECT_EQ(run->input.element, ElementRef(e));
  EXPECT_TRUE(run->applied);
  EXPECT_FALSE(run->report.equal);
  ASSERT_FALSE(run->report.differences.empty());
  EXPECT_EQ(run->report.differences[0], first_line(verdict.feedback));
  EXPECT_EQ(run->report.differences[0], expected.differences[0]);
  EXPECT_FALSE(run->report.mine.edits.empty());  // the replay has the student's writes
  EXPECT_TRUE(app_->exercises().can_replay(app_->document()));
  // The lesson waits on as it did: the button changes nothing of the step.
  EXPECT_EQ(lesson.waiting_for().kind, LessonWait::Kind::YourTurn);
  EXPECT_EQ(lesson.your_turns().size(), 1u);
}

TEST_F(EditorYourTurn, ACurveYourTurnTurnsTheCurveViewsMineOnForItsPointsAndT) {
  student_file("curve_drops_last", "curve.lua");
  const fs::path file = testing::scratch_dir() / "curve_turn.lua";
  std::ofstream(file) << "lesson { title = \"Curve turn\" }\n"
                         "step(\"Yours\", function()\n"
                         "  your_turn { exercise = \"curve\", points = {{0, 0}, {1, 2}, {3, 2}, {4, 0}}, t = 0.3 }\n"
                         "end)\n";
  ASSERT_TRUE(app_->open(file)) << app_->lesson().error();
  until_verdict();
  ASSERT_NE(your_turn_to_show(app_->lesson()), nullptr) << app_->lesson().error();
  EXPECT_FALSE(app_->view().bezier_mine().curve_on());

  click_show_mine();
  frames(2);
  until_mine();

  EXPECT_EQ(app_->mode(), ViewMode::Curve);
  const CurveEditorState& curve = app_->view().curve();
  const std::vector<glm::dvec2> points = {{0, 0}, {1, 2}, {3, 2}, {4, 0}};
  EXPECT_EQ(curve.curve.control_points, points);
  EXPECT_DOUBLE_EQ(curve.t, 0.3);
  EXPECT_EQ(curve.levels_shown, 3);
  ASSERT_TRUE(app_->view().bezier_mine().curve_on());
  // The view's mine ran the student's evaluate_step on the your_turn's input and stopped at its wrong level.
  const CurveMineLevels& mine = app_->view().bezier_mine().curve();
  EXPECT_TRUE(mine.failed()) << mine.message;
  EXPECT_EQ(mine.failed_level, 1) << mine.message;
  EXPECT_FALSE(mine.message.empty());
}

// The curve view's "mine" runs the student's evaluate_step beside the frames: a loop does not hold them, the line
// says it runs, and the window's deadline ends it with its line; a file saved right is computed afresh.
TEST_F(EditorYourTurn, TheCurveViewsMineRunsARunawayStepBesideTheFrames) {
  std::ofstream(student_ / "curve.lua") << "function evaluate_step(points, t)\n  while true do end\nend\n";
  ASSERT_TRUE(app_->open(testing::source_dir() / "assets" / "curve_cubic.bzc"));
  app_->view().bezier_mine().set_folder(student_);
  app_->panels().settings().student_code_seconds = 1.0;
  app_->view().bezier_mine().set_curve_on(true);
  app_->view().curve().levels_shown = 1;
  const auto started = std::chrono::steady_clock::now();
  frames(20);  // twenty frames drawn while the loop runs
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(), 0.9);
  ASSERT_TRUE(app_->view().bezier_mine().running());
  EXPECT_NE(app_->view().bezier_mine().curve().message.find("level 1: your evaluate_step is running ("),
            std::string::npos)
      << app_->view().bezier_mine().curve().message;
  until_mine();
  const CurveMineLevels& stopped = app_->view().bezier_mine().curve();
  EXPECT_EQ(stopped.failed_level, 1);
  EXPECT_EQ(stopped.error, "curve.lua:2: time limit exceeded (1 s)") << stopped.message;

  fs::copy_file(testing::source_dir() / "tests" / "exercise" / "solutions" / "curve.lua", student_ / "curve.lua",
                fs::copy_options::overwrite_existing);
  app_->view().curve().levels_shown = 3;
  frames(1);
  until_mine();
  EXPECT_TRUE(app_->view().bezier_mine().curve().complete()) << app_->view().bezier_mine().curve().message;
  EXPECT_EQ(app_->view().bezier_mine().curve().message, "levels 1 to 3 are the reference's: your curve point is right");
}

// Switching the curve view's "mine" off stops its running call at once (nothing of it is kept), and switching it
// on runs the student's code afresh.
TEST_F(EditorYourTurn, SwitchingTheCurveViewsMineOffStopsItsRunningCall) {
  std::ofstream(student_ / "curve.lua") << "function evaluate_step(points, t)\n  while true do end\nend\n";
  ASSERT_TRUE(app_->open(testing::source_dir() / "assets" / "curve_cubic.bzc"));
  app_->view().bezier_mine().set_folder(student_);
  app_->panels().settings().student_code_seconds = 30.0;
  app_->view().bezier_mine().set_curve_on(true);
  app_->view().curve().levels_shown = 1;
  frames(3);
  ASSERT_TRUE(app_->view().bezier_mine().running());

  const auto off = std::chrono::steady_clock::now();
  app_->view().bezier_mine().set_curve_on(false);
  until_mine();
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - off).count(), 5.0);
  EXPECT_FALSE(app_->view().bezier_mine().running());

  app_->view().bezier_mine().set_curve_on(true);
  frames(3);
  EXPECT_TRUE(app_->view().bezier_mine().running());
  EXPECT_NE(app_->view().bezier_mine().curve().message.find("level 1: your evaluate_step is running ("),
            std::string::npos)
      << app_->view().bezier_mine().curve().message;
  app_->view().bezier_mine().set_curve_on(false);
  until_mine();
}

TEST_F(EditorYourTurn, ARunawayYourTurnRunsBesideTheFramesAndStopEndsItWithItsLine) {
  std::ofstream(student_ / "flip.lua") << "function flip_edge(mesh, e)\n  while true do end\nend\n";
  const fs::path file = student_.parent_path() / "flip_turn.lua";
  std::ofstream(file) << "lesson { title = \"Flip turn\" }\n"
                         "step(\"Yours\", function()\n"
                         "  your_turn { exercise = \"flip\", mesh = meshedit.grid(1, 1), element = \"e2\" }\n"
                         "  say(\"flipped\")\n"
                         "end)\n";
  ASSERT_TRUE(app_->open(file)) << app_->lesson().error();
  LessonRunner& lesson = app_->lesson();
  frames(20);  // twenty frames drawn while the loop runs
  ASSERT_TRUE(lesson.student_code_running()) << lesson.error();
  EXPECT_EQ(lesson.waiting_for().kind, LessonWait::Kind::YourTurnRunning);
  EXPECT_NE(lesson.waiting_for().question.find("your flip_edge in flip.lua is running on e2"), std::string::npos)
      << lesson.waiting_for().question;
  EXPECT_TRUE(lesson.your_turns().empty());

  const UiProbe::Item* stop = app_->panels().probe().find("lesson-stop-mine");
  ASSERT_NE(stop, nullptr) << "the lesson panel drew no Stop";
  harness_.click(stop->center(), [&] { draw(); });
  until_verdict();
  EXPECT_FALSE(lesson.student_code_running());
  ASSERT_EQ(lesson.waiting_for().kind, LessonWait::Kind::YourTurn) << lesson.error();
  ASSERT_EQ(lesson.your_turns().size(), 1u);
  EXPECT_FALSE(lesson.your_turns()[0].right);
  EXPECT_NE(lesson.waiting_for().feedback.find("flip.lua:2: stopped: you pressed Stop"), std::string::npos)
      << lesson.waiting_for().feedback;

  // Leaving the step while a run goes on stops it: the lesson goes on at once.
  std::ofstream(student_ / "flip.lua") << "function flip_edge(mesh, e)\n  while true do end\nend\n-- saved\n";
  for (int i = 0; i < 200 && !lesson.student_code_running(); ++i) {
    frames(1);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_TRUE(lesson.student_code_running());  // the save ran the file again
  lesson.restart_step();
  frames(1);
  EXPECT_TRUE(lesson.student_code_running());  // the step's new run
  EXPECT_EQ(lesson.your_turns().size(), 0u);
}

TEST_F(EditorYourTurn, WithNoWrongYourTurnWaitingItRefusesAndChangesNothing) {
  ASSERT_TRUE(app_->open(testing::source_dir() / "lessons" / "4_edge_flip.lua")) << app_->lesson().error();
  frames(2);
  const HalfedgeMesh before = app_->document().mesh;
  const Check check = app_->show_your_turn_mine();
  EXPECT_FALSE(check.ok);
  EXPECT_NE(check.reason.find("no your_turn waits on a wrong answer"), std::string::npos) << check.reason;
  EXPECT_EQ(app_->document().message.severity, Severity::Warning);
  EXPECT_TRUE(app_->document().mesh.same_as(before));
  EXPECT_FALSE(app_->exercises().last_run().has_value());
  frames(1);
  EXPECT_EQ(app_->panels().probe().find("lesson-show-mine"), nullptr);  // and the panel offers no button
}

}  // namespace
}  // namespace meshedit
