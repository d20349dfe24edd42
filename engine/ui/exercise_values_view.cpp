// The Exercises tab's view of an exercise on points or a patch: see exercise_values_view.h for the contract.
#include "ui/exercise_values_view.h"

#include <algorithm>

#include <imgui.h>

#include "core/translation.h"
#include "core/value_format.h"
#include "exercise/scripted_exercise.h"
#include "exercise/value_compare.h"
#include "ui/flow_layout.h"
#include "ui/theme.h"

namespace meshedit {

std::vector<ValueRow> value_rows(const ExerciseRun& run) {
  std::vector<ValueRow> rows;
  const std::shared_ptr<const ScriptedExercise> scripted = run.exercise.definition();
  if (!scripted || !scripted->takes_values()) return rows;
  const ExerciseOutcome& reference = run.report.reference;
  const ExerciseOutcome& mine = run.report.mine;
  const double tolerance = scripted->tolerance(run.input);
  const auto differs = [&](const ExerciseValue& a, const ExerciseValue& b) {
    return run.mine && !compare_values(a, b, tolerance, 0).equal;
  };
  const auto text = [&](const ExerciseOutcome& outcome) {
    return outcome.error.empty() ? value_text(outcome.value) : std::string(tr("(failed)"));
  };
  const ExerciseValue& want = reference.value;
  const ExerciseValue& got = mine.value;
  const bool lists = want.kind == ExerciseValue::Kind::List && (!run.mine || got.kind == ExerciseValue::Kind::List);
  if (!lists || !reference.error.empty() || (run.mine && !mine.error.empty())) {
    rows.push_back({tr("returned"), run.mine ? text(mine) : "", text(reference), differs(got, want)});
    return rows;
  }
  const size_t n = std::min(std::max(want.items.size(), run.mine ? got.items.size() : 0), kMaxValueRows);
  if (n == 0) rows.push_back({tr("returned"), run.mine ? "{}" : "", "{}", false});
  for (size_t i = 0; i < n; ++i) {
    const ExerciseValue* a = run.mine && i < got.items.size() ? &got.items[i] : nullptr;
    const ExerciseValue* b = i < want.items.size() ? &want.items[i] : nullptr;
    ValueRow row;
    // One template per item word ("number {number}", "point {number}", "list {number}", "value {number}"): the word
    // is not a fragment of a translated text.
    const std::string what = std::string(item_word(b ? *b : *a)) + " {number}";
    row.what = tr_format(what.c_str(), {{"number", std::to_string(i + 1)}});
    row.mine = run.mine ? (a ? value_text(*a) : tr("(none)")) : "";
    row.reference = b ? value_text(*b) : tr("(none)");
    row.differs = run.mine && (!a || !b || differs(*a, *b));
    rows.push_back(std::move(row));
  }
  return rows;
}

std::vector<std::string> value_input_lines(const ExerciseRun& run) {
  std::vector<std::string> lines;
  const std::shared_ptr<const ScriptedExercise> scripted = run.exercise.definition();
  if (!scripted || !scripted->takes_values()) return lines;
  const ExerciseInput& input = run.input;
  if (scripted->input() == ScriptedExercise::Input::Patch) {
    for (size_t row = 0; row < 4; ++row) {
      std::string line = tr_format("row {row}:", {{"row", std::to_string(row)}});
      for (size_t col = 0; col < 4; ++col) line += " " + format_position(input.patch.points[4 * row + col]);
      lines.push_back(std::move(line));
    }
  } else {
    for (size_t i = 0; i < input.points.size() && i < kMaxValueRows; ++i) {
      lines.push_back("P" + std::to_string(i) + " " + format_position(input.points[i]));
    }
  }
  if (!input.args.empty()) {
    std::string line = "args:";
    for (size_t i = 0; i < input.args.size(); ++i) line += (i == 0 ? " " : ", ") + value_text(input.args[i]);
    lines.push_back(std::move(line));
  }
  return lines;
}

void draw_value_fixture_chooser(ExerciseSession& session) {
  const std::shared_ptr<const ScriptedExercise> scripted = session.exercise().definition();
  if (!scripted || !scripted->takes_values()) return;
  const std::vector<ScriptedFixture>& fixtures = scripted->fixtures();
  if (fixtures.empty()) {
    ImGui::TextDisabled("%s", tr("this exercise has no fixtures to run on"));
    return;
  }
  const size_t current = std::min(session.fixture(), fixtures.size() - 1);
  const std::string shown = session.has_values_input() ? tr("the lesson's input") : fixtures[current].name;
  ImGui::SetNextItemWidth(320);
  if (ImGui::BeginCombo(tr_label("input"), shown.c_str())) {
    for (size_t i = 0; i < fixtures.size(); ++i) {
      const std::string label = fixtures[i].name + "##f" + std::to_string(i);
      if (ImGui::Selectable(label.c_str(), !session.has_values_input() && i == current)) session.set_fixture(i);
    }
    ImGui::EndCombo();
  }
}

void draw_value_tables(const ExerciseRun& run, const std::vector<ValueRow>& rows) {
  if (ImGui::CollapsingHeader(tr_label("input"), ImGuiTreeNodeFlags_DefaultOpen)) {
    for (const std::string& line : value_input_lines(run)) ImGui::TextUnformatted(line.c_str());
  }
  if (rows.empty()) return;
  if (!ImGui::CollapsingHeader(tr_label("returned, mine vs reference"), ImGuiTreeNodeFlags_DefaultOpen)) return;
  const ImGuiTableFlags flags = ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY;
  if (!ImGui::BeginTable("values", 3, flags, ImVec2(0, 220))) return;
  ImGui::TableSetupScrollFreeze(0, 1);
  ImGui::TableSetupColumn(tr("item"));
  ImGui::TableSetupColumn(tr("mine"));
  ImGui::TableSetupColumn(tr("reference"));
  ImGui::TableHeadersRow();
  ImGuiListClipper clipper;
  clipper.Begin(int(rows.size()));
  while (clipper.Step()) {
    for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
      const ValueRow& row = rows[size_t(i)];
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(row.what.c_str());
      for (const std::string* value : {&row.mine, &row.reference}) {
        ImGui::TableNextColumn();
        if (row.differs) ImGui::TableSetBgColor(ImGuiTableBgTarget_CellBg, im_colour_u32(ui_palette().differing_cell));
        text_wrapped_at_spaces(*value);
      }
    }
  }
  ImGui::EndTable();
}

}  // namespace meshedit
