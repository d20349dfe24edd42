// Wrapping rows of widgets (see flow_layout.h).
#include "ui/flow_layout.h"

#include <imgui.h>

namespace meshedit {

void same_line_if_room(const char* label) {
  const ImGuiStyle& style = ImGui::GetStyle();
  // Wide enough for a checkbox's box or a button's padding around the label.
  const float width = ImGui::CalcTextSize(label, nullptr, true).x + style.FramePadding.x * 2.0f + ImGui::GetFrameHeight();
  const float right_edge = ImGui::GetItemRectMax().x + style.ItemSpacing.x + width;
  if (right_edge <= ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x) ImGui::SameLine();
}

}  // namespace meshedit
