// The Exercises panel: see exercise_panel.h for the contract.
#include "ui/exercise_panel.h"

#include <algorithm>
#include <unordered_map>
#include <utility>

#include <imgui.h>

#include "core/history.h"
#include "core/translation.h"
#include "core/value_format.h"
#include "exercise/scripted_exercise.h"
#include "ui/flow_layout.h"
#include "ui/theme.h"
#include "ui/upsample_phase_view.h"

namespace meshedit {
namespace {

// Colours from the theme's palette (core/palette.h).
ImVec4 failed_colour() { return im_colour(ui_palette().error); }
ImVec4 passed_colour() { return im_colour(ui_palette().ok); }
ImVec4 hint_colour() { return im_colour(ui_palette().emphasis); }  // as the lesson panel's hints

void text(const std::string& line) { text_wrapped_at_spaces(line); }

void coloured(const ImVec4& colour, const std::string& line) {
  ImGui::PushStyleColor(ImGuiCol_Text, colour);
  text_wrapped_at_spaces(line);
  ImGui::PopStyleColor();
}

// One side's sentences, each whole: the side's name is not a fragment put before a translated rest.
struct OutcomeWords {
  const char* id;  // "yours" and "the reference" each have their own tree nodes
  const char* failed;
  const char* refused;
  const char* returned;
  const char* after_call;
  const char* problems;
};
constexpr OutcomeWords kYours{"yours",
                              "yours failed: {error}",
                              "yours refused: {reason}",
                              "yours returned {value}",
                              "yours after the call: {summary}",
                              "yours: {count} problems"};
constexpr OutcomeWords kTheReference{"the reference",
                                     "the reference failed: {error}",
                                     "the reference refused: {reason}",
                                     "the reference returned {value}",
                                     "the reference after the call: {summary}",
                                     "the reference: {count} problems"};

// `error_listed`: the outcome's error is already one of the differences shown above, so it is not said again.
void draw_outcome(const OutcomeWords& who, const ExerciseOutcome& outcome, bool show_validation,
                  bool error_listed = false) {
  ImGui::PushID(who.id);
  if (!outcome.error.empty()) {
    if (!error_listed) coloured(failed_colour(), tr_format(who.failed, {{"error", outcome.error}}));
  } else if (!outcome.refused.empty()) {
    text(tr_format(who.refused, {{"reason", outcome.refused}}));
  } else if (outcome.ran) {
    text(tr_format(who.returned, {{"value", outcome.returned}}));
  }
  if (show_validation && outcome.validation) {
    const ValidationReport& report = *outcome.validation;
    coloured(report.ok() ? passed_colour() : failed_colour(),
             tr_format(who.after_call, {{"summary", report.summary()}}));
    if (!report.ok() &&
        ImGui::TreeNode("problems", "%s", tr_format(who.problems, {{"count", std::to_string(report.total)}}).c_str())) {
      for (const Violation& violation : report.violations) text(violation.message);
      ImGui::TreePop();
    }
  }
  if (!outcome.output.empty() &&
      ImGui::TreeNode(
          "print", "%s",
          tr_format("print output ({count} lines)", {{"count", std::to_string(outcome.output.size())}}).c_str())) {
    for (const std::string& line : outcome.output) text(line);
    ImGui::TreePop();
  }
  ImGui::PopID();
}

constexpr size_t kDifferencesShown = 3;  // a report's first differences, always shown

void draw_report(const ExerciseRun& run) {
  const ExerciseReport& report = run.report;
  text(run.label + "  (" + run.input.describe(run.exercise) + ")");
  if (!run.mine) {
    draw_outcome(kTheReference, report.reference, false);
    return;
  }
  if (report.identical) {
    coloured(passed_colour(), tr("identical to the reference (pointer for pointer)"));
  } else if (report.equal) {
    coloured(passed_colour(), tr("equal to the reference (up to renumbering and rounding)"));
  } else {
    const size_t n = report.total_differences;
    coloured(failed_colour(), tr_format(n == 1 ? "different from the reference: {count} difference"
                                               : "different from the reference: {count} differences, the likely "
                                                 "mistake first",
                                        {{"count", std::to_string(n)}}));
  }
  // The likely mistakes are the first differences: those are shown, the rest fold away so that the tables and the
  // replay below stay in reach.
  const size_t shown = std::min(report.differences.size(), kDifferencesShown);
  for (size_t i = 0; i < shown; ++i) coloured(failed_colour(), "- " + report.differences[i]);
  const size_t more = report.total_differences - std::min(report.total_differences, shown);
  if (more > 0 && ImGui::TreeNode("differences", "%s",
                                  tr_format(more == 1 ? "{count} more difference" : "{count} more differences",
                                            {{"count", std::to_string(more)}})
                                      .c_str())) {
    for (size_t i = shown; i < report.differences.size(); ++i) coloured(failed_colour(), "- " + report.differences[i]);
    if (report.total_differences > report.differences.size()) {
      text(tr_format("... and {count} more",
                     {{"count", std::to_string(report.total_differences - report.differences.size())}}));
    }
    ImGui::TreePop();
  }
  if (!report.equal) {  // an instructor's exercise brings its own hint
    if (const std::shared_ptr<const ScriptedExercise> scripted = run.exercise.definition();
        scripted && !scripted->hint().empty()) {
      ImGui::PushStyleColor(ImGuiCol_Text, hint_colour());
      text(tr_format("Hint: {hint}", {{"hint", scripted->hint()}}));
      ImGui::PopStyleColor();
    }
  }
  if (!report.notes.empty() &&
      ImGui::TreeNode("notes", "%s",
                      tr_format("notes ({count})", {{"count", std::to_string(report.notes.size())}}).c_str())) {
    for (const std::string& line : report.notes) text("- " + line);
    ImGui::TreePop();
  }
  bool error_listed = false;  // a run that failed says its error once, among the differences shown
  for (size_t i = 0; i < shown; ++i) error_listed = error_listed || report.differences[i] == report.mine.error;
  draw_outcome(kYours, report.mine, true, !report.mine.error.empty() && error_listed);
  draw_outcome(kTheReference, report.reference, false);
}

void draw_pointer_table(const std::vector<PointerRow>& rows) {
  if (rows.empty()) return;
  const size_t differing =
      size_t(std::count_if(rows.begin(), rows.end(), [](const PointerRow& r) { return r.differs(); }));
  if (!ImGui::CollapsingHeader(tr_label("changed pointers, mine vs reference"), ImGuiTreeNodeFlags_DefaultOpen)) return;
  text(tr_format("{count} fields changed, {differing} differ",
                 {{"count", std::to_string(rows.size())}, {"differing", std::to_string(differing)}}));
  const ImGuiTableFlags flags = ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY;
  if (!ImGui::BeginTable("pointers", 4, flags, ImVec2(0, 220))) return;
  ImGui::TableSetupScrollFreeze(0, 1);
  ImGui::TableSetupColumn(tr("field"));
  ImGui::TableSetupColumn(tr("before"));
  ImGui::TableSetupColumn(tr("mine"));
  ImGui::TableSetupColumn(tr("reference"));
  ImGui::TableHeadersRow();
  ImGuiListClipper clipper;
  clipper.Begin(int(rows.size()));
  while (clipper.Step()) {
    for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
      const PointerRow& row = rows[size_t(i)];
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      text(format_id(row.element) + "." + row.field);
      ImGui::TableNextColumn();
      text(row.before);
      for (const std::string* value : {&row.mine, &row.reference}) {
        ImGui::TableNextColumn();
        if (row.differs()) {
          ImGui::TableSetBgColor(ImGuiTableBgTarget_CellBg, im_colour_u32(ui_palette().differing_cell));
        }
        text(*value);
      }
    }
  }
  ImGui::EndTable();
}

void draw_replay(ExerciseSession& session, ExercisePanelState& state, MeshDocument& doc) {
  const size_t n = session.replay_length();
  if (n == 0) return;
  if (!ImGui::CollapsingHeader(tr_label("replay your writes"), ImGuiTreeNodeFlags_DefaultOpen)) return;
  const bool replaying = session.replaying();
  if (!replaying) {
    ImGui::BeginDisabled(!session.can_replay(doc));
    if (ImGui::Button(tr_label("Replay"))) session.start_replay(doc);
    ImGui::EndDisabled();
    ImGui::SameLine();
    text(tr_format("{count} writes recorded", {{"count", std::to_string(n)}}));
  } else {
    const size_t k = session.replay_position();
    if (ImGui::Button("|<")) session.replay_step(doc, 0);
    ImGui::SameLine();
    if (ImGui::Button("<")) session.replay_step(doc, k == 0 ? 0 : k - 1);
    ImGui::SameLine();
    if (ImGui::Button(">")) session.replay_step(doc, k + 1);
    ImGui::SameLine();
    if (ImGui::Button(">|")) session.replay_step(doc, n);
    ImGui::SameLine();
    if (ImGui::Button(tr_label("Done"))) session.finish_replay(doc);
    int slider = int(session.replay_position());
    ImGui::SetNextItemWidth(-1);
    // The slider's printf format: its %d is the position.
    const std::string format =
        tr_format("write {position}/{count}", {{"position", "%d"}, {"count", std::to_string(n)}});
    if (ImGui::SliderInt("##k", &slider, 0, int(n), format.c_str())) {
      session.replay_step(doc, size_t(std::max(slider, 0)));
    }
  }
  draw_upsample_phases(session, state, doc);
  const std::vector<RecordedEdit>& edits = session.edits();
  const size_t current = session.replaying() ? session.replay_position() : 0;
  state.writes_drawn = 0;
  ImGui::BeginChild("writes", ImVec2(0, 180), true);
  ImGuiListClipper clipper;
  clipper.Begin(int(edits.size()));
  while (clipper.Step()) {
    for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
      const RecordedEdit& edit = edits[size_t(i)];
      // An upsample's writes say their phase: "[2] 5. split e4 -> v12".
      const std::string phase =
          state.phases ? "[" + std::to_string(int(state.phases->phase_at(size_t(i) + 1))) + "] " : std::string();
      const std::string line =
          phase + std::to_string(i + 1) + ". " + describe(edit) + (edit.where.empty() ? "" : "   " + edit.where);
      const bool is_current = session.replaying() && size_t(i) + 1 == current;
      const bool done = session.replaying() && size_t(i) + 1 < current;
      const ImVec4 colour = is_current ? im_colour(ui_palette().emphasis)
                            : done     ? ImGui::GetStyleColorVec4(ImGuiCol_Text)
                                       : im_colour(ui_palette().dead);
      ImGui::PushStyleColor(ImGuiCol_Text, colour);
      if (ImGui::Selectable((line + "##w" + std::to_string(i)).c_str(), is_current) && session.replaying()) {
        session.replay_step(doc, size_t(i) + 1);
      }
      ImGui::PopStyleColor();
      ++state.writes_drawn;
    }
  }
  if (state.follow_replay && session.replaying() && current > 0) {
    const float row = ImGui::GetTextLineHeightWithSpacing();
    const float y = row * float(current - 1);
    if (y < ImGui::GetScrollY() || y > ImGui::GetScrollY() + ImGui::GetWindowHeight() - 2 * row) {
      ImGui::SetScrollY(y - ImGui::GetWindowHeight() * 0.5f);
    }
  }
  ImGui::EndChild();
}

}  // namespace

