// The Check tab (see check_panel.h).
#include "ui/check_panel.h"

#include <imgui.h>

#include "core/translation.h"
#include "core/value_format.h"
#include "ui/flow_layout.h"

namespace meshedit {
namespace {

void wrapped(const std::string& text) { text_wrapped_at_spaces(text); }

void coloured(const ImVec4& colour, const std::string& text) {
  ImGui::PushStyleColor(ImGuiCol_Text, colour);
  wrapped(text);
  ImGui::PopStyleColor();
}

bool button(const char* label, const char* probe_name, UiProbe* probe) {
  const bool clicked = ImGui::Button(label);
  if (probe) probe->record_last_item(probe_name);
  return clicked;
}

void draw_rows(const CheckPanelView& view, CheckPanelActions& actions, UiProbe* probe) {
  bool first_failure = true;  // opens by itself; the others open with a click, so the list stays an overview
  for (size_t i = 0; i < view.rows.size(); ++i) {
    const CheckPanelView::Row& row = view.rows[i];
    ImGui::PushID(static_cast<int>(i));
    ImGui::PushStyleColor(ImGuiCol_Text, row.passed ? ui_colors::valid() : ui_colors::broken());
    const ImGuiTreeNodeFlags flags = !row.passed && first_failure ? ImGuiTreeNodeFlags_DefaultOpen : 0;
    first_failure = first_failure && row.passed;
    // The node holds the verdict and the number; the name beside it wraps at the column's edge (a node's label would
    // be cut off there).
    const std::string label = tr_format(row.passed ? "passed ({points}) {number}:" : "FAILED ({points}) {number}:",
                                        {{"points", row.points}, {"number", row.number}});
    const bool open = ImGui::TreeNodeEx("test", flags, "%s", label.c_str());
    ImGui::SameLine();
    wrapped(row.name);
    ImGui::PopStyleColor();
    if (probe) probe->record_last_item("check-test:" + row.number);
    if (open) {
      wrapped(row.text);
      if (!row.case_input.empty()) {
        if (button(tr_label("Open in Exercises"), ("check-open:" + row.number).c_str(), probe)) actions.open_case = i;
        if (ImGui::IsItemHovered()) {
          ImGui::SetTooltip("%s", tr_format("the input of this test ({input}) in the Exercises tab, with your function "
                                            "run on it",
                                            {{"input", row.case_input}})
                                      .c_str());
        }
      }
      ImGui::TreePop();
    }
    ImGui::PopID();
  }
}

constexpr const char* kNotRun = "Not checked yet. Save your files, then press Check my work.";
constexpr const char* kStopped = "Stopped: no verdict.";
constexpr const char* kProblem = "The grader could not check your work:";

}  // namespace

std::string check_row_label(const CheckPanelView::Row& row) {
  return std::string(row.passed ? "passed" : "FAILED") + " (" + row.points + ") " + row.number + ": " + row.name;
}

std::string check_panel_text(const CheckPanelView& view) {
  std::string text;
  const auto line = [&](const std::string& words) {
    if (!words.empty()) text += words + (words.back() == '\n' ? "" : "\n");
  };
  switch (view.state) {
    case CheckPanelView::State::NotRun: line(kNotRun); break;
    case CheckPanelView::State::Running:
      line("Running: " + std::to_string(view.done) + " of " + std::to_string(view.total) + " tests done");
      if (!view.running_test.empty()) line("now: test " + std::to_string(view.done + 1) + ", " + view.running_test);
      break;
    case CheckPanelView::State::Stopped: line(kStopped); break;
    case CheckPanelView::State::Problem:
      line(kProblem);
      line(view.problem);
      break;
    case CheckPanelView::State::Graded:
      line(view.total_line);
      line(view.not_shown);
      line(view.notes);
      for (const auto& row : view.rows) {
        line(check_row_label(row));
        line(row.text);
      }
      break;
  }
  return text;
}

CheckPanelActions draw_check_panel_contents(const CheckPanelView& view, CheckPanelState& /*state*/, UiProbe* probe) {
  CheckPanelActions actions;
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextDisabled("%s", tr("Check my work: the course's visible tests on your files, as Gradescope runs them"));
  ImGui::TextDisabled("%s", tr_format("Suite {suite}; your files in {folder}",
                                      {{"suite", view.suite.filename().string()}, {"folder", view.folder}})
                                .c_str());
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", view.suite.string().c_str());
  if (view.state == CheckPanelView::State::Running) {
    if (button(tr_label("Stop"), "check-stop", probe)) actions.stop = true;
    ImGui::SameLine();
    const std::string seconds = format_fixed(view.seconds, 1);
    if (view.total > 0) {
      ImGui::TextUnformatted(
          tr_format("Running: {done} of {total} tests done ({seconds} s)",
                    {{"done", std::to_string(view.done)}, {"total", std::to_string(view.total)}, {"seconds", seconds}})
              .c_str());
      ImGui::ProgressBar(static_cast<float>(view.done) / static_cast<float>(view.total), ImVec2(-1.0f, 0.0f));
    } else {
      ImGui::TextUnformatted(tr_format("Starting the grader... ({seconds} s)", {{"seconds", seconds}}).c_str());
    }
    if (!view.running_test.empty()) {
      ImGui::TextDisabled("%s", tr_format("now: test {number}, {test}",
                                          {{"number", std::to_string(view.done + 1)}, {"test", view.running_test}})
                                    .c_str());
    }
    ImGui::PopTextWrapPos();
    return actions;
  }
  if (button(tr_label(view.state == CheckPanelView::State::NotRun ? "Check my work" : "Check again"), "check-run",
             probe)) {
    actions.check = true;
  }
  ImGui::Separator();
  switch (view.state) {
    case CheckPanelView::State::NotRun: wrapped(tr(kNotRun)); break;
    case CheckPanelView::State::Stopped: coloured(ui_colors::warning(), tr(kStopped)); break;
    case CheckPanelView::State::Problem:
      coloured(ui_colors::broken(), tr(kProblem));
      wrapped(view.problem);
      break;
    case CheckPanelView::State::Graded: {
      const bool all = !view.rows.empty() && [&] {
        for (const auto& row : view.rows) {
          if (!row.passed) return false;
        }
        return true;
      }();
      coloured(all ? ui_colors::valid() : ui_colors::warning(), view.total_line);
      if (probe) probe->record_last_item("check-total");
      if (!view.not_shown.empty()) ImGui::TextDisabled("%s", view.not_shown.c_str());
      for (const std::string& warning : view.warnings) coloured(ui_colors::warning(), warning);
      if (!view.notes.empty() && ImGui::TreeNode(tr_label("Your files, as the grader found them"))) {
        wrapped(view.notes);
        ImGui::TreePop();
      }
      ImGui::Separator();
      draw_rows(view, actions, probe);
      break;
    }
    case CheckPanelView::State::Running: break;
  }
  ImGui::PopTextWrapPos();
  return actions;
}

}  // namespace meshedit
