// What the key actions' callers ask before acting (document/document_actions.h) when memory runs out: which edge the
// local operations would act on (edge_for_operation, also the exercise session's question) and the label of the next
// Loop phase (next_loop_phase_label, the Edit menu's item). edge_for_operation runs with its Nth allocation failing, or
// the Nth and every later one (FailingAllocations), for N = 1, 2, ... until it gets through without a failure: nothing
// escapes, and it answers as with memory to spare (the edge, or the refusal's sentence) or refuses with kMemoryRanOut.
// next_loop_phase_label, asked with every allocation failing, allocates nothing and names the phase.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/mesh_build.h"
#include "core/primitives.h"
#include "document/document_actions.h"
#include "support/failing_allocations.h"

namespace meshedit {
namespace {

using testing::FailingAllocations;
using Later = FailingAllocations::Later;

bool same_answer(const OpResult<EdgeId>& a, const OpResult<EdgeId>& b) {
  return a.check.ok == b.check.ok && a.check.reason == b.check.reason && (!a.check.ok || a.value == b.value);
}

// edge_for_operation(mesh, selected) at every allocation it makes, one failing or memory staying short.
void expect_edge_answered(const HalfedgeMesh& mesh, ElementRef selected) {
  SCOPED_TRACE(format_id(selected));
  const OpResult<EdgeId> spare = edge_for_operation(mesh, selected);
  for (const Later later : {Later::Succeed, Later::Fail}) {
    for (size_t n = 1;; ++n) {
      SCOPED_TRACE(n);
      OpResult<EdgeId> answer;
      bool escaped = false, failed = false;
      {
        const FailingAllocations failing(n, later);
        try {
          answer = edge_for_operation(mesh, selected);
        } catch (...) {
          escaped = true;
        }
        failed = failing.failed();
      }
      ASSERT_FALSE(escaped);
      if (!failed) {
        EXPECT_TRUE(same_answer(answer, spare)) << answer.check.reason;
        break;
      }
      EXPECT_TRUE(same_answer(answer, spare) || (!answer.check.ok && answer.check.reason == kMemoryRanOut))
          << answer.check.reason;
      if (::testing::Test::HasFailure()) return;
    }
  }
}

TEST(ActionQueriesOutOfMemory, EdgeForOperationAnswersOrSaysMemoryRanOut) {
  HalfedgeMesh mesh = build_halfedge_mesh(make_grid(1, 1));
  // The edge, and each refusal: nothing, a vertex, a face, a missing edge.
  for (const ElementRef selected :
       std::vector<ElementRef>{EdgeId(2), HalfedgeId(3), ElementRef(), VertexId(3), FaceId::face(0), EdgeId(99)}) {
    expect_edge_answered(mesh, selected);
  }
  mesh.set_edge(HalfedgeId(3), EdgeId());  // a broken pointer: the walk to the edge refuses
  expect_edge_answered(mesh, HalfedgeId(3));
}

TEST(ActionQueriesOutOfMemory, NextLoopPhaseLabelAllocatesNothing) {
  MeshDocument doc = make_document(build_halfedge_mesh(make_tetrahedron()));
  Selection selection;
  const auto expect_label = [&](const std::string& expected) {
    bool escaped = false, same = false;
    size_t allocations = 0;
    {
      const FailingAllocations failing(1, Later::Fail);
      try {
        same = next_loop_phase_label(doc) == expected;
      } catch (...) {
        escaped = true;
      }
      allocations = failing.allocations();
    }
    EXPECT_FALSE(escaped) << expected;
    EXPECT_EQ(allocations, 0u) << expected;
    EXPECT_TRUE(same) << expected;
  };
  expect_label("Loop 1/4: compute new positions");
  ASSERT_TRUE(loop_subdivide_step(doc, selection).ok);
  expect_label("Loop 2/4: split every original edge");
  ASSERT_TRUE(loop_subdivide_step(doc, selection).ok);
  expect_label("Loop 3/4: flip new edges joining an old and a new vertex");
  ASSERT_TRUE(undo_edit(doc, selection));  // the mesh changed since phase 2: the next press starts again
  expect_label("Loop 1/4: compute new positions");
}

}  // namespace
}  // namespace meshedit
