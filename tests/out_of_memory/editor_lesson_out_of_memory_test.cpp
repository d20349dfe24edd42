// Opening a lesson in the window (EditorApp::open, open_lesson) when memory runs out: FailingAllocations fails the
// Nth allocation, or the Nth and every later one, for N = 1, 2, ... until the call gets through without a failure.
// The window shows a torus and runs an earlier lesson. Each time nothing escapes, and the lesson is opened whole or
// not at all: either the runner runs the new lesson, the window is titled after it and the status line says it was
// opened; or the runner still runs the earlier lesson, the title is the earlier one, the document is as it was and
// the status line is an Error that says memory ran out. The new lesson's first step shows a tetrahedron: it either
// ran (the document is the tetrahedron, whole) or stopped on an error that says memory
// ran out, with the document the torus as it was or the tetrahedron whole. Then, with memory to spare, the lesson
// opens and its first step runs. The window's part of a lesson's show(mesh) alone is whole or nothing too: the mesh is
// shown, or what stopped it is thrown (for the step's error) with the document as it was. So are a reload of a lesson
// saved with a new title (reload_lesson: the new version under its title, or the old one under its own), and going
// back to the list of lessons (show_lesson_list: a fresh runner and no highlights, or the lesson with its highlights).
// EditorApp needs an OpenGL context: a surfaceless EGL one, as the render tests use; skipped where none can be made.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/editor_app.h"
#include "core/mesh_build.h"
#include "core/primitives.h"
#include "core/validate.h"
#include "render/gl_test_support.h"
#include "support/failing_allocations.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;
using testing::FailingAllocations;
using Later = FailingAllocations::Later;

class EditorLessonOutOfMemory : public testing::GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    if (IsSkipped()) return;
    dir_ = fs::temp_directory_path() / ("meshedit_lesson_oom_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    earlier_ = dir_ / "earlier.lua";
    std::ofstream(earlier_) << "lesson { title = \"An earlier lesson\" }\n"
                               "step(\"Only\", function() say(\"the earlier lesson's only step\") end)\n";
    lesson_ = dir_ / "memory.lua";
    std::ofstream(lesson_) << "lesson { title = \"Running short of memory\" }\n"
                              "local shape = meshedit.tetrahedron()\n"
                              "step(\"Shown\", function()\n"
                              "  show(shape)\n"
                              "  say(\"a tetrahedron, shown by the first step with a long sentence\")\n"
                              "end)\n"
                              "step(\"Second\", function() say(\"second\") end)\n";
  }
  void TearDown() override {
    app_.reset();  // its GL objects go while the context is current
    if (!dir_.empty()) fs::remove_all(dir_);
  }

  // The window showing a torus, running the earlier lesson.
  void fresh_window() {
    app_ = std::make_unique<EditorApp>();
    app_->show_mesh(build_halfedge_mesh(make_torus(5, 7)), "torus.obj");
    ASSERT_TRUE(app_->lessons().open(earlier_)) << app_->lesson().error();
  }

  std::unique_ptr<EditorApp> app_;
  fs::path dir_, earlier_, lesson_;
};

bool says_memory_ran_out(const std::string& text) { return text.find("memory") != std::string::npos; }

