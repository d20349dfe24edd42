// element_link and UiProbe (see element_link.h).
#include "ui/element_link.h"

#include <imgui_internal.h>

#include "core/translation.h"

namespace meshedit {

const UiProbe::Item* UiProbe::find(std::string_view name, ElementRef element) const {
  for (const Item& item : items)
    if (item.name == name && (!element.valid() || item.element == element)) return &item;
  return nullptr;
}

void UiProbe::record_last_item(std::string name, ElementRef element) {
  items.push_back(Item{std::move(name), element, ImGui::GetItemRectMin(), ImGui::GetItemRectMax()});
}

void default_window_size(ImVec2 size) {
  if (!(ImGui::GetCurrentContext()->NextWindowData.Flags & ImGuiNextWindowDataFlags_HasSize))
    ImGui::SetNextWindowSize(size, ImGuiCond_FirstUseEver);
}

bool element_link(const HalfedgeMesh& mesh, ElementRef ref, Selection& selection, const char* name, UiProbe* probe) {
  const std::string text = format_id(ref);
  if (reference_state(mesh, ref) != RefState::Live) {
    ImGui::TextColored(ui_colors::broken(), "%s", text.c_str());
    if (ImGui::IsItemHovered()) {
      const std::string tip = tr_format("{problem}; not followed", {{"problem", reference_problem(mesh, ref)}});
      ImGui::SetTooltip("%s", tip.c_str());
    }
    if (probe) probe->record_last_item(name, ref);
    return false;
  }
  ImGui::PushID(name);
  ImGui::PushStyleColor(ImGuiCol_Text, ui_colors::link());
  const bool clicked = ImGui::Selectable(text.c_str(), selection.selected == ref, 0, ImGui::CalcTextSize(text.c_str()));
  ImGui::PopStyleColor();
  ImGui::PopID();
  if (ImGui::IsItemHovered()) selection.hovered = ref;
  if (probe) probe->record_last_item(name, ref);
  if (clicked) selection.selected = ref;
  return clicked;
}

}  // namespace meshedit
