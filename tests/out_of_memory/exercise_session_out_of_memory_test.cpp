// The exercise session's runs (document/exercise_session.h: mine and the reference, on the selection) when memory runs
// out at any allocation they make: copying the mesh for the exercise's input, running it, building the label and the
// status line, and the document's own. Each run has its Nth allocation fail (FailingAllocations), or the Nth and
// every later one, for N = 1, 2, ... until it gets through without a failure. Each time nothing escapes, and it keeps
// document_actions.h's contract: the run was not done (mesh, version, history as they were; an Error that says memory
// ran out where memory to spare would have changed the mesh) or was done as the document keeps it (the mesh memory to
// spare gives, recorded, or kept without its record and said so), and then the session's last run names the state
// the document shows. A message other than the one memory to spare gives says memory ran out, as a Warning or worse.
// Then, with memory to spare, the same run gives what it gives from the start. Finishing a replay, the first thing a
// run does, is whole or nothing too, and a student file whose load ran out of memory is loaded again at the next run.
#include <filesystem>
#include <memory>
#include <new>
#include <ostream>
#include <string>

#include <gtest/gtest.h>

#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/primitives.h"
#include "core/validate.h"
#include "document/exercise_session.h"
#include "document/student_file.h"
#include "support/failing_allocations.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

using testing::FailingAllocations;
using Later = FailingAllocations::Later;

struct Case {
  const char* name;
  Exercise exercise;
  bool mine;
  ElementRef selected;
  bool loaded_before = true;  // false: the run loads the student file first
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

// The solutions the script tests grade: mine with the correct flip changes the mesh as the reference does.
std::filesystem::path solutions() { return testing::source_dir() / "tests" / "exercise" / "solutions"; }

bool says_memory_ran_out(const DocumentMessage& message) {
  return message.severity != Severity::Info && message.text.find(kMemoryRanOut) != std::string::npos;
}

class ExerciseSessionOutOfMemory : public ::testing::TestWithParam<Case> {
 protected:
  // A cube with a flip behind it, the session on the case's exercise with the student file loaded.
  void fresh() {
    doc_ = make_document(build_halfedge_mesh(make_cube()));
    ASSERT_TRUE(apply_operation(doc_, "flip e3", [](HalfedgeMesh& m) { return flip(m, EdgeId(3)); }).ok());
    session_ = std::make_unique<ExerciseSession>(solutions());
    ASSERT_TRUE(session_->set_exercise(GetParam().exercise));
    if (GetParam().loaded_before) {
      ASSERT_TRUE(session_->ensure_loaded()) << session_->load_error();
    }
    selection_ = {};
    selection_.selected = GetParam().selected;
  }
  Check run() {
    return GetParam().mine ? session_->run_mine(doc_, selection_) : session_->run_reference(doc_, selection_);
  }

