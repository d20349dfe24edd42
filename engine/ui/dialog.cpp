// The modal dialogs' frame and their path field (see dialog.h).
#include "ui/dialog.h"

#include <algorithm>

namespace meshedit {

bool begin_dialog(const char* name, bool& shown, ImVec2 size) {
  if (!shown) return false;
  if (!ImGui::IsPopupOpen(name)) ImGui::OpenPopup(name);
  const ImGuiViewport* main = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(main->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(std::min(size.x, main->Size.x * 0.9f), std::min(size.y, main->Size.y * 0.9f)),
                           ImGuiCond_Appearing);
  if (ImGui::BeginPopupModal(name, &shown)) return true;
  shown = false;  // closed from outside (the popup stack was cleared)
  return false;
}

void end_dialog(bool shown) {
  if (!shown) ImGui::CloseCurrentPopup();
  ImGui::EndPopup();
}

bool input_path(const char* label, std::string& text) {
  char buffer[1024];
  const size_t n = std::min(text.size(), sizeof buffer - 1);
  std::copy_n(text.data(), n, buffer);
  buffer[n] = '\0';
  const bool entered = ImGui::InputText(label, buffer, sizeof buffer, ImGuiInputTextFlags_EnterReturnsTrue);
  text = buffer;
  return entered;
}

}  // namespace meshedit
