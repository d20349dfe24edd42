// The curve view's ImGui window (ImDrawList only, no GL). The state changes are curve_view_state.h's.
//
// Map of this file (each part starts at its `// ---- name` banner):
//   ImGui            colours, "mine" levels, draw_mismatch
//   the canvas       draw_canvas, draw_canvas_contents and their parts
//   the level table  table_text_row, draw_mine_rows, draw_level_table
//   windows          draw_curve_controls, draw_curve_canvas, draw_curve_picture, draw_curve_levels,
//                    draw_curve_editor
#include "ui/curve_editor.h"

#include <algorithm>
#include <cfloat>
#include <cstdio>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <imgui.h>
#include <glm/geometric.hpp>

#include "core/translation.h"
#include "core/value_format.h"
#include "document/bezier_mine.h"
#include "ui/flow_layout.h"
#include "ui/theme.h"

namespace meshedit {

// ---- ImGui -----------------------------------------------------------------------------------------

namespace {

// Colours from the theme's palette (core/palette.h). "Mine": a level of yours that is not the reference's is
// drawn in the wrong colour, the reference's level it should have been in the reference colour (ghosted).
const Palette& palette() { return ui_palette(); }
ImU32 colour_of(glm::vec3 rgb, float alpha = 1.0f) { return im_colour_u32(rgb, alpha); }
ImU32 control_colour() { return colour_of(palette().control); }
ImU32 final_colour() { return colour_of(palette().final_point); }
ImU32 curve_colour() { return colour_of(palette().curve); }  // the grabbed point too: the course draws it green
// The halves' polygons run along the level lines (they are made of the pyramid's edge points), so they
// are drawn as wide translucent bands underneath, with rings on their points above everything.
ImU32 split_left_band() { return colour_of(palette().split_left, 0.47f); }
ImU32 split_right_band() { return colour_of(palette().split_right, 0.47f); }
ImU32 split_left_ring() { return colour_of(palette().split_left); }
ImU32 split_right_ring() { return colour_of(palette().split_right); }
ImU32 wrong_colour() { return colour_of(palette().wrong); }
ImU32 ghost_colour() { return colour_of(palette().reference, kGhostAlpha); }
ImU32 error_colour() { return colour_of(palette().error); }
ImU32 mine_ok_colour() { return colour_of(palette().mine); }
ImU32 level_colour(int k) { return colour_of(meshedit::level_colour(palette(), k)); }

ImVec2 to_imvec(glm::dvec2 p) { return ImVec2(static_cast<float>(p.x), static_cast<float>(p.y)); }

// The canvas's words: in the window's language on the window's canvas (`window`), English in a write-up's picture,
// whose bytes stay the same whatever the window shows.
const char* canvas_word(const char* english, bool window) { return window ? tr(english) : english; }
std::string canvas_format(const char* english, const MessageParts& parts, bool window) {
  return window ? tr_format(english, parts) : fill_template(english, parts);
}

void draw_polyline(ImDrawList* dl, const CurveView& view, std::span<const glm::dvec2> points, ImU32 colour,
                   float thickness) {
  if (points.size() < 2) return;
  std::vector<ImVec2> screen;
  screen.reserve(points.size());
  for (const glm::dvec2& p : points) screen.push_back(to_imvec(curve_to_screen(view, p)));
  dl->AddPolyline(screen.data(), static_cast<int>(screen.size()), colour, ImDrawFlags_None, thickness);
}

void draw_points(ImDrawList* dl, const CurveView& view, std::span<const glm::dvec2> points, ImU32 colour,
                 float radius) {
  for (const glm::dvec2& p : points) dl->AddCircleFilled(to_imvec(curve_to_screen(view, p)), radius, colour);
}

std::string format_points(std::span<const glm::dvec2> points) {
  std::string text;
  for (const glm::dvec2& p : points) {
    text += (text.empty() ? "(" : "  (") + format_fixed(p.x, 4) + ", " + format_fixed(p.y, 4) + ")";
  }
  return text;
}

glm::dvec2 flat(const glm::dvec3& p) { return {p.x, p.y}; }

std::vector<glm::dvec2> flat(const std::vector<glm::dvec3>& points) {
  std::vector<glm::dvec2> out;
  out.reserve(points.size());
  for (const glm::dvec3& p : points) out.push_back(flat(p));
  return out;
}

// Your levels 0..shown (fewer when yours stopped earlier).
std::vector<std::vector<glm::dvec2>> mine_shown_levels(const CurveMineLevels& mine, int shown) {
  std::vector<std::vector<glm::dvec2>> levels;
  for (int k = 0; k < static_cast<int>(mine.levels.size()) && k <= shown; ++k) levels.push_back(flat(mine.levels[k]));
  return levels;
}

ImU32 mine_message_colour(const CurveMineLevels& mine, int shown) {
  if (mine.load_failed || (!mine.error.empty() && mine.failed_level <= shown)) return error_colour();
  if (mine.failed() && mine.failed_level <= shown) return wrong_colour();
  return mine_ok_colour();
}

// Under your level that differs: the reference's level, ghosted, and a line from your wrong point to the
// reference's, each labelled.
void draw_mismatch(ImDrawList* dl, const CurveView& view, const CurveMineLevels& mine, bool window) {
  const std::vector<glm::dvec2> reference = flat(mine.reference_level);
  draw_polyline(dl, view, reference, ghost_colour(), 1.0f);
  for (const glm::dvec2& p : reference) {
    dl->AddCircle(to_imvec(curve_to_screen(view, p)), 5.0f, ghost_colour(), 0, 1.5f);
  }
  if (mine.wrong_point < 0) return;
  const ImVec2 yours = to_imvec(curve_to_screen(view, flat(mine.mine_point)));
  const ImVec2 theirs = to_imvec(curve_to_screen(view, flat(mine.reference_point)));
  dl->AddLine(yours, theirs, wrong_colour(), 1.0f);
  dl->AddCircle(yours, 11.0f, wrong_colour(), 0, 2.0f);
  dl->AddText(ImVec2(yours.x + 13.0f, yours.y - 8.0f), wrong_colour(), canvas_word("yours", window));
  dl->AddText(ImVec2(theirs.x + 9.0f, theirs.y + 2.0f), ghost_colour(), canvas_word("reference", window));
}

// ---- the canvas ------------------------------------------------------------------------------------

// The canvas; `mine` is the student's levels when the switch is on (else null).
// The mouse over the canvas (the invisible button just drawn), handed to handle_canvas_input.
void read_canvas_input(CurveEditorState& state) {
  if (!ImGui::IsMousePosValid()) return;
  const ImGuiIO& io = ImGui::GetIO();
  CanvasInput input;
  input.mouse = {io.MousePos.x, io.MousePos.y};
  input.hovered = ImGui::IsItemHovered();
  input.left_down = ImGui::IsMouseDown(ImGuiMouseButton_Left);
  input.left_pressed = input.hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left);
  input.left_double_clicked = input.hovered && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left);
  input.right_pressed = input.hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Right);
  input.wheel = input.hovered ? io.MouseWheel : 0.0;
  handle_canvas_input(state, input);
}

