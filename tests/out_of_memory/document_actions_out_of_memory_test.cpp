// The key actions (document/document_actions.h) when memory runs out at any allocation they make: their own (the edit's
// label, a refusal's sentence, the "; new vertex v4" split adds to the message, Loop's phase 1) and the document's.
// Each action runs with its Nth allocation failing (FailingAllocations), or the Nth and every later one, for
// N = 1, 2, ... until it gets through without a failure. Each time nothing escapes, the selection names only live
// elements, and the action either was not done (mesh, version, history, `last`, selection and Loop stepper as they
// were; an Error when memory to spare would have done it) or was done as the document keeps it (mesh_document.h:
// recorded like with memory to spare, or kept without its record). A message other than the one memory to spare
// gives says memory ran out. Then the document works on: an action that was not done gives, run again with memory
// to spare, exactly what it gives from the start; the Loop stepper finishes the subdivision; an edit records and
// undoes as usual.
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "core/loop_subdivision.h"
#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/primitives.h"
#include "core/validate.h"
#include "document/document_actions.h"
#include "support/failing_allocations.h"
#include "support/next_edit_check.h"

namespace meshedit {
namespace {

using testing::FailingAllocations;
using Later = FailingAllocations::Later;

// A document and selection to run an action on, made with memory to spare.
struct Start {
  MeshDocument doc;
  Selection selection;
};

// A torus with a change behind it (so the next change rolls last.before forward), `selected` selected.
Start torus(ElementRef selected) {
  DocumentLimits limits;
  limits.max_listed_changes = 100;  // local edits are listed, Loop subdivision only counted
  Start start{make_document(build_halfedge_mesh(make_torus(5, 7)), "", limits), {selected, {}}};
  EXPECT_TRUE(apply_operation(start.doc, "flip e9", [](HalfedgeMesh& m) { return flip(m, EdgeId(9)); }).ok());
  return start;
}
Start torus_edge() { return torus(EdgeId(4)); }
Start torus_halfedge() { return torus(HalfedgeId(8)); }
Start torus_vertex() { return torus(VertexId(3)); }
Start torus_nothing() { return torus({}); }
Start grid_boundary_edge() { return {make_document(build_halfedge_mesh(make_grid(1, 1))), {EdgeId(0), {}}}; }
Start quads() { return {make_document(build_halfedge_mesh(make_cube_quads())), {}}; }
// `phases` Loop phases already run on the torus.
Start torus_after_loop_phases(int phases) {
  Start start = torus_edge();
  for (int i = 0; i < phases; ++i) EXPECT_TRUE(loop_subdivide_step(start.doc, start.selection).ok);
  return start;
}
Start loop_phase_2() { return torus_after_loop_phases(1); }
Start loop_phase_3() { return torus_after_loop_phases(2); }
Start loop_phase_4() { return torus_after_loop_phases(3); }
// Two phases run, then one undone: the next press starts again at phase 1 and says so.
Start loop_restart() {
  Start start = torus_after_loop_phases(2);
  EXPECT_TRUE(undo_edit(start.doc, start.selection));
  return start;
}
Start flipped() {
  Start start = torus_edge();
  EXPECT_TRUE(flip_selected(start.doc, start.selection).ok);
  return start;
}
Start flipped_and_undone() {
  Start start = flipped();
  EXPECT_TRUE(undo_edit(start.doc, start.selection));
  return start;
}

void flip_action(MeshDocument& doc, Selection& sel) { flip_selected(doc, sel); }
void split_action(MeshDocument& doc, Selection& sel) { split_selected(doc, sel); }
void collapse_action(MeshDocument& doc, Selection& sel) { collapse_selected(doc, sel); }
void loop_all_action(MeshDocument& doc, Selection& sel) { loop_subdivide_all(doc, sel); }
void loop_step_action(MeshDocument& doc, Selection& sel) { loop_subdivide_step(doc, sel); }
void next_action(MeshDocument& doc, Selection& sel) { navigate_selection(doc, sel, NavStep::Next); }
void halfedge_action(MeshDocument& doc, Selection& sel) { navigate_selection(doc, sel, NavStep::Halfedge); }
void select_missing_action(MeshDocument& doc, Selection& sel) { select_element(doc, sel, FaceId::face(999)); }
void undo_action(MeshDocument& doc, Selection& sel) { undo_edit(doc, sel); }
void redo_action(MeshDocument& doc, Selection& sel) { redo_edit(doc, sel); }

struct Case {
  const char* name;  // the test's name
  Start (*start)();
  void (*action)(MeshDocument&, Selection&);
  // Snapshot-sized (Loop subdivision, its phases 2-4): memory short for good may lose the state before, and the mesh
  // stays as the subdivision stopped (mesh_document.h).
  bool may_lose_state_before = false;
};

const std::vector<Case>& cases() {
  static const std::vector<Case> all = {
      {"FlipTheSelectedEdge", torus_edge, flip_action},
      {"FlipTheSelectedHalfedgesEdge", torus_halfedge, flip_action},
      {"FlipWithAVertexSelected", torus_vertex, flip_action},
      {"FlipWithNothingSelected", torus_nothing, flip_action},
      {"FlipABoundaryEdge", grid_boundary_edge, flip_action},
      {"Split", torus_edge, split_action},
      {"Collapse", torus_edge, collapse_action},
      {"LoopSubdivision", torus_edge, loop_all_action, true},
      {"LoopPhase1", torus_edge, loop_step_action},
      {"LoopPhase2", loop_phase_2, loop_step_action, true},
      {"LoopPhase3", loop_phase_3, loop_step_action, true},
      {"LoopPhase4", loop_phase_4, loop_step_action, true},
      {"LoopPhase1AgainAfterAnUndo", loop_restart, loop_step_action},
      {"LoopPhase1Refused", quads, loop_step_action},
      {"NextFromAHalfedge", torus_halfedge, next_action},
      {"HalfedgeRefusedOnAHalfedge", torus_halfedge, halfedge_action},
      {"SelectAMissingFace", torus_edge, select_missing_action},
      {"Undo", flipped, undo_action},
      {"Redo", flipped_and_undone, redo_action},
  };
  return all;
}

// What a document and selection look like, for comparing before, after and with memory to spare.
struct State {
  HalfedgeMesh mesh;
  uint64_t version, serial;
  size_t undo_depth;
  bool can_redo;
  std::string undo_label, redo_label;
  ElementRef selected;
  int loop_next_phase;
  uint64_t loop_version;
  DocumentMessage message;
};

State state_of(const MeshDocument& doc, const Selection& sel) {
  return {doc.mesh,
          doc.mesh.version(),
          doc.last.serial,
          doc.history.undo_depth(),
          doc.history.can_redo(),
          doc.history.undo_label(),
          doc.history.redo_label(),
          sel.selected,
          doc.loop.next_phase,
          doc.loop.version,
          doc.message};
}

bool same_history(const State& a, const State& b) {
  return a.undo_depth == b.undo_depth && a.can_redo == b.can_redo && a.undo_label == b.undo_label &&
         a.redo_label == b.redo_label;
}

bool same_message(const DocumentMessage& a, const DocumentMessage& b) {
  return a.severity == b.severity && a.text == b.text;
}

bool says_memory_ran_out(const DocumentMessage& message) {
  return message.severity != Severity::Info && message.text.find(kMemoryRanOut) != std::string::npos;
}

// Nothing done: the document and the selection are as they were; only the message may differ.
bool nothing_done(const State& now, const State& before) {
  return now.mesh.same_as(before.mesh) && now.version == before.version && now.serial == before.serial &&
         same_history(now, before) && now.selected == before.selected &&
         now.loop_next_phase == before.loop_next_phase && now.loop_version == before.loop_version;
}

// The state an action left after an allocation failed in it (`before` it ran, `spare`: with memory to spare).
void expect_before_or_kept(const Case& c, const MeshDocument& doc, const State& now, const State& before,
                           const State& spare, Later later) {
  EXPECT_TRUE(!now.selected.valid() || doc.mesh.alive(now.selected)) << format_id(now.selected);
  if (!same_message(now.message, spare.message)) {
    EXPECT_TRUE(says_memory_ran_out(now.message)) << now.message.text;
  }
  if (nothing_done(now, before)) {
    if (!nothing_done(spare, before)) {
      EXPECT_EQ(now.message.severity, Severity::Error) << now.message.text;  // memory to spare would have done it
    }
    return;
  }
  // Done: the same selection and Loop stepper as with memory to spare.
  EXPECT_EQ(now.selected, spare.selected) << format_id(now.selected);
  EXPECT_EQ(now.loop_next_phase, spare.loop_next_phase);
  if (now.serial == before.serial) {
    // Done without a change to the mesh (a selection, Loop's phase 1).
    EXPECT_TRUE(now.mesh.same_as(before.mesh));
    EXPECT_EQ(now.version, before.version);
    EXPECT_TRUE(same_history(now, before));
    return;
  }
  ASSERT_EQ(now.serial, before.serial + 1);
  EXPECT_GT(now.version, before.version);
  EXPECT_EQ(doc.last.version_after, now.version);
  if (doc.last.recorded) {
    EXPECT_TRUE(now.mesh.same_as(spare.mesh));
    EXPECT_TRUE(same_history(now, spare));
    return;
  }
  // Kept without its record: the history is cleared or still ends with this step.
  EXPECT_NE(now.message.severity, Severity::Info);
  const bool history_kept = now.undo_depth > 0 || now.can_redo;
  if (history_kept) {
    EXPECT_TRUE(same_history(now, spare));
  }
  if (!history_kept && c.may_lose_state_before && later == Later::Fail) return;  // as the subdivision stopped
  EXPECT_TRUE(now.mesh.same_as(spare.mesh));
  EXPECT_TRUE(validate(doc.mesh).ok());
}

// With memory to spare again, the document works on from whatever state the failure left (`finished`: the mesh the
// Loop stepper ends with when the run with memory to spare goes on to the last phase).
void expect_works_on(const Case& c, MeshDocument& doc, Selection& sel, const State& before, const State& spare,
                     const HalfedgeMesh& finished) {
  if (nothing_done(state_of(doc, sel), before)) {
    // The same action gets through now, exactly as it does from the start.
    c.action(doc, sel);
    const State again = state_of(doc, sel);
    EXPECT_TRUE(again.mesh.same_as(spare.mesh));
    EXPECT_TRUE(same_message(again.message, spare.message)) << again.message.text;
    EXPECT_EQ(again.selected, spare.selected);
    EXPECT_TRUE(same_history(again, spare));
    EXPECT_EQ(again.loop_next_phase, spare.loop_next_phase);
  }
  if (doc.loop.next_phase > 1 && doc.mesh.same_as(spare.mesh)) {
    // A Loop subdivision under way finishes as it does with memory to spare (not so a mesh left as a phase stopped).
    while (doc.loop.next_phase > 1) ASSERT_TRUE(loop_subdivide_step(doc, sel).ok) << doc.message.text;
    EXPECT_TRUE(doc.mesh.same_as(finished));
  }
  testing::expect_next_edit_recorded(doc, [&] { return undo_edit(doc, sel); });
}

void expect_survives_every_allocation(const Case& c, Later later) {
  Start reference = c.start();
  const State before_reference = state_of(reference.doc, reference.selection);
  c.action(reference.doc, reference.selection);
  const State spare = state_of(reference.doc, reference.selection);
  ASSERT_FALSE(nothing_done(spare, before_reference) && same_message(spare.message, before_reference.message));
  while (reference.doc.loop.next_phase > 1) ASSERT_TRUE(loop_subdivide_step(reference.doc, reference.selection).ok);
  const HalfedgeMesh finished = reference.doc.mesh;
  for (size_t n = 1;; ++n) {
    SCOPED_TRACE(n);
    Start start = c.start();
    const State before = state_of(start.doc, start.selection);
    bool escaped = false, failed = false;
    {
      const FailingAllocations failing(n, later);
      try {
        c.action(start.doc, start.selection);
      } catch (...) {
        escaped = true;
      }
      failed = failing.failed();
    }
    ASSERT_FALSE(escaped);
    const State now = state_of(start.doc, start.selection);
    if (!failed) {
      // Every allocation of the action has been failed once; this run had memory to spare.
      EXPECT_TRUE(now.mesh.same_as(spare.mesh));
      EXPECT_TRUE(same_message(now.message, spare.message)) << now.message.text;
      return;
    }
    expect_before_or_kept(c, start.doc, now, before, spare, later);
    expect_works_on(c, start.doc, start.selection, before, spare, finished);
    if (::testing::Test::HasFailure()) return;  // one allocation's failures are enough to read
  }
}

// One test per action and way of running out (Later::Succeed: one allocation fails; Later::Fail: memory stays short).
class DocumentActionsOutOfMemory : public ::testing::TestWithParam<std::tuple<size_t, Later>> {};

TEST_P(DocumentActionsOutOfMemory, NothingEscapesAndTheDocumentStaysConsistent) {
  const auto [index, later] = GetParam();
  expect_survives_every_allocation(cases()[index], later);
}

std::string case_name(const ::testing::TestParamInfo<std::tuple<size_t, Later>>& param) {
  const Case& c = cases()[std::get<0>(param.param)];
  const bool one = std::get<1>(param.param) == Later::Succeed;
  return std::string(c.name) + (one ? "_OneAllocationFails" : "_MemoryStaysShort");
}

INSTANTIATE_TEST_SUITE_P(Actions, DocumentActionsOutOfMemory,
                         ::testing::Combine(::testing::Range<size_t>(0, cases().size()),
                                            ::testing::Values(Later::Succeed, Later::Fail)),
                         case_name);

}  // namespace
}  // namespace meshedit
