// Widgets set left to right that wrap to a new line when the panel is too narrow for the next one, so a row of
// buttons and checkboxes stays readable in a narrow column instead of running off its edge; and a button whose
// label, too long for the column, wraps inside it.
#pragma once

namespace meshedit {

// Call between two widgets: keeps the next one, a button or checkbox labelled `label`, on the current line when it
// still fits inside the window's content region, else lets it start a new line.
void same_line_if_room(const char* label);

// ImGui::Button(label), except that a label wider than the space left on the line makes a button as wide as the
// column with the label wrapped inside it (ImGui's own buttons never wrap). `label` is shown whole (no "##" part);
// push an id around it when two buttons may share a label. Returns true when pressed.
bool wrapping_button(const char* label);

}  // namespace meshedit
