// Lesson 4's your_turn in the real window under Xvfb, with a buggy flip.lua
// (tests/grading/students/flip_forgets_faces.lua) in the window's student folder (the `exercise flip FOLDER` action):
// the last step waits with the diagnosis the Exercises tab's checker gives on the lesson's rigged diamond;
// `lesson-show-mine` (the panel's "Show mine vs reference") puts that diamond in the document with the student's flip
// applied, pointer for pointer, selects e, and the Exercises tab's last run is mine on e, wrong, with the same first
// difference. At 1280x800 and 1024x640.
#include <gtest/gtest.h>

#include <sstream>

#include "app/window_test_support.h"
#include "core/mesh_build.h"
#include "exercise/exercises.h"
#include "render/image_file.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

using testing::expect_every_pointer;
using testing::run_window;
using testing::WindowRun;
using testing::XServer;
namespace fs = std::filesystem;

// Lesson 4's rigged diamond, built as the lesson builds it: a-b is e0, c above, d below; f0.halfedge = h2,
// f1.halfedge = h4, a.halfedge = h0, b.halfedge = h1 (the diagram's names, walked from h0 = e0.halfedge).
HalfedgeMesh rigged_diamond() {
  PolygonMesh polygons;
  for (const glm::dvec3& p : {glm::dvec3(-1, 0, 0), glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, -1, 0)}) {
    polygons.add_vertex(p);
  }
  polygons.add_face({0, 1, 2});
  polygons.add_face({1, 0, 3});
  HalfedgeMesh mesh = build_halfedge_mesh(polygons);
  const HalfedgeId h0 = mesh.halfedge(EdgeId(0)), h1 = mesh.twin(h0);
  const HalfedgeId h2 = mesh.next(h0), h4 = mesh.next(h1);
  mesh.set_halfedge(mesh.face(h0), h2);
  mesh.set_halfedge(mesh.face(h1), h4);
  mesh.set_halfedge(mesh.vertex(h0), h0);
  mesh.set_halfedge(mesh.vertex(h1), h1);
  return mesh;
}

void run_lesson_four(const std::string& screen) {
  XServer x(screen);
  if (x.display().empty()) GTEST_SKIP() << "no Xvfb";
  const fs::path dir = testing::scratch_dir();
  const fs::path student = dir / "student";
  fs::create_directories(student);
  fs::copy_file(testing::source_dir() / "tests" / "grading" / "students" / "flip_forgets_faces.lua",
                student / "flip.lua");

  // What the lesson's checker says of the student's flip on the diamond, and the mesh it leaves.
  auto input = std::make_shared<const HalfedgeMesh>(rigged_diamond());
  auto code = load_student_file(student / "flip.lua");
  const ExerciseReport report = check_exercise(*code, Exercise::FlipEdge, ExerciseInput::edge(input, EdgeId(0)));
  ASSERT_FALSE(report.equal);
  ASSERT_FALSE(report.differences.empty());
  ASSERT_TRUE(report.mine.mesh);
  const HalfedgeMesh& mine = *report.mine.mesh;
  const HalfedgeId h0 = input->halfedge(EdgeId(0)), h2 = input->next(h0);
  const FaceId f0 = input->face(h0);
  ASSERT_EQ(mine.halfedge(f0), h2);  // the bug: f0 keeps h2 ...
  ASSERT_NE(mine.face(h2), f0);      // ... which the flip moved into f1

  const fs::path shot = dir / ("show_mine_" + screen + ".png");
  std::ostringstream actions;
  actions << "frames 2\n"
          << "exercise flip " << student.string() << "\n";
  for (int i = 0; i < 6; ++i) actions << "lesson-next\n";
  actions << "frames 1\n"
          << "lesson-answer 4\n"
          << "frames 2\n"
          << "expect-lesson-step 7 waiting\n"
          << "expect-lesson-feedback " << report.differences[0] << "\n"
          << "lesson-show-mine\n"
          << "frames 2\n"
          << "expect-selected e0\n"
          << "expect-exercise-run mine: flip e0 (e0 of a mesh with 4 vertices and 2 faces): different: "
          << report.differences[0] << "\n"
          << "expect-field " << format_id(f0) << " halfedge " << format_id(h2) << "\n"
          << expect_every_pointer(mine)
          << "expect-lesson-step 7 waiting\n"  // the button leaves the step waiting on the student's file
          << "screenshot " << shot.string() << "\n"
          << "frames 2\n"
          << "quit\n";
  const WindowRun run =
      run_window(x.display(), testing::source_dir() / "lessons" / "4_edge_flip.lua", actions.str(), dir, screen);
  EXPECT_EQ(run.status, 0) << run.output;
  EXPECT_EQ(std::to_string(read_png(shot).width) + "x" + std::to_string(read_png(shot).height), screen);
}

TEST(WindowYourTurn, ShowMineRunsTheBuggyFlipOfLessonFourInTheExercisesTabAt1280x800) { run_lesson_four("1280x800"); }

TEST(WindowYourTurn, ShowMineRunsTheBuggyFlipOfLessonFourInTheExercisesTabAt1024x640) { run_lesson_four("1024x640"); }

}  // namespace
}  // namespace meshedit
