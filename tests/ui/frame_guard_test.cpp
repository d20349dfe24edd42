// run_guarded_frame: an exception thrown in the middle of a frame (inside a window, an ID push and a table) becomes
// an Error message, ImGui's stacks are closed so the frame renders, and the next frame draws normally; a frame that
// throws nothing leaves the message alone.
#include <new>
#include <stdexcept>

#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include "core/mesh_build.h"
#include "core/primitives.h"
#include "support/imgui_harness.h"
#include "ui/frame_guard.h"

namespace meshedit {
namespace {

// A frame that opens a window, an ID scope and a table, then throws `error` from inside them.
template <class Error>
void throwing_frame(const Error& error) {
  ImGui::Begin("panel");
  ImGui::PushID(7);
  if (ImGui::BeginTable("rows", 2)) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted("cell");
    throw error;
  }
  ImGui::PopID();
  ImGui::End();
}

TEST(FrameGuard, AnExceptionMidFrameBecomesAnErrorAndTheFrameStillRenders) {
  ui_testing::ImGuiHarness imgui;
  MeshDocument doc = make_document(build_halfedge_mesh(make_cube()));
  int windows_open_after = -1;
  imgui.frame([&] {
    run_guarded_frame(doc, [] { throwing_frame(std::bad_alloc()); });
    windows_open_after = ImGui::GetCurrentContext()->CurrentWindowStack.Size;
  });
  EXPECT_EQ(windows_open_after, 1);  // only ImGui's own fallback window
  EXPECT_EQ(doc.message.severity, Severity::Error);
  EXPECT_EQ(doc.message.text, "memory ran out; the last action did not finish");

  imgui.frame([&] { run_guarded_frame(doc, [] { throwing_frame(std::runtime_error("boom")); }); });
  EXPECT_EQ(doc.message.severity, Severity::Error);
  EXPECT_EQ(doc.message.text, "the last action failed: boom");

  // The next frame starts clean and draws the same window without a throw.
  set_message(doc, Severity::Info, "fine");
  const int vertices = imgui.frame([&] {
    run_guarded_frame(doc, [] {
      ImGui::Begin("panel");
      ImGui::TextUnformatted("drawn");
      ImGui::End();
    });
  });
  EXPECT_GT(vertices, 0);
  EXPECT_EQ(doc.message.text, "fine");
}

}  // namespace
}  // namespace meshedit