TEST_F(EditorLessonOutOfMemory, ALessonOpensWholeOrNotAtAll) {
  const HalfedgeMesh tetrahedron = build_halfedge_mesh(make_tetrahedron());
  fresh_window();
  ASSERT_TRUE(app_->open(lesson_));
  ASSERT_EQ(app_->title(), "MeshEdit - Running short of memory");
  ASSERT_TRUE(app_->document().mesh.same_as(tetrahedron));
  const std::string spare = app_->document().message.text;
  ASSERT_EQ(spare, "lesson memory.lua");
  const std::vector<std::string> said = {"a tetrahedron, shown by the first step with a long sentence"};
  ASSERT_EQ(app_->lesson().said(), said);
  for (const Later later : {Later::Succeed, Later::Fail}) {
    for (size_t n = 1;; ++n) {
      SCOPED_TRACE(n);
      fresh_window();
      const MeshDocument& doc = app_->document();
      const HalfedgeMesh torus = doc.mesh;
      const uint64_t generation = doc.generation;
      const std::string title = app_->title();
      bool opened = false, escaped = false, failed = false;
      {
        const FailingAllocations failing(n, later);
        try {
          opened = app_->open(lesson_);
        } catch (...) {
          escaped = true;
        }
        failed = failing.failed();
      }
      EXPECT_FALSE(escaped);
      const LessonRunner& lesson = app_->lesson();
      const bool torus_kept = doc.mesh.same_as(torus) && doc.generation == generation;
      const bool tetrahedron_shown =
          doc.mesh.same_as(tetrahedron) && doc.generation == generation + 1 && validate(doc.mesh).ok();
      if (opened) {
        EXPECT_EQ(lesson.title(), "Running short of memory");
        EXPECT_EQ(app_->title(), "MeshEdit - Running short of memory");
        EXPECT_EQ(doc.message.text, spare);
        if (lesson.step_state() == LessonRunner::StepState::Failed) {
          EXPECT_TRUE(says_memory_ran_out(lesson.error())) << lesson.error();
          EXPECT_TRUE(torus_kept || tetrahedron_shown);
        } else {
          EXPECT_TRUE(lesson.error().empty()) << lesson.error();
          EXPECT_EQ(lesson.said(), said);
          EXPECT_TRUE(tetrahedron_shown);
        }
      } else {
        EXPECT_EQ(lesson.title(), "An earlier lesson");
        EXPECT_EQ(app_->title(), title);
        EXPECT_TRUE(torus_kept);
        EXPECT_EQ(doc.message.severity, Severity::Error);
        EXPECT_TRUE(says_memory_ran_out(doc.message.text)) << doc.message.text;
      }
      EXPECT_TRUE(app_->open(lesson_));  // with memory to spare again
      EXPECT_EQ(app_->title(), "MeshEdit - Running short of memory");
      EXPECT_EQ(app_->lesson().said(), said);
      EXPECT_TRUE(doc.mesh.same_as(tetrahedron));
      if (!failed || HasFailure()) break;
    }
  }
}

// What a lesson's show(mesh) asks of the window: the mesh shown whole, or an exception with the window as it was.
TEST_F(EditorLessonOutOfMemory, ALessonsMeshIsShownWholeOrNotAtAll) {
  const HalfedgeMesh tetrahedron = build_halfedge_mesh(make_tetrahedron());
  for (const Later later : {Later::Succeed, Later::Fail}) {
    for (size_t n = 1;; ++n) {
      SCOPED_TRACE(n);
      fresh_window();
      const MeshDocument& doc = app_->document();
      const HalfedgeMesh torus = doc.mesh;
      const uint64_t generation = doc.generation;
      bool escaped = false, failed = false;
      {
        const FailingAllocations failing(n, later);
        try {
          app_->view().show_lesson_mesh(tetrahedron, true);
        } catch (const std::bad_alloc&) {
          escaped = true;
        }
        failed = failing.failed();
      }
      if (escaped) {
        EXPECT_TRUE(doc.mesh.same_as(torus));
        EXPECT_EQ(doc.generation, generation);
      } else {
        EXPECT_TRUE(doc.mesh.same_as(tetrahedron));
        EXPECT_EQ(doc.generation, generation + 1);
        EXPECT_TRUE(validate(doc.mesh).ok());
      }
      if (!failed || HasFailure()) break;
    }
  }
}

