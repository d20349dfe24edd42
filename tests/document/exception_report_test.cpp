// report_exception, report_escaped_exception and run_guarded: an exception becomes an Error in the status line, in
// its own words or in memory-ran-out's; what the action did before it threw stays; an action that throws nothing
// leaves its own message.
#include <new>
#include <stdexcept>

#include <gtest/gtest.h>

#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/primitives.h"
#include "document/exception_report.h"

namespace meshedit {
namespace {

MeshDocument torus() { return make_document(build_halfedge_mesh(make_torus(5, 7))); }

TEST(ExceptionReport, AReportedExceptionSaysItsOwnWordsOrThatMemoryRanOut) {
  MeshDocument doc = torus();
  report_exception(doc, std::runtime_error("cow.obj: cannot open the file"));
  EXPECT_EQ(doc.message.severity, Severity::Error);
  EXPECT_EQ(doc.message.text, "cow.obj: cannot open the file");
  report_exception(doc, std::bad_alloc());
  EXPECT_EQ(doc.message.severity, Severity::Error);
  EXPECT_EQ(doc.message.text, kMemoryRanOut);
}

TEST(ExceptionReport, AnExceptionThatEscapesAnActionIsShownAndWhatTheActionDidStays) {
  MeshDocument doc = torus();
  const HalfedgeMesh before = doc.mesh;
  run_guarded(doc, [&] {
    ASSERT_TRUE(apply_operation(doc, "flip e4", [](HalfedgeMesh& m) { return flip(m, EdgeId(4)); }).ok());
    throw std::runtime_error("boom");
  });
  EXPECT_EQ(doc.message.severity, Severity::Error);
  EXPECT_EQ(doc.message.text, "the last action failed: boom");
  EXPECT_FALSE(doc.mesh.same_as(before));
  EXPECT_EQ(doc.history.undo_label(), "flip e4");

  run_guarded(doc, [] { throw std::bad_alloc(); });
  EXPECT_EQ(doc.message.severity, Severity::Error);
  EXPECT_EQ(doc.message.text, "memory ran out; the last action did not finish");

  run_guarded(doc, [&] { set_message(doc, Severity::Info, "fine"); });
  EXPECT_EQ(doc.message.severity, Severity::Info);
  EXPECT_EQ(doc.message.text, "fine");
}

}  // namespace
}  // namespace meshedit
