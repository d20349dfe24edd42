// The exception reports (document/exception_report.h) when memory has run out for good (every allocation fails):
// nothing escapes them or run_guarded, and the status line says memory ran out, as an Error, with no allocation.
#include <new>
#include <stdexcept>

#include <gtest/gtest.h>

#include "core/mesh_build.h"
#include "core/primitives.h"
#include "document/exception_report.h"
#include "support/failing_allocations.h"

namespace meshedit {
namespace {

using testing::FailingAllocations;

TEST(ExceptionReportOutOfMemory, TheReportsNeedNoMemory) {
  MeshDocument doc = make_document(build_halfedge_mesh(make_cube()));
  const std::runtime_error error("a message longer than any string's inline buffer");
  const auto expect_memory_ran_out = [&](auto report) {
    set_message(doc, Severity::Info, "a message from before, longer than the inline buffer");
    bool escaped = false, failed = false;
    {
      const FailingAllocations failing(1, FailingAllocations::Later::Fail);
      try {
        report();
      } catch (...) {
        escaped = true;
      }
      failed = failing.failed();
    }
    EXPECT_FALSE(escaped);
    EXPECT_TRUE(failed);
    EXPECT_EQ(doc.message.severity, Severity::Error);
    EXPECT_EQ(doc.message.text, kMemoryRanOut);
  };
  expect_memory_ran_out([&] { report_exception(doc, error); });
  expect_memory_ran_out([&] { report_escaped_exception(doc, error); });
  expect_memory_ran_out([&] { report_escaped_exception(doc, std::bad_alloc()); });
  expect_memory_ran_out([&] { run_guarded(doc, [] { throw std::bad_alloc(); }); });
  expect_memory_ran_out([&] { run_guarded(doc, [] { throw std::runtime_error("no memory left to copy this"); }); });
}

}  // namespace
}  // namespace meshedit
