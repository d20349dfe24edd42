// The Lua console's panel: see script_console.h.
#include "ui/script_console.h"

#include <algorithm>
#include <string>

#include <imgui.h>

#include "ui/theme.h"

namespace meshedit {
namespace {

// ImGui's input callback: Up/Down browse the history.
int input_callback(ImGuiInputTextCallbackData* data) {
  if (data->EventFlag == ImGuiInputTextFlags_CallbackHistory) {
    auto* console = static_cast<ScriptConsole*>(data->UserData);
    const std::string line = data->EventKey == ImGuiKey_UpArrow ? console->history_up() : console->history_down();
    data->DeleteChars(0, data->BufTextLen);
    data->InsertChars(0, line.c_str(), line.c_str() + std::min(line.size(), size_t(data->BufSize - 1)));
  }
  return 0;
}

ImVec4 colour_of(ConsoleEntryKind kind) {
  switch (kind) {
    case ConsoleEntryKind::Input: return im_colour(ui_palette().console_input);
    case ConsoleEntryKind::Error: return im_colour(ui_palette().error);
    case ConsoleEntryKind::Output: break;
  }
  return ImGui::GetStyleColorVec4(ImGuiCol_Text);
}

}  // namespace

void draw_console_panel_contents(ScriptConsole& console, ConsolePanelState& state, MeshDocument& doc,
                                 const Selection& selection) {
  const float input_height = ImGui::GetFrameHeightWithSpacing();
  ImGui::BeginChild("transcript", ImVec2(0, -input_height), false, ImGuiWindowFlags_HorizontalScrollbar);
  for (const ConsoleEntry& entry : console.entries()) {
    ImGui::PushStyleColor(ImGuiCol_Text, colour_of(entry.kind));
    if (entry.kind == ConsoleEntryKind::Input) {
      ImGui::TextUnformatted("> ");
      ImGui::SameLine(0, 0);
    }
    ImGui::TextUnformatted(entry.text.c_str(), entry.text.c_str() + entry.text.size());
    ImGui::PopStyleColor();
  }
  if (state.scroll_to_bottom) ImGui::SetScrollHereY(1.0f);
  state.scroll_to_bottom = false;
  ImGui::EndChild();

  if (state.focus_input) ImGui::SetKeyboardFocusHere();
  state.focus_input = false;
  ImGui::SetNextItemWidth(-1);
  const ImGuiInputTextFlags flags = ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_CallbackHistory;
  if (ImGui::InputText("##lua", state.input.data(), state.input.size(), flags, input_callback, &console)) {
    const std::string code = state.input.data();
    state.input[0] = '\0';
    console.submit(doc, selection, code);
    state.focus_input = true;  // Enter keeps the keyboard in the console
    state.scroll_to_bottom = true;
  }
}

}  // namespace meshedit
