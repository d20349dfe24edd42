// The phases of a student's upsample in the Exercises tab (see upsample_phase_view.h for the contract).
#include "ui/upsample_phase_view.h"

#include <exception>
#include <string>

#include <imgui.h>

#include "core/translation.h"
#include "core/value_format.h"
#include "ui/flow_layout.h"
#include "ui/theme.h"

namespace meshedit {
namespace {

void text(const std::string& line) { text_wrapped_at_spaces(line); }

void coloured(const ImVec4& colour, const std::string& line) {
  ImGui::PushStyleColor(ImGuiCol_Text, colour);
  ImGui::TextWrapped("%s", line.c_str());
  ImGui::PopStyleColor();
}

std::string counts_text(const MeshCounts& c) {
  return std::to_string(c.vertices) + " / " + std::to_string(c.edges) + " / " + std::to_string(c.faces);
}

// Shows replay position k, starting the replay when none runs.
void jump(ExerciseSession& session, MeshDocument& doc, size_t k) {
  if (!session.replaying() && !session.start_replay(doc)) return;
  session.replay_step(doc, k);
}

// upsample_phase_title in the window's language: "phase 3 (new edges flipped)".
std::string phase_title(UpsamplePhase phase) {
  if (phase == UpsamplePhase::Other) return tr(upsample_phase_name(phase));
  return tr_format("phase {number} ({name})",
                   {{"number", std::to_string(int(phase))}, {"name", tr(upsample_phase_name(phase))}});
}

// "writes 19..30", or "writes 2..40 (12 of them)" when other phases' writes come between.
std::string writes_text(const UpsamplePhases& phases, int p) {
  if (p == 1) return tr("writes none (your Lua tables)");
  const UpsamplePhaseSpan& span = phases.span[size_t(p)];
  if (!span.started) return tr("writes never started");
  const MessageParts parts = {{"first", std::to_string(span.first + 1)},
                              {"last", std::to_string(span.last + 1)},
                              {"count", std::to_string(span.writes)}};
  return tr_format(
      span.last - span.first + 1 != span.writes ? "writes {first}..{last} ({count} of them)" : "writes {first}..{last}",
      parts);
}

// "identical", "same shape, other ids", "12 positions, 30 halfedges differ": a template for each pair of counts'
// numbers (one, many), so the English reads as plural() wrote it.
std::string verdict_text(const UpsamplePhaseState& s, bool& good) {
  good = s.identical() || s.same_shape;
  if (s.identical()) return tr("identical");
  if (s.same_shape) return tr("same shape, other ids");
  const bool one_position = s.positions_differ == 1, one_halfedge = s.halfedges_differ == 1;
  const char* differ = one_position ? (one_halfedge ? "{positions} position, {halfedges} halfedge differs"
                                                    : "{positions} position, {halfedges} halfedges differ")
                                    : (one_halfedge ? "{positions} positions, {halfedges} halfedge differs"
                                                    : "{positions} positions, {halfedges} halfedges differ");
  std::string out = tr_format(
      differ, {{"positions", std::to_string(s.positions_differ)}, {"halfedges", std::to_string(s.halfedges_differ)}});
  if (!(s.mine == s.reference)) out = tr_format("other counts; {differences}", {{"differences", out}});
  return out;
}

void draw_table(ExerciseSession& session, const ExercisePanelState& state, MeshDocument& doc, UpsamplePhase current) {
  const UpsamplePhases& phases = *state.phases;
  const ImGuiTableFlags flags = ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp;
  if (!ImGui::BeginTable("phases", 4, flags)) return;
  ImGui::TableSetupColumn(tr("phase"), ImGuiTableColumnFlags_WidthStretch, 2.0f);
  ImGui::TableSetupColumn(tr("yours"), ImGuiTableColumnFlags_WidthStretch, 1.0f);
  ImGui::TableSetupColumn(tr("reference"), ImGuiTableColumnFlags_WidthStretch, 1.0f);
  ImGui::TableSetupColumn(tr("vs reference"), ImGuiTableColumnFlags_WidthStretch, 1.4f);
  ImGui::TableHeadersRow();
  for (int p = 1; p <= kUpsamplePhaseCount; ++p) {
    const UpsamplePhase phase = UpsamplePhase(p);
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    const std::optional<size_t> start = phases.start_position(phase);
    // The row of the write shown is lit whole, however many lines its cells wrap to; a click on it jumps there.
    if (session.replaying() && phase == current) {
      ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg0, ImGui::GetColorU32(ImGuiCol_Header));
    }
    const std::string number = std::to_string(p) + "##phase" + std::to_string(p);
    if (ImGui::Selectable(number.c_str(), false, ImGuiSelectableFlags_SpanAllColumns) && start) {
      jump(session, doc, *start);
    }
    ImGui::SameLine();
    text(tr(upsample_phase_name(phase)));
    ImGui::TextDisabled("%s", writes_text(phases, p).c_str());
    if (!state.phase_states) continue;
    const UpsamplePhaseState& s = state.phase_states->at[size_t(p)];
    ImGui::TableNextColumn();
    text(counts_text(s.mine));
    ImGui::TableNextColumn();
    if (!state.phase_states->refused.empty()) {
      text("-");
      continue;
    }
    text(counts_text(s.reference));
    ImGui::TableNextColumn();
    bool good = false;
    const std::string verdict = verdict_text(s, good);
    coloured(im_colour(good ? ui_palette().ok : ui_palette().error), verdict);
  }
  ImGui::EndTable();
}

}  // namespace