// De Casteljau's levels above the control polygon; the first wrong one of yours (`wrong_level`) thicker, with what it
// should have been (its labels in the window's language on the window's canvas, `window`).
void draw_levels(ImDrawList* dl, const CurveView& view, const std::vector<std::vector<glm::dvec2>>& levels,
                 const CurveMineLevels* yours, int wrong_level, bool window) {
  for (size_t k = 1; k < levels.size(); ++k) {
    const bool wrong = static_cast<int>(k) == wrong_level;
    if (wrong) draw_mismatch(dl, view, *yours, window);
    const ImU32 colour = wrong ? wrong_colour() : level_colour(static_cast<int>(k));
    draw_polyline(dl, view, levels[k], colour, wrong ? 3.0f : 1.5f);
    draw_points(dl, view, levels[k], colour, wrong ? 5.0f : 4.0f);
  }
}

// C(t), when the last level shown is the single point and it is not the wrong one; over the control points.
void draw_curve_point(ImDrawList* dl, const CurveView& view, const std::vector<std::vector<glm::dvec2>>& levels,
                      int wrong_level) {
  if (levels.size() > 1 && levels.back().size() == 1 && static_cast<int>(levels.size()) - 1 != wrong_level) {
    const ImVec2 c = to_imvec(curve_to_screen(view, levels.back()[0]));
    dl->AddCircleFilled(c, 7.0f, final_colour());
    dl->AddText(ImVec2(c.x + 9.0f, c.y - 18.0f), final_colour(), "C(t)");
  }
}

