// DocumentRoom's Repairs tab (app/repair_marks.h): the summary, then one clickable row per change (its sentence, and
// the ids of its spots in the repaired mesh); a click selects the row's first spot. The spots are drawn over the mesh
// by the view (ViewRoom::draw_repair_spots).
#include <imgui.h>

#include <string>

#include "app/document_room.h"
#include "core/palette.h"
#include "core/translation.h"
#include "document/document_actions.h"
#include "ui/flow_layout.h"
#include "ui/theme.h"

namespace meshedit {
namespace {

// "v0 v5 f1", or what the row points at when it has no spot.
std::string spot_ids(const RepairSpots& spots) {
  std::string text;
  for (uint32_t v : spots.vertices) text += (text.empty() ? "" : " ") + format_id(VertexId(v));
  for (uint32_t f : spots.faces) text += (text.empty() ? "" : " ") + format_id(FaceId::face(f));
  return text.empty() ? std::string(tr("nothing left to show")) : text;
}

}  // namespace

bool DocumentRoom::repair_spots_current(bool mesh_shown) const {
  return mesh_shown && repairs_.current(doc_.generation, doc_.mesh.version());
}

bool DocumentRoom::click_repair_row(size_t row, bool mesh_shown) {
  std::string refused;
  ElementRef spot;
  if (row >= repairs_.rows.size()) {
    refused = tr_format("the Repairs tab has no change {number}", {{"number", std::to_string(row + 1)}});
  } else if (!repair_spots_current(mesh_shown)) {
    refused = tr("the repaired spots are gone: the mesh was edited or another one opened");
  } else if (!(spot = repairs_.first_spot(row)).valid()) {
    refused = tr("that change left nothing in the mesh to select");
  }
  if (refused.empty() && !select_element(doc_, selection_, spot)) {
    refused = tr_format("{id} is not live", {{"id", format_id(spot)}});
  }
  if (!refused.empty()) {
    set_message(doc_, Severity::Warning, std::move(refused));
    return false;
  }
  repair_row_clicked_ = row;
  return true;
}

void DocumentRoom::draw_repairs_tab(bool mesh_shown, Theme theme) {
  const bool current = repair_spots_current(mesh_shown);
  const Palette& palette = palette_for(theme);
  ImGui::TextWrapped("%s", repairs_.summary.c_str());
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextWrapped("%s", current ? tr("Click a change to select it; its spots are drawn in the last edit's colour.")
                                   : tr("The mesh was edited or another shown: the spots are no longer drawn."));
  ImGui::PopStyleColor();
  ImGui::Separator();
  const float line = ImGui::GetTextLineHeight();
  for (size_t i = 0; i < repairs_.rows.size(); ++i) {
    const std::string sentence = wrapped_at_spaces(repairs_.rows[i], ImGui::GetContentRegionAvail().x);
    const std::string ids = spot_ids(repairs_.spots[i]);
    const float height = ImGui::CalcTextSize(sentence.c_str()).y + line;
    const ImVec2 top = ImGui::GetCursorScreenPos();
    ImGui::PushID(int(i));
    ImGui::BeginDisabled(!current);
    if (ImGui::Selectable("##change", current && repair_row_clicked_ == i, ImGuiSelectableFlags_AllowItemOverlap,
                          ImVec2(0, height))) {
      click_repair_row(i, mesh_shown);
    }
    ImGui::EndDisabled();
    ImGui::PopID();
    const ImVec2 after = ImGui::GetCursorScreenPos();
    ImGui::SetCursorScreenPos(top);
    ImGui::TextUnformatted(sentence.c_str());
    ImGui::TextColored(im_colour(current ? palette.changed : palette.dead), "%s", ids.c_str());
    ImGui::SetCursorScreenPos(after);
    ImGui::Spacing();
  }
}

}  // namespace meshedit
