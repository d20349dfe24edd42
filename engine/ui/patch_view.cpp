// The patch view's overlay geometry (pure, in the theme's colours) and its ImGui panel; the state is
// patch_view_state.h's.
#include "ui/patch_view.h"

#include <algorithm>
#include <cstdio>
#include <iterator>
#include <span>
#include <utility>

#include <imgui.h>

#include "core/translation.h"
#include "core/value_format.h"
#include "document/bezier_mine.h"
#include "ui/flow_layout.h"
#include "ui/theme.h"

namespace meshedit {

namespace {

// Colours from the theme's palette (core/palette.h).
const Palette& palette() { return ui_palette(); }
glm::vec4 opaque(glm::vec3 rgb) { return glm::vec4(rgb, 1.0f); }
glm::vec4 column_level_colour(size_t k) {
  return opaque(palette().column_levels[(k - 1) % palette().column_levels.size()]);
}
// Your point: the mine colour when it is the reference's, the wrong colour when not, the error colour when your code
// failed.
glm::vec4 mine_colour(const PatchMinePoint& mine) {
  return opaque(!mine.error.empty() ? palette().error : mine.equal ? palette().mine : palette().wrong);
}
// P(u, v); once your point differs from it, it is the reference's answer and takes the reference colour.
glm::vec4 surface_point_colour(const PatchMinePoint* mine) {
  return opaque(mine && mine->ran && !mine->equal ? palette().reference : palette().final_point);
}

std::vector<glm::dvec3> sample_curve3(std::span<const glm::dvec3> points, int segments) {
  std::vector<glm::dvec3> samples;
  segments = std::max(segments, 1);
  samples.reserve(static_cast<size_t>(segments) + 1);
  for (int i = 0; i <= segments; ++i) samples.push_back(evaluate_curve(points, static_cast<double>(i) / segments));
  return samples;
}

PatchOverlayItem item(std::vector<glm::dvec3> points, glm::vec4 colour, float width, bool points_only, OverlayKind kind,
                      std::string label) {
  return PatchOverlayItem{std::move(points), colour, width, points_only, kind, std::move(label)};
}

}  // namespace

// ---- overlay geometry ------------------------------------------------------------------------------

std::vector<PatchOverlayItem> control_net_polylines(const BezierPatch& patch, glm::vec4 colour, float width,
                                                    const std::string& label_prefix) {
  std::vector<PatchOverlayItem> net;
  net.reserve(8);
  for (int r = 0; r < 4; ++r) {
    net.push_back(item({patch.at(r, 0), patch.at(r, 1), patch.at(r, 2), patch.at(r, 3)}, colour, width, false,
                       OverlayKind::ControlNet, label_prefix + "row " + std::to_string(r)));
  }
  for (int c = 0; c < 4; ++c) {
    net.push_back(item({patch.at(0, c), patch.at(1, c), patch.at(2, c), patch.at(3, c)}, colour, width, false,
                       OverlayKind::ControlNet, label_prefix + "column " + std::to_string(c)));
  }
  return net;
}

std::vector<PatchOverlayItem> build_probe_overlay(const BezierPatch& patch, double u, double v, int samples) {
  std::vector<PatchOverlayItem> items =
      control_net_polylines(patch, opaque(palette().probed_net), 2.0f, "control net ");
  for (int r = 0; r < 4; ++r) {
    const std::span<const glm::dvec3> row(patch.points.data() + ptrdiff_t(r) * 4, 4);
    items.push_back(item(sample_curve3(row, samples), opaque(palette().row_curve), 2.0f, false, OverlayKind::RowCurve,
                         "row curve " + std::to_string(r)));
  }
  const PatchEvaluation eval = evaluate_patch_steps(patch, u, v);
  const std::vector<glm::dvec3> row_points(eval.row_points.begin(), eval.row_points.end());
  items.push_back(item(row_points, opaque(palette().row_points), 9.0f, true, OverlayKind::RowPoints, "rows at u"));
  items.push_back(item(row_points, opaque(palette().column_polygon), 1.5f, false, OverlayKind::ColumnPolygon,
                       "column control polygon"));
  for (size_t k = 1; k + 1 < eval.column_levels.size(); ++k) {
    items.push_back(item(eval.column_levels[k], column_level_colour(k), 1.5f, false, OverlayKind::ColumnLevel,
                         "column level " + std::to_string(k) + " at v"));
  }
  items.push_back(item(sample_curve3(row_points, samples), opaque(palette().curve), 2.5f, false,
                       OverlayKind::ColumnCurve, "column curve"));
  items.push_back(item({evaluate_patch(patch, u, v)}, surface_point_colour(nullptr), 12.0f, true,
                       OverlayKind::SurfacePoint, "P(u, v)"));
  return items;
}

std::vector<PatchOverlayItem> patch_view_overlay(const PatchViewState& state, const PatchMinePoint* mine) {
  std::vector<PatchOverlayItem> items;
  const int count = static_cast<int>(state.patches.size());
  if (count == 0) return items;
  const int selected = std::clamp(state.selected_patch, 0, count - 1);
  if (state.show_control_net) {
    for (int p = 0; p < count; ++p) {
      if (p == selected && state.show_probe) continue;
      const bool bright = p == selected;
      auto net = control_net_polylines(state.patches[p], opaque(bright ? palette().probed_net : palette().net),
                                       bright ? 2.0f : 1.0f, "patch " + std::to_string(p) + " ");
      std::move(net.begin(), net.end(), std::back_inserter(items));
    }
  }
  if (state.show_probe) {
    auto probe = build_probe_overlay(state.patches[selected], state.u, state.v);
    for (PatchOverlayItem& probe_item : probe) {
      if (probe_item.kind == OverlayKind::SurfacePoint) probe_item.colour = surface_point_colour(mine);
    }
    std::move(probe.begin(), probe.end(), std::back_inserter(items));
    if (mine && mine->ran) {
      const glm::vec4 colour = mine_colour(*mine);
      if (!mine->equal) {
        items.push_back(
            item({mine->mine, mine->reference}, colour, 2.0f, false, OverlayKind::MinePoint, "yours to P(u, v)"));
      }
      // Smaller than P(u, v)'s dot, so a right answer shows as a dot of the mine colour inside P(u, v)'s.
      items.push_back(item({mine->mine}, colour, 8.0f, true, OverlayKind::MinePoint, "yours"));
    }
  }
  return items;
}

// ---- ImGui -----------------------------------------------------------------------------------------

namespace {

std::string format_points(std::span<const glm::dvec3> points) {
  std::string text;
  for (const glm::dvec3& p : points) {
    text += (text.empty() ? "(" : "  (") + format_fixed(p.x, 4) + ", " + format_fixed(p.y, 4) + ", " +
            format_fixed(p.z, 4) + ")";
  }
  return text;
}

void table_row(const std::string& step, std::span<const glm::dvec3> points, glm::vec4 colour) {
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  ImGui::TextColored(im_colour(colour), "%s", step.c_str());
  ImGui::TableNextColumn();
  text_wrapped_at_spaces(format_points(points));
}

void draw_evaluation_table(const PatchViewState& state, const PatchMinePoint* mine) {
  if (state.patches.empty()) return;
  const PatchEvaluation eval = evaluate_patch_steps(state.patches[state.selected_patch], state.u, state.v);
  const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_BordersOuter;
  if (!ImGui::BeginTable("separable evaluation", 2, flags)) return;
  ImGui::TableSetupColumn(tr("step"), ImGuiTableColumnFlags_WidthFixed);
  ImGui::TableSetupColumn(tr("points"), ImGuiTableColumnFlags_WidthStretch);
  ImGui::TableHeadersRow();
  for (int r = 0; r < 4; ++r) {
    table_row(tr_format("row {row} at u", {{"row", std::to_string(r)}}),
              std::span<const glm::dvec3>(&eval.row_points[r], 1), opaque(palette().row_points));
  }
  for (size_t k = 1; k + 1 < eval.column_levels.size(); ++k) {
    table_row(tr_format("column level {level} at v", {{"level", std::to_string(k)}}), eval.column_levels[k],
              column_level_colour(k));
  }
  table_row("P(u, v)", std::span<const glm::dvec3>(&eval.point, 1), surface_point_colour(mine));
  if (mine && mine->ran) {
    table_row(tr("yours"), std::span<const glm::dvec3>(&mine->mine, 1), mine_colour(*mine));
  }
  ImGui::EndTable();
}

// With the switch on: the verdict on your point (file:line for an error) and the checker's diagnosis.
void draw_mine_verdict(const PatchMinePoint& mine) {
  const glm::vec4 colour = mine_colour(mine);
  ImGui::PushStyleColor(ImGuiCol_Text, im_colour(colour));
  text_wrapped_at_spaces(tr_format("mine: {message}", {{"message", mine.message}}));
  if (!mine.equal) {
    for (const std::string& line : mine.details) text_wrapped_at_spaces("- " + line);
  }
  ImGui::PopStyleColor();
}

}  // namespace

void draw_patch_view_panel_contents(PatchViewState& state, BezierMine* mine) {
  const int count = static_cast<int>(state.patches.size());
  int resolution = state.resolution;
  if (ImGui::SliderInt(tr_label("resolution"), &resolution, 1, kMaxPatchViewResolution)) {
    set_resolution(state, resolution);
  }
  if (count > 0) {
    int selected = state.selected_patch;
    // The slider's printf format: its %d is the patch shown.
    const std::string format = tr_format("{patch} of {count}", {{"patch", "%d"}, {"count", std::to_string(count)}});
    if (ImGui::SliderInt(tr_label("patch"), &selected, 0, count - 1, format.c_str())) select_patch(state, selected);
  } else {
    ImGui::TextDisabled("%s", tr("no patches"));
  }
  double u = state.u;
  double v = state.v;
  const double zero = 0.0;
  const double one = 1.0;
  const bool u_changed = ImGui::SliderScalar("u", ImGuiDataType_Double, &u, &zero, &one, "%.4f");
  const bool v_changed = ImGui::SliderScalar("v", ImGuiDataType_Double, &v, &zero, &one, "%.4f");
  if (u_changed || v_changed) set_probe(state, u, v);
  ImGui::Checkbox(tr_label("control net"), &state.show_control_net);
  same_line_if_room(tr_label("surface"));
  ImGui::Checkbox(tr_label("surface"), &state.show_surface);
  same_line_if_room(tr_label("probe"));
  ImGui::Checkbox(tr_label("probe"), &state.show_probe);
  const PatchMinePoint* yours = nullptr;
  if (mine) {
    same_line_if_room(tr_label("mine (M)"));
    bool on = mine->patch_on();
    if (ImGui::Checkbox(tr_label("mine (M)"), &on)) mine->set_patch_on(on);
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip("%s", tr_format("the probe point from your evaluate in {file}, checked against the reference",
                                        {{"file", mine->patch_file().path().string()}})
                                  .c_str());
    }
    if (mine->patch_on() && count > 0) {
      select_patch(state, state.selected_patch);
      yours = &mine->patch_point(state.patches[state.selected_patch], state.u, state.v);
    }
  }

  update_tessellation(state);
  const PatchTessellation& cache = state.tessellation;
  text_wrapped_at_spaces(
      tr_format("{patches} patches -> {vertices} vertices, {triangles} triangles (built {builds} "
                "times)",
                {{"patches", std::to_string(count)},
                 {"vertices", std::to_string(cache.polygons.num_vertices())},
                 {"triangles", std::to_string(cache.polygons.num_faces())},
                 {"builds", std::to_string(cache.rebuilds)}}));
  if (!cache.error.empty()) ImGui::TextColored(im_colour(palette().error), "%s", cache.error.c_str());
  if (yours) draw_mine_verdict(*yours);  // above the table, so it shows without scrolling

  ImGui::Separator();
  text_wrapped_at_spaces(tr("Separable evaluation: each row at u, then the column through them at v"));
  draw_evaluation_table(state, yours);
}

void draw_patch_view_panel(PatchViewState& state, const char* title, BezierMine* mine) {
  if (ImGui::Begin(tr_label(title))) draw_patch_view_panel_contents(state, mine);
  ImGui::End();
  update_tessellation(state);  // a collapsed panel must not leave the surface stale
}

}  // namespace meshedit
