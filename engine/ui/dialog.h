// The window's modal dialogs (Open or save, Keys, Save a bug report...): centred on the window, nothing else takes
// input while one is open, and a path field as ImGui 1.86 allows one without imgui_stdlib.
#pragma once

#include <imgui.h>

#include <string>

namespace meshedit {

// Opens the modal popup `name` while `shown` holds, centred and at most `size` (within the window). Returns whether
// it is open this frame (then call end_dialog).
bool begin_dialog(const char* name, bool& shown, ImVec2 size);
// Ends the popup begin_dialog opened, closing it when `shown` went false this frame.
void end_dialog(bool shown);
// A one-line text field of at most 1023 bytes; returns whether Enter was pressed in it.
bool input_path(const char* label, std::string& text);

}  // namespace meshedit