// The tangent at C(t): an arrow from C(t) along C'(t) / n (as long as the last step's segment), labelled.
void draw_tangent(ImDrawList* dl, const CurveEditorState& state) {
  const auto& points = state.curve.control_points;
  if (points.size() < 2) return;
  const double degree = static_cast<double>(points.size() - 1);
  const glm::dvec2 from = evaluate_curve(state.curve, state.t);
  const glm::dvec2 to = from + curve_derivative(points, state.t) / degree;
  const glm::dvec2 a = curve_to_screen(state.view, from), b = curve_to_screen(state.view, to);
  const ImU32 colour = final_colour();
  dl->AddLine(to_imvec(a), to_imvec(b), colour, 3.0f);
  const double length = glm::length(b - a);
  if (length >= 1.0) {  // the head: a triangle 12 pixels long at `to`
    const glm::dvec2 along = (b - a) / length, across(-along.y, along.x);
    const double head = std::min(12.0, length);
    dl->AddTriangleFilled(to_imvec(b), to_imvec(b - head * along + 0.5 * head * across),
                          to_imvec(b - head * along - 0.5 * head * across), colour);
  }
  char label[32];
  std::snprintf(label, sizeof label, "C'(t) / %d", static_cast<int>(degree));
  dl->AddText(ImVec2(static_cast<float>(b.x) + 8.0f, static_cast<float>(b.y) - 8.0f), colour, label);
}

// The control points (the grabbed and the hovered one marked), and rings on the two halves' control points.
void draw_control_points(ImDrawList* dl, const CurveEditorState& state, const CurveSplit<glm::dvec2>& halves) {
  const auto& points = state.curve.control_points;
  for (int i = 0; i < static_cast<int>(points.size()); ++i) {
    const ImVec2 c = to_imvec(curve_to_screen(state.view, points[i]));
    const bool grabbed = i == state.dragged;
    dl->AddCircleFilled(c, grabbed ? 7.0f : 6.0f, grabbed ? curve_colour() : control_colour());
    if (i == state.hovered && !grabbed) dl->AddCircle(c, 10.0f, curve_colour(), 0, 2.0f);
  }
  for (const glm::dvec2& p : halves.left) {
    dl->AddCircle(to_imvec(curve_to_screen(state.view, p)), 9.0f, split_left_ring(), 0, 2.0f);
  }
  for (const glm::dvec2& p : halves.right) {
    dl->AddCircle(to_imvec(curve_to_screen(state.view, p)), 12.0f, split_right_ring(), 0, 2.0f);
  }
}

