// The status bar (see status_bar.h).
#include "ui/status_bar.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <imgui.h>

#include "core/translation.h"
#include "core/validate.h"
#include "core/value_format.h"

namespace meshedit {
namespace {

ImVec4 severity_color(Severity severity) {
  switch (severity) {
    case Severity::Info: return ImGui::GetStyleColorVec4(ImGuiCol_Text);
    case Severity::Warning: return ui_colors::warning();
    case Severity::Error: return ui_colors::broken();
  }
  return ui_colors::broken();
}

void draw_validation(MeshDocument& doc, Selection& selection, StatusBarState& state) {
  const bool automatic = doc.mesh.num_halfedges() <= state.auto_validate_max_halfedges;
  if (!automatic && !cached_validation_if_cheap(doc)) {
    ImGui::TextDisabled("%s", tr("not validated (large mesh)"));
    ImGui::SameLine();
    const bool pressed = ImGui::SmallButton(tr_label("validate"));
    if (state.probe) state.probe->record_last_item("validate");
    if (!pressed) return;
  }
  const ValidationReport& report = cached_validation(doc);
  if (report.ok()) {
    ImGui::TextColored(ui_colors::valid(), "%s", tr("valid"));
    return;
  }
  const Violation& first = report.violations.front();
  const std::string problems =
      tr_format(report.total == 1 ? "{count} problem; first: {problem}" : "{count} problems; first: {problem}",
                {{"count", std::to_string(report.total)}, {"problem", first.message}});
  ImGui::TextColored(ui_colors::broken(), "%s", problems.c_str());
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", report.summary().c_str());
  ImGui::SameLine();
  const bool pressed = ImGui::SmallButton(tr_label("select##culprit"));
  if (state.probe) state.probe->record_last_item("select-culprit", first.element);
  if (pressed && in_range(doc.mesh, first.element)) selection.selected = first.element;
}

}  // namespace

float draw_status_bar(MeshDocument& doc, Selection& selection, StatusBarState& state, float frame_ms) {
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  // Whole pixels, as the window layout counts them (document/window_layout.h).
  const float height = std::ceil(ImGui::GetFrameHeightWithSpacing() + ImGui::GetStyle().WindowPadding.y * 2.0f);
  ImGui::SetNextWindowPos(ImVec2(viewport->WorkPos.x, viewport->WorkPos.y + viewport->WorkSize.y - height));
  ImGui::SetNextWindowSize(ImVec2(viewport->WorkSize.x, height));
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                 ImGuiWindowFlags_NoBringToFrontOnFocus;
  if (ImGui::Begin("##status bar", nullptr, flags)) {
    // The up axis and the frame time keep their place at the right end; the rest, whose length varies (a message,
    // the view's note, undo hints), is clipped before them rather than pushing them off the window.
    const std::string frame = format_fixed(frame_ms, 1) + " ms";
    const bool show_axis = !state.up_axis.empty() && state.view_is_3d;
    const char* up_axis = show_axis ? tr(state.up_axis.data()) : "";  // NUL-terminated literals (status_bar.h)
    const float gap = 24.0f;
    const float right_width =
        ImGui::CalcTextSize(frame.c_str()).x + (show_axis ? ImGui::CalcTextSize(up_axis).x + gap : 0.0f);
    const float left_width = std::max(1.0f, ImGui::GetContentRegionAvail().x - right_width - gap);
    ImGui::BeginChild("##status left", ImVec2(left_width, ImGui::GetFrameHeight()), false,
                      ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
    const HalfedgeMesh& mesh = doc.mesh;
    if (state.mesh_shown) {
      const long chi = long(mesh.num_vertices()) - long(mesh.num_edges()) + long(mesh.num_faces());
      ImGui::Text("V %zu  E %zu  F %zu  H %zu  B %zu  chi %ld", mesh.num_vertices(), mesh.num_edges(), mesh.num_faces(),
                  mesh.num_halfedges(), mesh.num_boundaries(), chi);
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tr("chi = V - E + F (boundary loops are holes, not faces)"));
      ImGui::SameLine(0.0f, gap);
      draw_validation(doc, selection, state);
    }
    if (!doc.message.text.empty()) {
      ImGui::SameLine(0.0f, gap);
      ImGui::TextColored(severity_color(doc.message.severity), "%s", doc.message.text.c_str());
      if (ImGui::IsItemHovered()) {  // the whole message, where the bar cuts it
        ImGui::BeginTooltip();
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * 40.0f);
        ImGui::TextUnformatted(doc.message.text.c_str());
        ImGui::PopTextWrapPos();
        ImGui::EndTooltip();
      }
      if (in_range(doc.mesh, doc.message.element) && doc.message.severity != Severity::Info) {
        ImGui::SameLine();
        const bool pressed = ImGui::SmallButton(tr_label("select##message"));
        if (state.probe) state.probe->record_last_item("select-message", doc.message.element);
        if (pressed) selection.selected = doc.message.element;
      }
    }
    if (!state.note.empty()) {
      ImGui::SameLine(0.0f, gap);
      ImGui::TextDisabled("%s", state.note.c_str());
    }
    if (state.mesh_shown && doc.history.can_undo()) {
      ImGui::SameLine(0.0f, gap);
      ImGui::TextDisabled("%s",
                          tr_format("Ctrl+Z: undo {operation}", {{"operation", doc.history.undo_label()}}).c_str());
    }
    if (state.mesh_shown && doc.history.can_redo()) {
      ImGui::SameLine();
      ImGui::TextDisabled("%s",
                          tr_format(" Ctrl+Y: redo {operation}", {{"operation", doc.history.redo_label()}}).c_str());
    }
    ImGui::EndChild();
    if (show_axis) {
      ImGui::SameLine(0.0f, gap);
      ImGui::TextDisabled("%s", up_axis);
      if (state.probe) state.probe->record_last_item("up-axis");
      if (ImGui::IsItemHovered() && !state.up_axis_why.empty()) ImGui::SetTooltip("%s", tr(state.up_axis_why.data()));
    }
    ImGui::SameLine(0.0f, gap);
    ImGui::TextDisabled("%s", frame.c_str());
  }
  ImGui::End();
  return height;
}

}  // namespace meshedit
