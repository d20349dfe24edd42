// EditorApp when memory runs out in what it reports itself and in what the window runs outside the frame guard:
// opening a file (a missing one, a mesh, a curve, patches), saving (where nothing can be written, and where it can),
// the files dropped on the window, and a script of actions (--actions). FailingAllocations fails the Nth allocation,
// or the Nth and every later one, for N = 1, 2, ... until the call gets through without a failure. Each time nothing
// escapes; a file is opened or saved whole or not at all: the document, view, title and recent list are all the
// opened file's (the document whole and valid) and a saved file is first in the recent list, or all is as before with
// an Error that says memory ran out; another message than the one memory to spare gives is such an Error; the call
// then works with memory to spare; and the script counts a failed expectation whenever an action was not done.
// EditorApp needs an OpenGL context: a surfaceless EGL one, as the render tests use; skipped where none can be made.
// Nothing draws while allocations fail: the driver's shader compiler may allocate through the replaced operator new.
#include <unistd.h>

#include <deque>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/action_player.h"
#include "app/editor_app.h"
#include "app/scripted_actions.h"
#include "core/mesh_build.h"
#include "core/primitives.h"
#include "core/validate.h"
#include "document/document_actions.h"
#include "render/gl_test_support.h"
#include "support/failing_allocations.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;
using testing::FailingAllocations;
using Later = FailingAllocations::Later;

class EditorAppOutOfMemory : public testing::GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    if (IsSkipped()) return;
    app_ = std::make_unique<EditorApp>();
    dir_ = fs::temp_directory_path() / ("meshedit_app_oom_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    tetrahedron_ = dir_ / "tetrahedron.obj";
    std::ofstream(tetrahedron_) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n";
    missing_ = dir_ / "missing.obj";
    curve_ = dir_ / "curve.bzc";
    std::ofstream(curve_) << "4\n0 0\n0.3 1\n0.7 1\n1 0\n";
    patch_ = dir_ / "patch.bez";  // one flat patch
    std::ofstream patch(patch_);
    patch << "1\n";
    for (int row = 0; row < 4; ++row) {
      for (int col = 0; col < 4; ++col) patch << col << " " << row << " 0" << (col < 3 ? "  " : "\n");
    }
  }
  void TearDown() override {
    app_.reset();  // its GL objects go while the context is current
    if (!dir_.empty()) fs::remove_all(dir_);
  }

  // The window as it starts: a torus, saved as torus.obj (first in the recent list), with one flip behind it, e4
  // selected.
  MeshDocument& fresh_document() {
    app_->show_mesh(build_halfedge_mesh(make_torus(5, 7)), "");
    EXPECT_TRUE(app_->document_room().save(dir_ / "torus.obj"));
    app_->selection().selected = EdgeId(9);
    EXPECT_TRUE(flip_selected(app_->document(), app_->selection()).ok);
    app_->selection().selected = EdgeId(4);
    return app_->document();
  }

  // Runs `call` with the Nth allocation failing; returns whether an allocation failed. Fails the test when
  // something escapes.
  template <class Call>
  bool run_failing(size_t n, Later later, Call&& call) {
    bool escaped = false, failed = false;
    {
      const FailingAllocations failing(n, later);
      try {
        call();
      } catch (...) {
        escaped = true;
      }
      failed = failing.failed();
    }
    EXPECT_FALSE(escaped) << "allocation " << n;
    return failed;
  }

  // `call` fails even with memory to spare, with an Error. Failing each of its allocations in turn, it still fails,
  // leaves the document as it was, and says what it says with memory to spare or that memory ran out, as an Error.
  template <class Call>
  void expect_failure_reported_alone(Call&& call);
  // `call` opens `file` with memory to spare and returns whether it says so. Failing each of its allocations in
  // turn, the window shows the old document, view, title and recent list, and says that memory ran out, or it says
  // it opened `file` and shows it (a mesh file: as the document, whole), under its title, first in the recent list;
  // and with memory to spare again the call opens `file`.
  template <class Call>
  void expect_opened_whole_or_not(const fs::path& file, Call&& call);

  std::unique_ptr<EditorApp> app_;
  fs::path dir_, tetrahedron_, missing_, curve_, patch_;
};

// What a document looked like, to tell whether a call left it alone.
struct Before {
  HalfedgeMesh mesh;
  uint64_t version, generation;
  size_t undo_depth;
};

Before before_of(const MeshDocument& doc) {
  return {doc.mesh, doc.mesh.version(), doc.generation, doc.history.undo_depth()};
}

bool left_alone(const MeshDocument& doc, const Before& before) {
  return doc.mesh.same_as(before.mesh) && doc.mesh.version() == before.version && doc.generation == before.generation &&
         doc.history.undo_depth() == before.undo_depth;
}