void update_upsample_phases(const ExerciseRun& run, ExercisePanelState& state) {
  if (run.serial == state.phases_serial) return;
  state.phases_serial = run.serial;
  state.phases.reset();
  state.phase_states.reset();
  state.phases_error.clear();
  if (!run.mine || run.exercise != Exercise::Upsample || run.report.mine.edits.empty() || !run.input.mesh) return;
  try {
    state.phases = find_upsample_phases(run.report.mine.edits);
    state.phase_states = upsample_phase_states(*run.input.mesh, run.report.mine.edits, *state.phases);
  } catch (const std::exception& e) {
    state.phase_states.reset();
    try {
      state.phases_error = tr_format("the phases' meshes could not be made: {error}", {{"error", e.what()}});
    } catch (const std::exception&) {  // memory ran out: no table, no sentence
    }
  }
}

void draw_upsample_phases(ExerciseSession& session, ExercisePanelState& state, MeshDocument& doc) {
  if (!state.phases) return;
  const UpsamplePhases& phases = *state.phases;
  const bool replaying = session.replaying();
  const size_t n = session.replay_length();
  const size_t k = replaying ? session.replay_position() : 0;
  const std::optional<size_t> previous = replaying ? phases.previous_phase_position(k) : std::nullopt;
  const std::optional<size_t> next = replaying ? phases.next_phase_position(k) : std::optional<size_t>(0);
  const bool can = session.can_replay(doc);
  ImGui::BeginDisabled(!can || !previous);
  if (ImGui::Button(tr_label("< previous phase")) && previous) jump(session, doc, *previous);
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(!can || !next);
  const bool pressed = ImGui::Button(tr_label(replaying ? "next phase >" : "replay by phase >"));
  const ImVec2 low = ImGui::GetItemRectMin(), high = ImGui::GetItemRectMax();
  state.next_phase_x = 0.5f * (low.x + high.x);
  state.next_phase_y = 0.5f * (low.y + high.y);
  if (pressed && next) jump(session, doc, *next);
  ImGui::EndDisabled();
  const UpsamplePhase current = phases.phase_at(k);
  if (!replaying) {
    text(tr_format("yours after all {count} writes", {{"count", std::to_string(n)}}));
  } else if (k == 0) {
    text(tr_format("before the first write: {phase}; your positions are in Lua tables, the mesh is unchanged",
                   {{"phase", phase_title(UpsamplePhase::Compute)}}));
  } else {
    coloured(
        im_colour(ui_palette().emphasis),
        tr_format("write {position}/{count} is in {phase}",
                  {{"position", std::to_string(k)}, {"count", std::to_string(n)}, {"phase", phase_title(current)}}));
  }
  draw_table(session, state, doc, current);
  ImGui::TextDisabled(
      "%s", tr("V/E/F: vertices, edges, faces when the phase is done; positions and halfedges are compared by id"));
  for (const std::string& problem : phases.problems) coloured(im_colour(ui_palette().error), "- " + problem);
  if (!state.phases_error.empty()) coloured(im_colour(ui_palette().error), state.phases_error);
}

}  // namespace meshedit