// The panel's Reload and hot reload (reload_lesson) of a lesson saved with a new title: the new version runs under its
// title, or the version that ran goes on under its own and the outcome says memory ran out (hot reload tries again).
TEST_F(EditorLessonOutOfMemory, AReloadIsWholeOrNotAtAll) {
  const std::string saved =
      "lesson { title = \"A renamed lesson\" }\n"
      "step(\"Only\", function() say(\"the renamed lesson's only step\") end)\n";
  const std::string earlier = testing::read_text(earlier_);
  for (const Later later : {Later::Succeed, Later::Fail}) {
    for (size_t n = 1;; ++n) {
      SCOPED_TRACE(n);
      std::ofstream(earlier_, std::ios::binary) << earlier;
      fresh_window();
      std::ofstream(earlier_, std::ios::binary) << saved;
      ReloadOutcome outcome = ReloadOutcome::Failed;
      bool escaped = false, failed = false;
      {
        const FailingAllocations failing(n, later);
        try {
          outcome = app_->lessons().reload();
        } catch (...) {
          escaped = true;
        }
        failed = failing.failed();
      }
      EXPECT_FALSE(escaped);
      if (outcome == ReloadOutcome::Reloaded) {
        EXPECT_EQ(app_->lesson().title(), "A renamed lesson");
        EXPECT_EQ(app_->title(), "MeshEdit - A renamed lesson");
      } else {
        EXPECT_EQ(outcome, ReloadOutcome::OutOfMemory);
        EXPECT_EQ(app_->lesson().title(), "An earlier lesson");
        EXPECT_EQ(app_->title(), "MeshEdit - An earlier lesson");
        EXPECT_EQ(app_->lessons().reload(), ReloadOutcome::Reloaded) << app_->lesson().error();  // memory to spare
        EXPECT_EQ(app_->title(), "MeshEdit - A renamed lesson");
      }
      if (!failed || HasFailure()) break;
    }
  }
  std::ofstream(earlier_, std::ios::binary) << earlier;
}

// The lesson panel's "Lessons" (show_lesson_list): a fresh runner and no marks, or (memory ran out making the runner)
// the lesson that ran, with its highlight and label, and the exception for the frame guard.
TEST_F(EditorLessonOutOfMemory, GoingBackToTheListIsWholeOrNothing) {
  const fs::path marked = dir_ / "marked.lua";
  std::ofstream(marked) << "lesson { title = \"Marked\" }\n"
                           "step(\"Marks\", function()\n"
                           "  local cube = meshedit.cube()\n"
                           "  show(cube)\n"
                           "  highlight(cube:vertex(3), \"red\")\n"
                           "  label(cube:vertex(3), \"a vertex worth a label\")\n"
                           "end)\n";
  for (const Later later : {Later::Succeed, Later::Fail}) {
    for (size_t n = 1;; ++n) {
      SCOPED_TRACE(n);
      fresh_window();
      ASSERT_TRUE(app_->lessons().open(marked)) << app_->lesson().error();
      ASSERT_EQ(app_->lessons().marks().highlights.size(), 1u) << app_->lesson().error();
      ASSERT_EQ(app_->lessons().marks().labels.size(), 1u);
      const LessonRunner* before = &app_->lesson();
      bool escaped = false, failed = false;
      {
        const FailingAllocations failing(n, later);
        try {
          app_->lessons().show_list();
        } catch (const std::bad_alloc&) {
          escaped = true;
        }
        failed = failing.failed();
      }
      const LessonMarks& marks = app_->lessons().marks();
      if (escaped) {
        EXPECT_EQ(&app_->lesson(), before);
        EXPECT_EQ(app_->lesson().title(), "Marked");
        ASSERT_EQ(marks.highlights.size(), 1u);
        EXPECT_EQ(marks.highlights[0].first, ElementRef(VertexId(3)));
        ASSERT_EQ(marks.labels.size(), 1u);
        EXPECT_EQ(marks.labels[0].second, "a vertex worth a label");
      } else {
        EXPECT_FALSE(app_->lesson().loaded());
        EXPECT_TRUE(marks.highlights.empty());
        EXPECT_TRUE(marks.labels.empty());
      }
      if (!failed || HasFailure()) break;
    }
  }
}

}  // namespace
}  // namespace meshedit