// Replaced whole by `opened`: a new generation with no history.
bool replaced_by(const MeshDocument& doc, const Before& before, const HalfedgeMesh& opened) {
  return doc.mesh.same_as(opened) && doc.generation == before.generation + 1 && !doc.history.can_undo() &&
         !doc.history.can_redo() && validate(doc.mesh).ok();
}

// What the window says about the file it shows besides the document: its title and the recent list.
struct Names {
  std::string title;
  std::deque<std::string> recent;
  bool operator==(const Names&) const = default;
};

Names names_of(const EditorApp& app) { return {app.title(), app.document_room().recent_files()}; }

bool is_memory_error(const DocumentMessage& message) {
  return message.severity == Severity::Error && message.text.find(kMemoryRanOut) != std::string::npos;
}

template <class Call>
void EditorAppOutOfMemory::expect_failure_reported_alone(Call&& call) {
  MeshDocument& doc = fresh_document();
  ASSERT_FALSE(call());
  const DocumentMessage spare = doc.message;
  ASSERT_EQ(spare.severity, Severity::Error);
  for (const Later later : {Later::Succeed, Later::Fail}) {
    for (size_t n = 1;; ++n) {
      SCOPED_TRACE(n);
      fresh_document();
      const Before before = before_of(doc);
      bool succeeded = true;
      const bool failed = run_failing(n, later, [&] { succeeded = call(); });
      EXPECT_FALSE(succeeded);
      EXPECT_TRUE(left_alone(doc, before));
      EXPECT_TRUE(doc.message.text == spare.text || is_memory_error(doc.message)) << doc.message.text;
      EXPECT_EQ(doc.message.severity, Severity::Error);
      if (!failed || HasFailure()) break;
    }
  }
  fresh_document();
  ASSERT_FALSE(call());  // with memory to spare again: the usual message
  EXPECT_EQ(doc.message.text, spare.text);
}

template <class Call>
void EditorAppOutOfMemory::expect_opened_whole_or_not(const fs::path& file, Call&& call) {
  MeshDocument& doc = fresh_document();
  const Names start = names_of(*app_);
  ASSERT_TRUE(call());
  const ViewMode opened_mode = app_->mode();
  const bool mesh_file = opened_mode == ViewMode::Mesh;
  const HalfedgeMesh opened = doc.mesh;
  const DocumentMessage spare = doc.message;
  const Names opened_names = names_of(*app_);
  ASSERT_EQ(spare.text, "opened " + file.string());
  ASSERT_EQ(opened_names.title, "MeshEdit - " + file.filename().string());
  std::deque<std::string> recent = start.recent;  // `file` moved up to the front
  std::erase(recent, file.string());
  recent.push_front(file.string());
  ASSERT_EQ(opened_names.recent, recent);
  for (const Later later : {Later::Succeed, Later::Fail}) {
    for (size_t n = 1;; ++n) {
      SCOPED_TRACE(n);
      fresh_document();
      const Before before = before_of(doc);
      const Names names = names_of(*app_);
      bool result = false;
      const bool failed = run_failing(n, later, [&] { result = call(); });
      if (result) {
        EXPECT_EQ(app_->mode(), opened_mode);
        EXPECT_TRUE(mesh_file ? replaced_by(doc, before, opened) : left_alone(doc, before));
        EXPECT_EQ(doc.message.text, spare.text);
        EXPECT_TRUE(names_of(*app_) == opened_names) << app_->title();
      } else {
        EXPECT_EQ(app_->mode(), ViewMode::Mesh);
        EXPECT_TRUE(left_alone(doc, before));
        EXPECT_TRUE(names_of(*app_) == names) << app_->title();
        EXPECT_TRUE(is_memory_error(doc.message)) << doc.message.text;
      }
      EXPECT_TRUE(call());  // with memory to spare again
      EXPECT_EQ(app_->mode(), opened_mode);
      if (mesh_file) {
        EXPECT_TRUE(doc.mesh.same_as(opened));
      }
      if (!failed || HasFailure()) break;
    }
  }
}

TEST_F(EditorAppOutOfMemory, AFileThatWillNotOpenIsReportedAndTheDocumentStays) {
  expect_failure_reported_alone([&] { return app_->open(missing_); });
  EXPECT_NE(app_->document().message.text.find("missing.obj"), std::string::npos);
}

TEST_F(EditorAppOutOfMemory, AFileThatOpensIsOpenedWholeOrNotAtAll) {
  expect_opened_whole_or_not(tetrahedron_, [&] { return app_->open(tetrahedron_); });
}

