// The "Your code" panel (see student_editor.h): a gutter of line numbers beside a child window (the code view) that
// scrolls around ImGui's multiline text box, made the size of the text so that the box itself never scrolls; the
// gutter follows the view's scroll, and the view follows the box's text cursor (ImGui's input state, imgui_internal.h).
#include "ui/student_editor.h"

#include <algorithm>
#include <cstdio>

#include <imgui.h>
#include <imgui_internal.h>
#include <imgui_stdlib.h>

#include "core/translation.h"
#include "ui/fonts.h"
#include "ui/key_pressed.h"
#include "ui/theme.h"

namespace meshedit {
namespace {

struct TextShape {
  size_t lines = 1;
  size_t widest = 0;  // characters of the longest line
};

TextShape shape_of(const std::string& text) {
  TextShape shape;
  size_t width = 0;
  for (const char c : text) {
    if (c == '\n') {
      shape.widest = std::max(shape.widest, width);
      width = 0;
      shape.lines += 1;
    } else {
      width += c == '\t' ? 4 : 1;
    }
  }
  shape.widest = std::max(shape.widest, width);
  return shape;
}

// Where the text cursor of the box `box_id` is, in pixels from the text's top-left corner; nullopt when the box is not
// being edited or the cursor has not moved and the text not changed since the last call.
std::optional<ImVec2> moved_cursor(ImGuiID box_id, StudentEditorState& state, float line_height) {
  const ImGuiInputTextState* edit = ImGui::GetInputTextState(box_id);
  if (!edit) {
    state.cursor_seen = state.length_seen = -1;
    return std::nullopt;
  }
  const int cursor = std::min(edit->Stb.cursor, edit->CurLenW);
  if (cursor == state.cursor_seen && edit->CurLenW == state.length_seen) return std::nullopt;
  state.cursor_seen = cursor;
  state.length_seen = edit->CurLenW;
  const ImFont* font = ImGui::GetFont();
  ImVec2 at(0.0f, 0.0f);
  for (int i = 0; i < cursor; ++i) {
    const ImWchar c = edit->TextW[i];
    if (c == '\n') {
      at = ImVec2(0.0f, at.y + line_height);
    } else {
      at.x += font->GetCharAdvance(c);
    }
  }
  return at;
}

// Scrolls the current window (the code view) so that the cursor at `cursor` (from the text's top-left corner, which
// sits `padding` inside the view's content) is in sight, with a few characters of margin sideways.
void keep_in_sight(ImVec2 cursor, ImVec2 padding, ImVec2 visible, float line_height) {
  const float margin = ImGui::GetFont()->GetCharAdvance(' ') * 4.0f;
  const float x = cursor.x + padding.x, y = cursor.y + padding.y;
  const float scroll_x = ImGui::GetScrollX(), scroll_y = ImGui::GetScrollY();
  if (x < scroll_x + margin) ImGui::SetScrollX(std::max(0.0f, x - margin));
  if (x > scroll_x + visible.x - margin) ImGui::SetScrollX(x - visible.x + margin);
  if (y < scroll_y) ImGui::SetScrollY(std::max(0.0f, y - padding.y));
  if (y + line_height > scroll_y + visible.y) ImGui::SetScrollY(y + line_height + padding.y - visible.y);
}

// The line numbers of the lines in sight, beside the view whose text starts at `text_top` (screen y, scrolled); the
// error line's number in the error colour on a band.
void draw_gutter(ImVec2 origin, ImVec2 size, float text_top, size_t lines, std::optional<size_t> error_line) {
  const Palette& palette = ui_palette();
  const float line_height = ImGui::GetTextLineHeight();
  const float spacing = ImGui::GetStyle().ItemSpacing.x;
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->PushClipRect(origin, ImVec2(origin.x + size.x, origin.y + size.y), true);
  const size_t first = size_t(std::max(0.0f, (origin.y - text_top) / line_height));
  const size_t last = std::min(lines, first + size_t(size.y / line_height) + 2);
  char number[24];
  for (size_t line = first + 1; line <= last; ++line) {
    const float y = text_top + float(line - 1) * line_height;
    const bool wrong = error_line && *error_line == line;
    if (wrong) {
      draw->AddRectFilled(ImVec2(origin.x, y), ImVec2(origin.x + size.x, y + line_height),
                          im_colour_u32(palette.error, 0.35f));
    }
    std::snprintf(number, sizeof number, "%zu", line);
    const float x = origin.x + size.x - spacing - ImGui::CalcTextSize(number).x;
    draw->AddText(ImVec2(x, y), wrong ? im_colour_u32(palette.error) : ImGui::GetColorU32(ImGuiCol_TextDisabled),
                  number);
  }
  draw->PopClipRect();
}

// The file's name, whether it is saved, and Save; true when Save was clicked.
bool draw_header(const StudentEdit& edit) {
  const std::string name = edit.path().filename().string();
  ImGui::TextUnformatted(name.empty() ? tr("no exercise") : name.c_str());
  ImGui::SameLine();
  ImGui::TextDisabled("%s", tr(edit.dirty() ? "(not saved)" : "(saved)"));
  ImGui::SameLine();
  const bool save = ImGui::Button(tr_label("Save"));
  ImGui::SameLine();
  ImGui::TextDisabled("Ctrl+S");
  if (!edit.read_error().empty()) ImGui::TextColored(im_colour(ui_palette().error), "%s", edit.read_error().c_str());
  return save;
}

// The code view: a child window that scrolls both ways around a text box the size of the text. Returns true when the
// student pressed Ctrl+S in the box; `text_top` is the screen y of the text's first line, scrolled.
bool draw_code_view(StudentEdit& edit, StudentEditorState& state, const TextShape& shape, ImVec2 size,
                    const std::string& error, std::optional<size_t> error_line, float& text_top) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float line_height = ImGui::GetTextLineHeight();
  ImGui::PushStyleColor(ImGuiCol_ChildBg, im_colour(ui_palette().neutrals.canvas));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0.0f, 0.0f));
  ImGui::BeginChild("##code view", size, true, ImGuiWindowFlags_HorizontalScrollbar);
  const ImVec2 visible = ImGui::GetContentRegionAvail();
  const float char_width = ImGui::GetFont()->GetCharAdvance(' ');
  const ImVec2 text_size(std::max(visible.x, float(shape.widest + 2) * char_width + style.FramePadding.x * 2.0f),
                         std::max(visible.y, float(shape.lines) * line_height + style.FramePadding.y * 2.0f));
  state.text_width = text_size.x;
  state.view_width = visible.x;
  const char* label = "##student code";
  const ImGuiID box_id = ImGui::GetID(label);
  ImGui::PushStyleColor(ImGuiCol_FrameBg, ImVec4(0.0f, 0.0f, 0.0f, 0.0f));  // the view's own background shows
  if (ImGui::InputTextMultiline(label, &edit.text_for_editing(), text_size,
                                ImGuiInputTextFlags_AllowTabInput | ImGuiInputTextFlags_NoHorizontalScroll)) {
    edit.mark_edited();
  }
  ImGui::PopStyleColor();
  const ImVec2 box_min = ImGui::GetItemRectMin();
  text_top = box_min.y + style.FramePadding.y;
  // Ctrl+S while the box has the keyboard (the GLFW backend's key indices: a letter is its ASCII capital).
  const bool save = ImGui::GetActiveID() == box_id && ImGui::GetIO().KeyCtrl && glfw_key_pressed('S', false);
  if (const std::optional<ImVec2> cursor = moved_cursor(box_id, state, line_height)) {
    keep_in_sight(*cursor, style.FramePadding, visible, line_height);
  }
  if (error.empty()) {
    state.scrolled_for.clear();
  } else if (error_line && error != state.scrolled_for) {
    ImGui::SetScrollY(std::max(0.0f, float(*error_line - 1) * line_height - visible.y / 3.0f));
    state.scrolled_for = error;
  }
  // The error line's band, under the text (the box's own window draws over the view's).
  if (error_line && *error_line <= shape.lines) {
    const float y = text_top + float(*error_line - 1) * line_height;
    ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(box_min.x, y), ImVec2(box_min.x + text_size.x, y + line_height),
                                              im_colour_u32(ui_palette().error, 0.25f));
  }
  ImGui::EndChild();
  ImGui::PopStyleVar();
  ImGui::PopStyleColor();
  return save;
}

}  // namespace