// The status line and mine's message (of `file`) at the top of the canvas, the key hints at its bottom (a window's
// canvas, not a picture).
void draw_canvas_text(ImDrawList* dl, const CurveEditorState& state, ImVec2 p0, ImVec2 size, int shown,
                      const CurveMineLevels* yours, const std::string& file, bool hints) {
  const float wrap = std::max(size.x - 16.0f, 50.0f);
  const MessageParts parts = {
      {"t", format_fixed(state.t, 4)},
      {"level", std::to_string(shown)},
      {"last", std::to_string(std::max(0, static_cast<int>(state.curve.control_points.size()) - 1))}};
  const char* status_template =
      yours ? "t = {t}   level {level} of {last}   mine: your evaluate_step" : "t = {t}   level {level} of {last}";
  const std::string status = canvas_format(status_template, parts, hints);
  dl->AddText(ImVec2(p0.x + 8.0f, p0.y + 6.0f), colour_of(palette().swatches.ink), status.c_str());
  if (yours) {
    const std::string line =
        canvas_format("mine ({file}): {message}", {{"file", file}, {"message", yours->message}}, hints);
    dl->AddText(ImGui::GetFont(), ImGui::GetFontSize(), ImVec2(p0.x + 8.0f, p0.y + 8.0f + ImGui::GetTextLineHeight()),
                mine_message_colour(*yours, shown), line.c_str(), nullptr, wrap);
  }
  if (!hints) return;
  const char* hint =
      tr("drag: move   double-click: add   right-click: remove   scroll: t   E: step   C: curve   M: mine");
  const ImVec2 hint_size = ImGui::GetFont()->CalcTextSizeA(ImGui::GetFontSize(), FLT_MAX, wrap, hint);
  dl->AddText(ImGui::GetFont(), ImGui::GetFontSize(), ImVec2(p0.x + 8.0f, p0.y + size.y - hint_size.y - 6.0f),
              colour_of(palette().swatches.grey), hint, nullptr, wrap);
}

// Everything the canvas shows, in the rectangle at p0 of `size` (state.view already placed there).
void draw_canvas_contents(ImDrawList* dl, const CurveEditorState& state, ImVec2 p0, ImVec2 size,
                          const CurveMineLevels* yours, const std::string& file, bool hints) {
  const int shown = shown_level(state);
  const ImVec2 p1(p0.x + size.x, p0.y + size.y);
  dl->PushClipRect(p0, p1, true);
  dl->AddRectFilled(p0, p1, colour_of(palette().neutrals.canvas));
  dl->AddRect(p0, p1, colour_of(palette().swatches.grey));

  const auto& points = state.curve.control_points;
  const CurveView& view = state.view;
  if (state.show_curve) draw_polyline(dl, view, sample_curve(points), curve_colour(), 2.5f);
  const CurveSplit<glm::dvec2> halves = state.show_split ? split_halves(state) : CurveSplit<glm::dvec2>{};
  draw_polyline(dl, view, halves.left, split_left_band(), 8.0f);
  draw_polyline(dl, view, halves.right, split_right_band(), 8.0f);
  draw_polyline(dl, view, points, control_colour(), 2.0f);

  const auto levels = yours ? mine_shown_levels(*yours, shown) : shown_levels(state);
  const int wrong_level = yours && yours->error.empty() ? yours->failed_level : -1;
  draw_levels(dl, view, levels, yours, wrong_level, hints);
  draw_control_points(dl, state, halves);
  draw_curve_point(dl, view, levels, wrong_level);
  if (state.show_tangent) draw_tangent(dl, state);
  draw_canvas_text(dl, state, p0, size, shown, yours, file, hints);
  dl->PopClipRect();
}

