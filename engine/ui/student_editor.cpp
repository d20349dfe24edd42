// The "Your code" panel (see student_editor.h): a gutter of line numbers beside ImGui's multiline text box, which
// scrolls itself; the gutter follows the box's scroll, read from the box's child window.
#include "ui/student_editor.h"

#include <algorithm>
#include <cstdio>

#include <imgui.h>
#include <imgui_internal.h>
#include <imgui_stdlib.h>

#include "ui/fonts.h"
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

// The child window ImGui's InputTextMultiline made for `label` in the current window (1.86 names it
// "PARENT/LABEL_ID"), or null before its first frame.
ImGuiWindow* text_box_window(const char* label) {
  ImGuiWindow* parent = ImGui::GetCurrentWindow();
  const ImGuiID id = parent->GetID(label);
  char name[512];
  std::snprintf(name, sizeof name, "%s/%s_%08X", parent->Name, label, id);
  return ImGui::FindWindowByName(name);
}

}  // namespace

bool draw_student_editor_contents(StudentEdit& edit, StudentEditorState& state, const std::string& error,
                                  std::optional<size_t> error_line) {
  const Palette& palette = ui_palette();
  bool save = false;
  const std::string name = edit.path().filename().string();
  ImGui::TextUnformatted(name.empty() ? "no exercise" : name.c_str());
  ImGui::SameLine();
  ImGui::TextDisabled(edit.dirty() ? "(not saved)" : "(saved)");
  ImGui::SameLine();
  if (ImGui::Button("Save")) save = true;
  const ImVec2 save_min = ImGui::GetItemRectMin(), save_max = ImGui::GetItemRectMax();
  state.save_x = (save_min.x + save_max.x) * 0.5f;
  state.save_y = (save_min.y + save_max.y) * 0.5f;
  ImGui::SameLine();
  ImGui::TextDisabled("Ctrl+S");
  if (!edit.read_error().empty()) ImGui::TextColored(im_colour(palette.error), "%s", edit.read_error().c_str());

  ImGui::PushFont(mono_font());
  const float line_height = ImGui::GetTextLineHeight();
  const TextShape shape = shape_of(edit.text());
  char number[24];
  std::snprintf(number, sizeof number, "%zu", std::max<size_t>(shape.lines, 99));
  const float gutter = ImGui::CalcTextSize(number).x + ImGui::GetStyle().ItemSpacing.x * 2.0f;
  // The message under the editor: a few wrapped lines, kept in sight below the box.
  const float message_height = error.empty() ? 0.0f : ImGui::GetTextLineHeightWithSpacing() * 4.0f;
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const float box_height = std::max(line_height * 4.0f, avail.y - message_height);
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::Dummy(ImVec2(gutter, box_height));
  ImGui::SameLine(0.0f, 0.0f);
  const char* label = "##student code";
  const ImGuiID box_id = ImGui::GetID(label);
  if (ImGui::InputTextMultiline(label, &edit.text_for_editing(), ImVec2(avail.x - gutter, box_height),
                                ImGuiInputTextFlags_AllowTabInput)) {
    edit.mark_edited();
  }
  // Ctrl+S while the box has the keyboard (the GLFW backend's key indices: a letter is its ASCII capital).
  const ImGuiIO& io = ImGui::GetIO();
  if (ImGui::GetActiveID() == box_id && io.KeyCtrl && ImGui::IsKeyPressed('S', false)) save = true;

  // The gutter: the numbers of the lines in sight, at the box's scroll; the error line in the error colour, and a
  // band across the box on that line.
  ImGuiWindow* box = text_box_window(label);
  if (error.empty()) {
    state.scrolled_for.clear();
  } else if (box && error_line && error != state.scrolled_for) {
    ImGui::SetScrollY(box, std::max(0.0f, float(*error_line - 1) * line_height - box_height / 3.0f));
    state.scrolled_for = error;
  }
  const float scroll = box ? box->Scroll.y : 0.0f;
  const float top = origin.y + ImGui::GetStyle().FramePadding.y;
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->PushClipRect(origin, ImVec2(origin.x + gutter, origin.y + box_height), true);
  const size_t first = size_t(std::max(0.0f, scroll / line_height));
  const size_t last = std::min(shape.lines, first + size_t(box_height / line_height) + 2);
  state.lines_drawn = 0;
  for (size_t line = first + 1; line <= last; ++line) {
    const float y = top + float(line - 1) * line_height - scroll;
    const bool wrong = error_line && *error_line == line;
    if (wrong)
      draw->AddRectFilled(ImVec2(origin.x, y), ImVec2(origin.x + gutter, y + line_height),
                          im_colour_u32(palette.error, 0.35f));
    std::snprintf(number, sizeof number, "%zu", line);
    const float x = origin.x + gutter - ImGui::GetStyle().ItemSpacing.x - ImGui::CalcTextSize(number).x;
    draw->AddText(ImVec2(x, y), wrong ? im_colour_u32(palette.error) : ImGui::GetColorU32(ImGuiCol_TextDisabled),
                  number);
    state.lines_drawn += 1;
  }
  draw->PopClipRect();
  if (error_line && box && *error_line <= shape.lines) {
    const float y = top + float(*error_line - 1) * line_height - scroll;
    ImDrawList* box_draw = box->DrawList;
    box_draw->PushClipRect(box->InnerClipRect.Min, box->InnerClipRect.Max, true);
    box_draw->AddRectFilled(ImVec2(box->Pos.x, y), ImVec2(box->Pos.x + box->Size.x, y + line_height),
                            im_colour_u32(palette.error, 0.25f));
    box_draw->PopClipRect();
  }
  ImGui::PopFont();

  if (!error.empty()) {
    ImGui::PushTextWrapPos(0.0f);
    if (error_line) {
      ImGui::TextColored(im_colour(palette.error), "line %zu: %s", *error_line, error.c_str());
    } else {
      ImGui::TextColored(im_colour(palette.error), "%s", error.c_str());
    }
    ImGui::PopTextWrapPos();
  }
  return save;
}

}  // namespace meshedit
