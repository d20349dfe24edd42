// Wrapping rows of widgets (see flow_layout.h).
#include "ui/flow_layout.h"

#include <algorithm>

#include <imgui.h>

#include "core/text_breaks.h"

namespace meshedit {

void same_line_if_room(const char* label) {
  const ImGuiStyle& style = ImGui::GetStyle();
  // Wide enough for a checkbox's box or a button's padding around the label.
  const float width =
      ImGui::CalcTextSize(label, nullptr, true).x + style.FramePadding.x * 2.0f + ImGui::GetFrameHeight();
  const float right_edge = ImGui::GetItemRectMax().x + style.ItemSpacing.x + width;
  if (right_edge <= ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x) ImGui::SameLine();
}

bool wrapping_button(const char* label) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float room = ImGui::GetContentRegionAvail().x;
  const float one_line = ImGui::CalcTextSize(label, nullptr, false).x + style.FramePadding.x * 2.0f;
  if (one_line <= room) return ImGui::Button(label);
  const float wrap = std::max(room - style.FramePadding.x * 2.0f, ImGui::GetFontSize() * 4.0f);
  const ImVec2 text = ImGui::CalcTextSize(label, nullptr, false, wrap);
  const ImVec2 size(wrap + style.FramePadding.x * 2.0f, text.y + style.FramePadding.y * 2.0f);
  ImGui::PushID(label);
  const bool pressed = ImGui::Button("##wrapped", size);
  ImGui::PopID();
  const ImVec2 corner = ImGui::GetItemRectMin();
  ImGui::GetWindowDrawList()->AddText(ImGui::GetFont(), ImGui::GetFontSize(),
                                      ImVec2(corner.x + style.FramePadding.x, corner.y + style.FramePadding.y),
                                      ImGui::GetColorU32(ImGuiCol_Text), label, nullptr, wrap);
  return pressed;
}

std::string wrapped_at_spaces(const std::string& text, float width) {
  return wrapped_text(text, width, [](const std::string& line) { return ImGui::CalcTextSize(line.c_str()).x; });
}

void text_wrapped_at_spaces(const std::string& text) {
  ImGui::TextUnformatted(wrapped_at_spaces(text, ImGui::GetContentRegionAvail().x).c_str());
}

}  // namespace meshedit