bool draw_student_editor_contents(StudentEdit& edit, StudentEditorState& state, const std::string& error,
                                  std::optional<size_t> error_line) {
  bool save = draw_header(edit);
  ImGui::PushFont(mono_font());
  const TextShape shape = shape_of(edit.text());
  char widest_number[24];
  std::snprintf(widest_number, sizeof widest_number, "%zu", std::max<size_t>(shape.lines, 99));
  const float gutter = ImGui::CalcTextSize(widest_number).x + ImGui::GetStyle().ItemSpacing.x * 2.0f;
  // The message under the editor: a few wrapped lines, kept in sight below the view.
  const float message_height = error.empty() ? 0.0f : ImGui::GetTextLineHeightWithSpacing() * 4.0f;
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const float view_height = std::max(ImGui::GetTextLineHeight() * 4.0f, avail.y - message_height);
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::Dummy(ImVec2(gutter, view_height));
  ImGui::SameLine(0.0f, 0.0f);
  float text_top = origin.y;
  save |= draw_code_view(edit, state, shape, ImVec2(avail.x - gutter, view_height), error, error_line, text_top);
  draw_gutter(origin, ImVec2(gutter, view_height), text_top, shape.lines, error_line);
  ImGui::PopFont();

  if (!error.empty()) {
    ImGui::PushTextWrapPos(0.0f);
    if (error_line) {
      ImGui::TextColored(
          im_colour(ui_palette().error), "%s",
          tr_format("line {line}: {error}", {{"line", std::to_string(*error_line)}, {"error", error}}).c_str());
    } else {
      ImGui::TextColored(im_colour(ui_palette().error), "%s", error.c_str());
    }
    ImGui::PopTextWrapPos();
  }
  return save;
}

}  // namespace meshedit