TEST_F(EditorAppOutOfMemory, ACurveOrPatchesOpenWholeOrNotAtAll) {
  expect_opened_whole_or_not(curve_, [&] { return app_->open(curve_); });
  EXPECT_EQ(app_->mode(), ViewMode::Curve);
  expect_opened_whole_or_not(patch_, [&] { return app_->open(patch_); });
  EXPECT_EQ(app_->mode(), ViewMode::Patches);
}

TEST_F(EditorAppOutOfMemory, ASaveThatFailsIsReportedAndTheDocumentStays) {
  const fs::path nowhere = dir_ / "no such folder" / "torus.obj";
  expect_failure_reported_alone([&] { return app_->document_room().save(nowhere); });
}

// Saved and reported so, first in the recent list, or not saved, reported so, the recent list as it was.
TEST_F(EditorAppOutOfMemory, ASaveThatWorksIsReportedWholeOrNotAtAll) {
  const fs::path saved = dir_ / "saved.obj";
  MeshDocument& doc = fresh_document();
  ASSERT_TRUE(app_->document_room().save(saved));
  const DocumentMessage spare = doc.message;
  const Names saved_names = names_of(*app_);
  ASSERT_EQ(spare.text, "saved " + saved.string());
  ASSERT_EQ(saved_names.recent.front(), saved.string());
  for (const Later later : {Later::Succeed, Later::Fail}) {
    for (size_t n = 1;; ++n) {
      SCOPED_TRACE(n);
      fresh_document();
      fs::remove(saved);
      const Before before = before_of(doc);
      const Names names = names_of(*app_);
      bool result = false;
      const bool failed = run_failing(n, later, [&] { result = app_->document_room().save(saved); });
      EXPECT_TRUE(left_alone(doc, before));
      if (result) {
        EXPECT_TRUE(fs::exists(saved));
        EXPECT_EQ(doc.message.text, spare.text);
        EXPECT_TRUE(names_of(*app_) == saved_names);
      } else {
        EXPECT_TRUE(names_of(*app_) == names);
        EXPECT_TRUE(is_memory_error(doc.message)) << doc.message.text;
      }
      EXPECT_TRUE(app_->document_room().save(saved));  // with memory to spare again
      if (!failed || HasFailure()) break;
    }
  }
}

TEST_F(EditorAppOutOfMemory, DroppedFilesOpenInTurnAndAFailureEndsNothing) {
  // Not opened: the tetrahedron ran out of memory, or the missing file did and memory stayed short.
  const std::vector<std::string> dropped = {missing_.string(), tetrahedron_.string()};
  expect_opened_whole_or_not(tetrahedron_, [&] {
    app_->open_dropped(dropped);
    return app_->document().message.severity == Severity::Info;
  });
}

// Flip, a select that fails (the one expectation that does not hold with memory to spare), split and undo, each
// checked by its message: an action that memory kept from being done fails an expectation too ("flip e4: memory
// ran out; ..." says no "fields changed").
constexpr char kScript[] =
    "select e4\n"
    "key F\n"
    "expect-message fields changed\n"
    "select e999\n"
    "key S\n"
    "expect-message new vertex\n"
    "expect-selected e4\n"
    "key ctrl+Z\n"
    "expect-message fields changed\n"
    "expect-valid\n";

TEST_F(EditorAppOutOfMemory, AScriptedActionThatRunsOutIsAFailedExpectationNotTheEnd) {
  const std::vector<ScriptedAction> actions = parse_actions(kScript, "script.txt");
  MeshDocument& doc = fresh_document();
  std::ostringstream spare_log;
  ActionPlayer spare(actions, spare_log);
  while (spare.step(*app_)) {
  }
  ASSERT_EQ(spare.failures(), 1);
  EXPECT_EQ(spare_log.str(), "script.txt:4: select failed: e999 is not live\n");
  const HalfedgeMesh played = doc.mesh;
  for (const Later later : {Later::Succeed, Later::Fail}) {
    for (size_t n = 1;; ++n) {
      SCOPED_TRACE(n);
      fresh_document();
      std::ostringstream log;
      ActionPlayer player(actions, log);
      const bool failed = run_failing(n, later, [&] {
        while (player.step(*app_)) {
        }
      });
      EXPECT_GE(player.failures(), 1);
      if (player.failures() == 1) {
        EXPECT_TRUE(doc.mesh.same_as(played));  // every expectation but the select's held: every action was done
      }
      EXPECT_TRUE(validate(doc.mesh).ok());
      const ElementRef selected = app_->selection().selected;
      EXPECT_TRUE(!selected.valid() || doc.mesh.alive(selected)) << format_id(selected);
      if (!failed || HasFailure()) break;
    }
  }
}

}  // namespace
}  // namespace meshedit