std::vector<PointerRow> pointer_rows(const ExerciseRun& run, size_t max_rows) {
  std::vector<PointerRow> rows;
  const HalfedgeMesh* before = run.input.mesh.get();
  const HalfedgeMesh* mine = run.report.mine.mesh.get();
  const HalfedgeMesh* reference = run.report.reference.mesh.get();
  if (!run.mine || !before || !mine || !reference) return rows;
  std::unordered_map<std::string, size_t> index;
  auto key = [](const FieldChange& c) { return format_id(c.element) + "." + c.field; };
  const std::vector<FieldChange> mine_changes = diff(*before, *mine);
  const std::vector<FieldChange> reference_changes = diff(*before, *reference);
  // Fields of an element both deleted say nothing (the dead elements' fields are left as they were).
  const auto dead_in_both = [&](const FieldChange& c) {
    return !mine->alive(c.element) && !reference->alive(c.element);
  };
  for (const FieldChange& change : mine_changes) {
    if (rows.size() >= max_rows) break;
    if (dead_in_both(change)) continue;
    index.emplace(key(change), rows.size());
    rows.push_back({change.element, change.field, change.before, change.after, change.before});
  }
  for (const FieldChange& change : reference_changes) {
    if (dead_in_both(change)) continue;
    const auto found = index.find(key(change));
    if (found != index.end()) {
      rows[found->second].reference = change.after;
    } else if (rows.size() < max_rows) {
      // Only the reference changed it: mine still holds the value from before.
      rows.push_back({change.element, change.field, change.before, change.before, change.after});
    }
  }
  // The rows that differ first: they are what the student is looking for.
  std::stable_partition(rows.begin(), rows.end(), [](const PointerRow& row) { return row.differs(); });
  return rows;
}

