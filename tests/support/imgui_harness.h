// ImGuiHarness: headless Dear ImGui for panel tests and benchmarks: a context with a built font atlas and no
// backend, frames run by hand, and clicks driven through io.MousePos / io.MouseDown over frames (hover, press,
// release). No GoogleTest here, so benchmarks can use it too (tests/ui/ui_test_support.h adds the test helpers).
#pragma once

#include <functional>

#include <imgui.h>

namespace meshedit::ui_testing {

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
