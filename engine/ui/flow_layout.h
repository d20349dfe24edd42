// Widgets set left to right that wrap to a new line when the panel is too narrow for the next one, so a row of
// buttons and checkboxes stays readable in a narrow column instead of running off its edge; a button whose
// label, too long for the column, wraps inside it; and text that wraps only at spaces.
#pragma once

#include <string>

namespace meshedit {

// Call between two widgets: keeps the next one, a button or checkbox labelled `label`, on the current line when it
// still fits inside the window's content region, else lets it start a new line.
void same_line_if_room(const char* label);

// ImGui::Button(label), except that a label wider than the space left on the line makes a button as wide as the
// column with the label wrapped inside it (ImGui's own buttons never wrap). `label` is shown whole (no "##" part);
// push an id around it when two buttons may share a label. Returns true when pressed.
bool wrapping_button(const char* label);

// `text` with line breaks put at spaces and between Chinese characters (core/text_breaks.h) so that no line is wider
// than `width` pixels in the current font (a word wider than that keeps a line of its own); the text's own line breaks
// stay. ImGui's own wrapping also breaks after a full stop or a comma, which splits numbers ("-0.\n2778") and ranges
// ("faces 2.\n.4"), and breaks Chinese only where a line overflows.
std::string wrapped_at_spaces(const std::string& text, float width);
// ImGui::TextWrapped for text with numbers in it: wrapped as above, to the content region's width.
void text_wrapped_at_spaces(const std::string& text);

}  // namespace meshedit