  MeshDocument doc_;
  Selection selection_;
  std::unique_ptr<ExerciseSession> session_;
};

TEST_P(ExerciseSessionOutOfMemory, ARunIsDoneAsTheDocumentKeepsItOrNotAtAll) {
  fresh();
  const HalfedgeMesh start = doc_.mesh;
  const Check spare_check = run();
  const HalfedgeMesh spare_mesh = doc_.mesh;
  const DocumentMessage spare = doc_.message;
  const size_t spare_depth = doc_.history.undo_depth();
  const bool spare_changes = !spare_mesh.same_as(start);
  for (const Later later : {Later::Succeed, Later::Fail}) {
    for (size_t n = 1;; ++n) {
      SCOPED_TRACE(n);
      fresh();
      const uint64_t version = doc_.mesh.version();
      const size_t depth = doc_.history.undo_depth();
      bool escaped = false, failed = false;
      {
        const FailingAllocations failing(n, later);
        try {
          (void)run();
        } catch (...) {
          escaped = true;
        }
        failed = failing.failed();
      }
      EXPECT_FALSE(escaped);
      if (doc_.message.text != spare.text || doc_.message.severity != spare.severity) {
        EXPECT_TRUE(says_memory_ran_out(doc_.message)) << doc_.message.text;
      }
      EXPECT_TRUE(!selection_.selected.valid() || doc_.mesh.alive(selection_.selected));
      if (doc_.mesh.version() == version) {
        EXPECT_TRUE(doc_.mesh.same_as(start));
        EXPECT_EQ(doc_.history.undo_depth(), depth);
        if (spare_changes) {
          EXPECT_EQ(doc_.message.severity, Severity::Error) << doc_.message.text;
        }
      } else {
        EXPECT_TRUE(spare_changes);
        EXPECT_TRUE(doc_.mesh.same_as(spare_mesh)) << doc_.message.text;
        EXPECT_TRUE(validate(doc_.mesh).ok());
        if (doc_.last.recorded) {
          EXPECT_EQ(doc_.history.undo_depth(), spare_depth);
        } else {
          EXPECT_NE(doc_.message.severity, Severity::Info);
        }
        ASSERT_TRUE(session_->last_run().has_value());
        EXPECT_EQ(session_->last_run()->generation, doc_.generation);
        EXPECT_EQ(session_->last_run()->version, doc_.mesh.version());
      }
      if (GetParam().mine) {  // with memory to spare again: a student file that ran out loading loads now
        EXPECT_TRUE(session_->ensure_loaded()) << session_->load_error();
      }
      fresh();
      EXPECT_EQ(run().ok, spare_check.ok);
      EXPECT_EQ(doc_.message.text, spare.text);
      if (!failed || HasFailure()) break;
    }
  }
}

// What a run does first: a replay in progress is finished whole (the operation's final state shown, the replay over),
// or what stopped it is thrown with the replay going on as it was.
TEST(ExerciseSessionReplayOutOfMemory, AReplayIsFinishedWholeOrGoesOn) {
  for (const Later later : {Later::Succeed, Later::Fail}) {
    for (size_t n = 1;; ++n) {
      SCOPED_TRACE(n);
      MeshDocument doc = make_document(build_halfedge_mesh(make_cube()));
      Selection selection;
      selection.selected = EdgeId(7);
      ExerciseSession session(solutions());
      ASSERT_TRUE(session.run_mine(doc, selection).ok) << doc.message.text;
      const HalfedgeMesh final_state = doc.mesh;
      ASSERT_TRUE(session.start_replay(doc).ok);
      ASSERT_TRUE(session.replay_step(doc, 1).ok);
      const HalfedgeMesh frame = doc.mesh;
      const uint64_t version = doc.mesh.version();
      bool escaped = false, failed = false;
      {
        const FailingAllocations failing(n, later);
        try {
          session.finish_replay(doc);
        } catch (const std::bad_alloc&) {
          escaped = true;
        }
        failed = failing.failed();
      }
      if (escaped) {
        EXPECT_TRUE(session.replaying());
        EXPECT_TRUE(doc.mesh.same_as(frame));
        EXPECT_EQ(doc.mesh.version(), version);
      } else {
        EXPECT_FALSE(session.replaying());
        EXPECT_TRUE(doc.mesh.same_as(final_state));
        EXPECT_TRUE(session.can_replay(doc));
      }
      if (!failed || HasFailure()) break;
    }
  }
}

// A student file that did not load for lack of memory is not the file's fault: it says memory ran out, and the next
// call loads it again (not only once the file changes).
TEST(StudentFileOutOfMemory, ALoadThatRanOutIsTriedAgain) {
  const std::filesystem::path file = solutions() / "flip.lua";
  for (const Later later : {Later::Succeed, Later::Fail}) {
    for (size_t n = 1;; ++n) {
      SCOPED_TRACE(n);
      StudentFile student(file);
      bool loaded = false, escaped = false, failed = false;
      {
        const FailingAllocations failing(n, later);
        try {
          loaded = student.ensure_loaded();
        } catch (...) {
          escaped = true;
        }
        failed = failing.failed();
      }
      EXPECT_FALSE(escaped);
      if (!loaded && !escaped) {
        EXPECT_NE(student.error().find("memory"), std::string::npos) << student.error();
      }
      EXPECT_TRUE(student.ensure_loaded()) << student.error();  // with memory to spare again
      if (!failed || HasFailure()) break;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Runs, ExerciseSessionOutOfMemory,
                         ::testing::Values(Case{"MineFlip", Exercise::FlipEdge, true, EdgeId(7)},
                                           Case{"ReferenceFlip", Exercise::FlipEdge, false, EdgeId(7)},
                                           Case{"ReferenceSplit", Exercise::SplitEdge, false, HalfedgeId(4)},
                                           Case{"ReferenceNormal", Exercise::VertexNormal, false, VertexId(2)},
                                           Case{"MineWithAFaceSelected", Exercise::FlipEdge, true, FaceId::face(1)},
                                           Case{"MineLoadingTheFile", Exercise::FlipEdge, true, EdgeId(7), false}),
                         [](const ::testing::TestParamInfo<Case>& param) { return std::string(param.param.name); });

}  // namespace
}  // namespace meshedit
