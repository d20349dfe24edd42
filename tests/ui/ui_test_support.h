// Headless Dear ImGui for the panel tests: a context with a built font atlas and no backend, frames run by
// hand, and clicks driven through io.MousePos / io.MouseDown over three frames (hover, press, release).
// Also short id helpers and the grid fixture whose ids the tests name.
#pragma once

#include <functional>

#include <gtest/gtest.h>
#include <imgui.h>

#include "core/halfedge_mesh.h"
#include "core/mesh_build.h"
#include "core/primitives.h"
#include "ui/element_link.h"

namespace meshedit::ui_testing {

inline VertexId V(uint32_t i) { return VertexId(i); }
inline HalfedgeId H(uint32_t i) { return HalfedgeId(i); }
inline EdgeId E(uint32_t i) { return EdgeId(i); }
inline FaceId F(uint32_t i) { return FaceId::face(i); }
inline FaceId B(uint32_t i) { return FaceId::boundary(i); }

// Compares elements by their printed form, so failures read "h13 vs h14".
#define EXPECT_REF(actual, expected)                                  \
  EXPECT_EQ(::meshedit::format_id(::meshedit::ElementRef(actual)), \
            ::meshedit::format_id(::meshedit::ElementRef(expected)))

// make_grid(1, 1): v0 (0,0) v1 (1,0) v2 (0,1) v3 (1,1); f0 = h0 h1 h2 (v0 v1 v3), f1 = h3 h4 h5 (v0 v3 v2);
// e0 = v0-v1 (h0/h6), e1 = v1-v3 (h1/h9), e2 = v3-v0, the diagonal (h2/h3), e3 = v3-v2 (h4/h8),
// e4 = v2-v0 (h5/h7); boundary loop b0 = h6 h7 h8 h9; v0.halfedge h7, v1 h6, v2 h8, v3 h9.
inline HalfedgeMesh grid_1x1() { return build_halfedge_mesh(make_grid(1, 1)); }

class ImGuiHarness {
 public:
  explicit ImGuiHarness(ImVec2 display = ImVec2(1280, 800)) {
    context_ = ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.LogFilename = nullptr;
    io.DisplaySize = display;
    io.DeltaTime = 1.0f / 60.0f;
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
  }
  ~ImGuiHarness() { ImGui::DestroyContext(context_); }
  ImGuiHarness(const ImGuiHarness&) = delete;
  ImGuiHarness& operator=(const ImGuiHarness&) = delete;

  // One frame: NewFrame, draw, Render. Returns the number of vertices ImGui produced.
  int frame(const std::function<void()>& draw) {
    ImGui::NewFrame();
    draw();
    ImGui::Render();
    const ImDrawData* data = ImGui::GetDrawData();
    return data ? data->TotalVtxCount : 0;
  }
  // Hover, press and release the left button at `pos`, one frame each.
  void click(ImVec2 pos, const std::function<void()>& draw) {
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = pos;
    io.MouseDown[0] = false;
    frame(draw);
    io.MouseDown[0] = true;
    frame(draw);
    io.MouseDown[0] = false;
    frame(draw);
    io.MousePos = ImVec2(-1.0f, -1.0f);
    frame(draw);
  }
  // Types text into the focused widget over one frame.
  void type(const char* text, const std::function<void()>& draw) {
    ImGui::GetIO().AddInputCharactersUTF8(text);
    frame(draw);
  }

 private:
  ImGuiContext* context_ = nullptr;
};

}  // namespace meshedit::ui_testing