void draw_exercise_panel(ExerciseSession& session, ExercisePanelState& state, MeshDocument& doc, Selection& selection) {
  session.sync(doc);
  if (!state.open) return;
  ImGui::SetNextWindowSize(ImVec2(520, 640), ImGuiCond_FirstUseEver);
  if (ImGui::Begin(tr_label("Exercises"), &state.open)) draw_exercise_panel_contents(session, state, doc, selection);
  ImGui::End();
}

void draw_exercise_panel_contents(ExerciseSession& session, ExercisePanelState& state, MeshDocument& doc,
                                  Selection& selection) {
  session.sync(doc);
  ImGui::PushTextWrapPos(0.0f);  // the panel is a column: its lines wrap at its edge
  const ExerciseInfo& active = exercise_info(session.exercise());
  ImGui::SetNextItemWidth(220);
  if (ImGui::BeginCombo(tr_label("exercise"), tr(active.title))) {
    for (const Exercise exercise : mesh_exercises()) {
      const ExerciseInfo& info = exercise_info(exercise);
      if (ImGui::Selectable(tr_label(info.title), exercise == session.exercise())) session.set_exercise(exercise);
    }
    ImGui::EndCombo();
  }
  draw_value_fixture_chooser(session);
  text(session.file().string());
  ImGui::TextDisabled("%s", active.signature);
  if (!session.last_run()) {
    ImGui::TextDisabled("%s",
                        tr("parts 1 and 2 (curve.lua, patch.lua): the mine box (M) of the curve and patch views"));
  }
  if (session.running()) {
    // The student's code runs on its own thread: the window goes on drawing, and Stop ends the code at its next line.
    const bool stop = ImGui::Button(tr_label("Stop"));
    const ImVec2 low = ImGui::GetItemRectMin(), high = ImGui::GetItemRectMax();
    state.run_mine_x = 0.5f * (low.x + high.x);
    state.run_mine_y = 0.5f * (low.y + high.y);
    if (stop) session.stop_running();
    ImGui::SameLine();
    // The time first, and wrapped: the label can be longer than a narrow panel.
    ImGui::TextWrapped(
        "%s", tr_format("running your code ({seconds} s): {what}",
                        {{"seconds", format_fixed(session.running_seconds(), 1)}, {"what", session.running_label()}})
                  .c_str());
  } else {
    const bool run_mine = ImGui::Button(tr_label("Run mine"));
    const ImVec2 low = ImGui::GetItemRectMin(), high = ImGui::GetItemRectMax();
    state.run_mine_x = 0.5f * (low.x + high.x);
    state.run_mine_y = 0.5f * (low.y + high.y);
    if (run_mine) session.start_mine(doc, selection);
    ImGui::SameLine();
    if (ImGui::Button(tr_label("Run reference"))) session.run_reference(doc, selection);
  }
  if (session.loads() > 0 && session.file_changed()) {  // two stat calls a frame
    ImGui::SameLine();
    ImGui::TextDisabled("%s", tr("(saved since the last run: reloads on the next)"));
  }
  if (!session.load_error().empty()) coloured(failed_colour(), session.load_error());
  ImGui::Separator();

  const std::optional<ExerciseRun>& run = session.last_run();
  if (run) {
    draw_report(*run);
    if (run->serial != state.rows_serial) {
      state.rows =
          (run->exercise == Exercise::FlipEdge || run->exercise == Exercise::SplitEdge || run->exercise.definition())
              ? pointer_rows(*run, ExercisePanelState::kMaxPointerRows)
              : std::vector<PointerRow>{};
      state.value_rows = value_rows(*run);
      state.rows_serial = run->serial;
    }
    update_upsample_phases(*run, state);
    if (!is_mesh_exercise(run->exercise)) draw_value_tables(*run, state.value_rows);
    draw_pointer_table(state.rows);
    if (std::exchange(state.bring_table_into_view, false) &&
        ImGui::GetCursorScreenPos().y > ImGui::GetWindowPos().y + ImGui::GetWindowHeight()) {
      ImGui::SetScrollHereY(1.0f);
    }
    if (run->mine) draw_replay(session, state, doc);
  } else if (session.load_error().empty() && !session.running()) {
    ImGui::TextDisabled("%s", tr(is_mesh_exercise(session.exercise()) ? "select an element and press Run mine"
                                                                      : "choose an input and press Run mine"));
  }
  ImGui::PopTextWrapPos();
}

}  // namespace meshedit
