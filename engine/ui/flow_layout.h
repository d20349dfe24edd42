// Widgets set left to right that wrap to a new line when the panel is too narrow for the next one, so a row of
// buttons and checkboxes stays readable in a narrow column instead of running off its edge.
#pragma once

namespace meshedit {

// Call between two widgets: keeps the next one, a button or checkbox labelled `label`, on the current line when it
// still fits inside the window's content region, else lets it start a new line.
void same_line_if_room(const char* label);

}  // namespace meshedit