void draw_canvas(CurveEditorState& state, ImVec2 size, BezierMine* mine) {
  const ImVec2 p0 = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton("canvas", size, ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
  state.view = view_for(state.region, {p0.x, p0.y}, {size.x, size.y});
  read_canvas_input(state);

  const int shown = shown_level(state);
  const CurveMineLevels* yours =
      mine && mine->curve_on() ? &mine->curve_levels(state.curve.control_points, state.t, shown) : nullptr;
  const std::string file = mine ? mine->curve_file().path().filename().string() : std::string();
  draw_canvas_contents(ImGui::GetWindowDrawList(), state, p0, size, yours, file, true);
}

// ---- the level table -------------------------------------------------------------------------------

void table_text_row(const char* name, ImU32 colour, const std::string& text) {
  const ImVec4 c = ImGui::ColorConvertU32ToFloat4(colour);
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  ImGui::TextColored(c, "%s", name);
  ImGui::TableNextColumn();
  ImGui::PushStyleColor(ImGuiCol_Text, c);
  text_wrapped_at_spaces(text);
  ImGui::PopStyleColor();
}

// With "mine": your levels, the one that differs in the wrong colour followed by the reference's and the
// checker's diagnosis; a Lua error in the error colour.
void draw_mine_rows(const CurveMineLevels& mine, int shown) {
  const ImU32 disabled = ImGui::GetColorU32(ImGuiCol_TextDisabled);
  for (int k = 0; k < static_cast<int>(mine.levels.size()); ++k) {
    const bool wrong = k == mine.failed_level;
    const bool final_point = k > 0 && mine.levels[k].size() == 1;
    const ImU32 colour = k > shown ? disabled : wrong ? wrong_colour() : final_point ? final_colour() : level_colour(k);
    table_text_row(std::to_string(k).c_str(), colour, format_points(flat(mine.levels[k])));
  }
  if (!mine.failed() || mine.failed_level > shown) {
    if (mine.running) {
      table_text_row(std::to_string(mine.levels.size()).c_str(), disabled, tr("your evaluate_step is running..."));
    } else if (!mine.complete()) {
      table_text_row("...", disabled, tr("the next level comes from your evaluate_step when E shows it"));
    }
    return;
  }
  if (!mine.error.empty()) {
    const std::string name =
        mine.load_failed ? tr("error") : tr_format("error {level}", {{"level", std::to_string(mine.failed_level)}});
    table_text_row(name.c_str(), error_colour(), mine.error);
    return;
  }
  table_text_row(tr("reference"), ghost_colour(), format_points(flat(mine.reference_level)));
  for (const std::string& line : mine.details) table_text_row("", wrong_colour(), "- " + line);
}

void draw_level_table(const CurveEditorState& state, const CurveMineLevels* mine) {
  const auto levels = all_levels(state);
  const int shown = shown_level(state);
  const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_BordersOuter;
  if (!ImGui::BeginTable("levels", 2, flags)) return;
  ImGui::TableSetupColumn(tr(mine ? "level (yours)" : "level"), ImGuiTableColumnFlags_WidthFixed);
  ImGui::TableSetupColumn(tr("points"), ImGuiTableColumnFlags_WidthStretch);
  ImGui::TableHeadersRow();
  if (mine) draw_mine_rows(*mine, shown);
  for (int k = 0; !mine && k < static_cast<int>(levels.size()); ++k) {
    const bool is_shown = k <= shown;
    const ImVec4 colour =
        is_shown ? ImGui::ColorConvertU32ToFloat4(k + 1 == static_cast<int>(levels.size()) && k > 0 ? final_colour()
                                                                                                    : level_colour(k))
                 : ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled);
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextColored(colour, "%d", k);
    ImGui::TableNextColumn();
    ImGui::PushStyleColor(ImGuiCol_Text, colour);
    text_wrapped_at_spaces(format_points(levels[k]));
    ImGui::PopStyleColor();
  }
  if (state.show_split) {
    const CurveSplit<glm::dvec2> halves = split_halves(state);
    const std::pair<const char*, const std::vector<glm::dvec2>*> rows[] = {{"left", &halves.left},
                                                                           {"right", &halves.right}};
    for (const auto& [name, points] : rows) {
      const ImVec4 colour =
          ImGui::ColorConvertU32ToFloat4(points == &halves.left ? split_left_ring() : split_right_ring());
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextColored(colour, "%s", tr(name));
      ImGui::TableNextColumn();
      ImGui::PushStyleColor(ImGuiCol_Text, colour);
      text_wrapped_at_spaces(format_points(*points));
      ImGui::PopStyleColor();
    }
  }
  ImGui::EndTable();
}

}  // namespace

// ---- windows ---------------------------------------------------------------------------------------

