// MeshDocument when memory runs out at any allocation of an edit (FailingAllocations fails the Nth allocation, or
// the Nth and every later one, for N = 1, 2, ... until the edit gets through without a failure): a flip, a split, a
// Loop subdivision, an assignment of the whole mesh, and the undo and redo of patch and snapshot entries. Each time
// nothing escapes, and the document either did nothing (mesh, version, history and `last` as they were; an Error
// that names the edit) or kept the edit without its record (the state after, a higher version, `last` not recorded,
// a history that is either cleared or still steps exactly between the two states; a Warning that names the edit).
// Then the next edit and its undo work. Only with memory short for good, an edit whose journal fell back to a
// snapshot may leave the mesh as it stopped (the documented loss of the state before): then the history is cleared.
#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "core/loop_subdivision.h"
#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/primitives.h"
#include "core/validate.h"
#include "document/mesh_document.h"
#include "support/failing_allocations.h"
#include "support/next_edit_check.h"

namespace meshedit {
namespace {

using testing::FailingAllocations;
using Later = FailingAllocations::Later;

// The edits, undo and redo, each with the label its messages carry. Labels are made before memory runs short: the
// test's own strings must not take the failures meant for the document.
void flip4(MeshDocument& doc, const std::string& label) {
  apply_operation(doc, label, [](HalfedgeMesh& m) { return flip(m, EdgeId(4)); });
}
void split4(MeshDocument& doc, const std::string& label) {
  apply_operation(doc, label, [](HalfedgeMesh& m) { return split(m, EdgeId(4)); });
}
void subdivide(MeshDocument& doc, const std::string& label) {
  apply_operation(doc, label, [](HalfedgeMesh& m) { return loop_subdivide(m); });
}
void assign(MeshDocument& doc, const std::string& label) {
  apply_operation(doc, label, [](HalfedgeMesh& m) {
    HalfedgeMesh moved = m;
    moved.set_position(VertexId(1), {0.5, 0.25, 2});
    m = moved;  // the journal falls back to a snapshot
    return Check::yes();
  });
}
void undo_once(MeshDocument& doc, const std::string&) { undo(doc); }
void redo_once(MeshDocument& doc, const std::string&) { redo(doc); }

struct Step {
  void (*run)(MeshDocument&, const std::string& label);
  const char* label;  // what the step's messages name
};
const Step kFlip{flip4, "flip e4"}, kSplit{split4, "split e4"}, kLoop{subdivide, "Loop subdivision"};

// A torus document that has a change behind it (so last.before is rolled forward) and then `setup`.
MeshDocument document(const std::vector<Step>& setup) {
  DocumentLimits limits;
  limits.max_listed_changes = 100;  // flips, splits and the assignment are listed, Loop subdivision only counted
  MeshDocument doc = make_document(build_halfedge_mesh(make_torus(5, 7)), "", limits);
  EXPECT_TRUE(apply_operation(doc, "flip e9", [](HalfedgeMesh& m) { return flip(m, EdgeId(9)); }).ok());
  for (const Step& step : setup) step.run(doc, step.label);
  return doc;
}

struct Case {
  Step action;
  std::vector<Step> setup;             // before the action
  bool is_undo = false;                // the way back is redo, not undo
  bool may_lose_state_before = false;  // falls back to a snapshot, which memory short for good may prevent
};

// What the document looked like before the action.
struct Before {
  HalfedgeMesh mesh;
  uint64_t version, serial;
  size_t undo_depth;
  bool can_redo;
  std::string undo_label, redo_label;
};

Before before_of(const MeshDocument& doc) {
  return {doc.mesh,
          doc.mesh.version(),
          doc.last.serial,
          doc.history.undo_depth(),
          doc.history.can_redo(),
          doc.history.undo_label(),
          doc.history.redo_label()};
}

// The message starts with the label, or is the one that needs no memory: when memory stays short, or when what ran
// out was the document's own copy of the label ("undo " + the entry's), so that nothing was done.
void expect_message_names(const MeshDocument& doc, const std::string& label, bool or_memory_ran_out) {
  if (or_memory_ran_out && doc.message.text == kMemoryRanOut) return;
  EXPECT_EQ(doc.message.text.rfind(label + ": ", 0), 0u) << doc.message.text;
}

// Runs the case out of memory at its Nth allocation for N = 1, 2, ... and checks the document each time.
void expect_survives_every_allocation(const Case& c, Later later) {
  const std::string label = c.action.label;
  MeshDocument reference = document(c.setup);
  c.action.run(reference, label);
  const HalfedgeMesh after = reference.mesh;
  ASSERT_EQ(reference.message.severity, Severity::Info) << reference.message.text;
  for (size_t n = 1;; ++n) {
    SCOPED_TRACE(n);
    MeshDocument doc = document(c.setup);
    const Before before = before_of(doc);
    bool escaped = false, failed = false;
    {
      const FailingAllocations failing(n, later);
      try {
        c.action.run(doc, label);
      } catch (...) {
        escaped = true;
      }
      failed = failing.failed();
    }
    ASSERT_FALSE(escaped);
    if (!failed) {
      EXPECT_GT(n, 1u);
      EXPECT_TRUE(doc.mesh.same_as(after));
      return;  // every allocation of the action has been failed once
    }
    expect_message_names(doc, label, later == Later::Fail || doc.last.serial == before.serial);
    if (doc.last.serial == before.serial + 1 && doc.last.recorded) {
      // Done and recorded: the failure was one the code works around (std::stable_sort sorts without its buffer).
      EXPECT_TRUE(doc.mesh.same_as(after));
      EXPECT_EQ(doc.message.text, reference.message.text);
    } else if (doc.last.serial == before.serial) {
      // Nothing done.
      EXPECT_EQ(doc.message.severity, Severity::Error) << doc.message.text;
      EXPECT_TRUE(doc.mesh.same_as(before.mesh));
      EXPECT_EQ(doc.mesh.version(), before.version);
      EXPECT_EQ(doc.history.undo_depth(), before.undo_depth);
      EXPECT_EQ(doc.history.can_redo(), before.can_redo);
      EXPECT_EQ(doc.history.undo_label(), before.undo_label);
      EXPECT_EQ(doc.history.redo_label(), before.redo_label);
    } else {
      // Kept without its record.
      ASSERT_EQ(doc.last.serial, before.serial + 1);
      EXPECT_NE(doc.message.severity, Severity::Info) << doc.message.text;
      EXPECT_EQ(doc.last.version_after, doc.mesh.version());
      EXPECT_GT(doc.mesh.version(), before.version);
      const bool history_kept = doc.history.can_undo() || doc.history.can_redo();
      if (!history_kept && c.may_lose_state_before && later == Later::Fail) {
        // The journal lost the state before and the edit then stopped: the mesh is as it left it.
      } else {
        EXPECT_TRUE(doc.mesh.same_as(after));
        EXPECT_TRUE(validate(doc.mesh).ok());
      }
      if (history_kept) {
        // The history still ends with this step: it goes back and forth exactly.
        EXPECT_EQ(doc.message.severity, Severity::Warning);
        ASSERT_TRUE(c.is_undo ? redo(doc) : undo(doc));
        EXPECT_TRUE(doc.mesh.same_as(before.mesh));
        ASSERT_TRUE(c.is_undo ? undo(doc) : redo(doc));
        EXPECT_TRUE(doc.mesh.same_as(after));
      }
    }
    testing::expect_next_edit_recorded(doc, [&] { return undo(doc); });
  }
}

const std::vector<Case>& cases() {
  const Step undo_step{undo_once, ""};
  static const std::vector<Case> all = {
      {kFlip, {}},
      {kSplit, {}},
      {kLoop, {}, false, true},
      {{assign, "assign"}, {}, false, true},
      {{undo_once, "undo flip e4"}, {kFlip}, true},
      {{redo_once, "redo flip e4"}, {kFlip, undo_step}},
      {{undo_once, "undo split e4"}, {kSplit}, true},
      {{redo_once, "redo split e4"}, {kSplit, undo_step}},
      {{undo_once, "undo Loop subdivision"}, {kLoop}, true},
      {{redo_once, "redo Loop subdivision"}, {kLoop, undo_step}},
  };
  return all;
}

TEST(DocumentOutOfMemoryAnywhere, OneAllocationFails) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.action.label);
    expect_survives_every_allocation(c, Later::Succeed);
  }
}

TEST(DocumentOutOfMemoryAnywhere, MemoryStaysShort) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.action.label);
    expect_survives_every_allocation(c, Later::Fail);
  }
}

}  // namespace
}  // namespace meshedit