void draw_curve_controls(CurveEditorState& state, BezierMine* mine) {
  const int n = static_cast<int>(state.curve.control_points.size());
  if (ImGui::Button(tr_label("Step (E)"))) step_level(state);
  same_line_if_room(tr_label("Curve (C)"));
  bool show_curve = state.show_curve;
  if (ImGui::Checkbox(tr_label("Curve (C)"), &show_curve)) toggle_curve(state);
  same_line_if_room(tr_label("Split at t"));
  bool show_split = state.show_split;
  if (ImGui::Checkbox(tr_label("Split at t"), &show_split)) toggle_split(state);
  same_line_if_room(tr_label("Tangent"));
  bool show_tangent = state.show_tangent;
  if (ImGui::Checkbox(tr_label("Tangent"), &show_tangent)) toggle_tangent(state);
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("%s", tr("the arrow C'(t) / n from C(t): the last step's segment, moved"));
  }
  same_line_if_room(tr_label("Add point"));
  if (ImGui::Button(tr_label("Add point"))) add_point_default(state);
  same_line_if_room(tr_label("Remove last"));
  ImGui::BeginDisabled(n <= 2);
  if (ImGui::Button(tr_label("Remove last"))) remove_point(state, n - 1);
  ImGui::EndDisabled();
  same_line_if_room(tr_label("Fit view"));
  if (ImGui::Button(tr_label("Fit view"))) fit_view(state);
  if (mine) {
    same_line_if_room(tr_label("mine (M)"));
    bool on = mine->curve_on();
    if (ImGui::Checkbox(tr_label("mine (M)"), &on)) mine->set_curve_on(on);
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip("%s", tr_format("levels from your evaluate_step in {file}, checked against the reference",
                                        {{"file", mine->curve_file().path().string()}})
                                  .c_str());
    }
  }

  double t = state.t;
  const double t_min = 0.0;
  const double t_max = 1.0;
  ImGui::SetNextItemWidth(std::max(ImGui::GetContentRegionAvail().x - 60.0f, 100.0f));
  if (ImGui::SliderScalar("t", ImGuiDataType_Double, &t, &t_min, &t_max, "%.4f")) set_t(state, t);
}

void draw_curve_canvas(CurveEditorState& state, ImVec2 size, BezierMine* mine) {
  draw_canvas(state, ImVec2(std::max(size.x, 1.0f), std::max(size.y, 1.0f)), mine);
}

void draw_curve_picture(ImDrawList* dl, CurveEditorState& state, ImVec2 p0, ImVec2 size, const CurveMineLevels* yours,
                        const std::string& file) {
  state.view = view_for(state.region, {p0.x, p0.y}, {size.x, size.y});
  draw_canvas_contents(dl, state, p0, size, yours, file, false);
}

void draw_curve_levels(CurveEditorState& state, BezierMine* mine) {
  // The canvas computed this frame's levels: reading them back runs no Lua.
  draw_level_table(state, mine && mine->curve_on() ? &mine->curve() : nullptr);
}

void draw_curve_editor_contents(CurveEditorState& state, BezierMine* mine) {
  draw_curve_controls(state, mine);
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const float line = ImGui::GetFrameHeightWithSpacing();
  const float table_height = std::clamp(avail.y * 0.3f, 3.0f * line, 12.0f * line);
  const ImVec2 canvas_size(std::max(avail.x, 240.0f), std::max(avail.y - table_height, 180.0f));
  draw_canvas(state, canvas_size, mine);

  ImGui::BeginChild("level_table", ImVec2(0.0f, 0.0f), false);
  draw_curve_levels(state, mine);
  ImGui::EndChild();
}

void draw_curve_editor(CurveEditorState& state, const char* title, BezierMine* mine) {
  // The wheel belongs to t over the canvas: the window itself must not scroll with it.
  if (ImGui::Begin(tr_label(title), nullptr, ImGuiWindowFlags_NoScrollWithMouse | ImGuiWindowFlags_NoScrollbar)) {
    draw_curve_editor_contents(state, mine);
  }
  ImGui::End();
}

}  // namespace meshedit
