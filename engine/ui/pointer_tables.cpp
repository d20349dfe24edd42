// The pointer tables and the Changes (Before/After) view (see pointer_tables.h for the contracts).
#include "ui/pointer_tables.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>

#include <imgui_internal.h>
#include <imgui_stdlib.h>

#include "core/translation.h"
#include "core/value_format.h"

namespace meshedit {
namespace {

constexpr TableTab kTabs[kTableTabCount] = {TableTab::Vertices, TableTab::Halfedges,  TableTab::Edges,
                                            TableTab::Faces,    TableTab::Boundaries, TableTab::Changes};

int kind_slot(ElementKind kind) { return static_cast<int>(kind); }

const char* tab_title(TableTab tab) {
  switch (tab) {
    case TableTab::Vertices: return "vertices";
    case TableTab::Halfedges: return "halfedges";
    case TableTab::Edges: return "edges";
    case TableTab::Faces: return "faces";
    case TableTab::Boundaries: return "boundary loops";
    case TableTab::Changes: return "changes";
  }
  return "?";
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

}  // namespace

ElementKind table_kind(TableTab tab) {
  switch (tab) {
    case TableTab::Vertices: return ElementKind::Vertex;
    case TableTab::Halfedges: return ElementKind::Halfedge;
    case TableTab::Edges: return ElementKind::Edge;
    case TableTab::Faces: return ElementKind::Face;
    case TableTab::Boundaries: return ElementKind::Boundary;
    case TableTab::Changes: return ElementKind::Halfedge;
  }
  return ElementKind::Halfedge;
}

TableTab tab_for_kind(ElementKind kind) {
  switch (kind) {
    case ElementKind::Vertex: return TableTab::Vertices;
    case ElementKind::Halfedge: return TableTab::Halfedges;
    case ElementKind::Edge: return TableTab::Edges;
    case ElementKind::Face: return TableTab::Faces;
    case ElementKind::Boundary: return TableTab::Boundaries;
  }
  return TableTab::Halfedges;
}

OpResult<ElementRef> parse_table_filter(std::string_view text, TableTab current) {
  OpResult<ElementRef> result;
  const std::string_view t = trim(text);
  const auto refuse = [&](std::string why) {
    result.check = Check::no(std::move(why));
    return result;
  };
  const auto not_an_id = [&] {
    return refuse(tr_format("'{text}' is not an id: type h37, v5, e2, f0, b0 or a number", {{"text", std::string(t)}}));
  };
  if (t.empty()) return refuse(tr("type an id: h37, v5, e2, f0, b0, or a number for the open tab"));
  if (std::isdigit(static_cast<unsigned char>(t.front()))) {
    if (current == TableTab::Changes) return refuse(tr("a bare number needs a kind here: type h37, v5, e2, f0 or b0"));
    uint32_t index = 0;
    const auto [end, error] = std::from_chars(t.data(), t.data() + t.size(), index);
    if (error != std::errc() || end != t.data() + t.size() || index == kInvalidIndex) return not_an_id();
    result.value = ElementRef(table_kind(current), index);
    return result;
  }
  std::string lowered(t);
  lowered[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(lowered[0])));
  const std::optional<ElementRef> parsed = parse_element(lowered);
  if (!parsed) return not_an_id();
  result.value = *parsed;
  return result;
}

OpResult<ElementRef> resolve_table_filter(const HalfedgeMesh& mesh, std::string_view text, TableTab current) {
  OpResult<ElementRef> result = parse_table_filter(text, current);
  if (result && !in_range(mesh, result.value)) {
    result.check = Check::no(reference_problem(mesh, result.value));
    result.value = ElementRef();
  }
  return result;
}

void reveal_in_tables(TablesState& state, ElementRef element) {
  if (!element.valid()) return;
  state.scroll_to = element;
  state.open_tab_requested = true;
}

namespace {

struct TableContext {
  const MeshDocument& doc;
  Selection& selection;
  TablesState& state;
  bool clicked = false;  // a click in the tables changed the selection this frame
};

ElementRef row_ref(ElementKind kind, uint32_t index) { return ElementRef(kind, index); }

void mark_if_changed(const TableContext& c, ElementRef row, MeshField field) {
  if (c.doc.last.index.contains(row, field))
    ImGui::TableSetBgColor(ImGuiTableBgTarget_CellBg, ImGui::GetColorU32(ui_colors::changed_cell()));
}

// One reference cell: a link in a live row, stale grey text in a dead one.
void ref_cell(TableContext& c, ElementRef row, bool alive, MeshField field, ElementRef value) {
  ImGui::TableNextColumn();
  mark_if_changed(c, row, field);
  const std::string name = std::string("cell:") + field_name(field);
  if (!alive) {
    ImGui::TextUnformatted(format_id(value).c_str());
    return;
  }
  if (element_link(c.doc.mesh, value, c.selection, name.c_str(), c.state.probe)) {
    c.clicked = true;
    reveal_in_tables(c.state, value);  // following a pointer shows its row, as a selection made elsewhere would
  }
}

void draw_row(TableContext& c, ElementKind kind, uint32_t index, bool scroll_here) {
  const HalfedgeMesh& mesh = c.doc.mesh;
  const ElementRef row = row_ref(kind, index);
  const bool alive = mesh.alive(row);
  ++c.state.rows_drawn;
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  ImGui::PushID(static_cast<int>(index));
  mark_if_changed(c, row, MeshField::Alive);
  if (!alive) ImGui::PushStyleColor(ImGuiCol_Text, ui_colors::dead());
  const std::string label = alive ? format_id(row) : tr_format("{id} dead", {{"id", format_id(row)}});
  if (ImGui::Selectable(label.c_str(), c.selection.selected == row,
                        ImGuiSelectableFlags_SpanAllColumns | ImGuiSelectableFlags_AllowItemOverlap)) {
    c.selection.selected = row;
    c.clicked = true;
  }
  if (ImGui::IsItemHovered()) c.selection.hovered = row;
  if (c.state.probe) c.state.probe->record_last_item("row", row);
  if (scroll_here) ImGui::SetScrollHereY(0.5f);
  switch (kind) {
    case ElementKind::Halfedge: {
      const HalfedgeId h(index);
      ref_cell(c, row, alive, MeshField::Next, mesh.next(h));
      ref_cell(c, row, alive, MeshField::Twin, mesh.twin(h));
      ref_cell(c, row, alive, MeshField::Vertex, mesh.vertex(h));
      ref_cell(c, row, alive, MeshField::Edge, mesh.edge(h));
      ref_cell(c, row, alive, MeshField::Face, mesh.face(h));
      break;
    }
    case ElementKind::Vertex: {
      const VertexId v(index);
      ref_cell(c, row, alive, MeshField::Halfedge, mesh.halfedge(v));
      ImGui::TableNextColumn();
      mark_if_changed(c, row, MeshField::Position);
      ImGui::TextUnformatted(format_position(mesh.position(v)).c_str());
      break;
    }
    case ElementKind::Edge: ref_cell(c, row, alive, MeshField::Halfedge, mesh.halfedge(EdgeId(index))); break;
    case ElementKind::Face:
    case ElementKind::Boundary: ref_cell(c, row, alive, MeshField::Halfedge, mesh.halfedge(row.face_id())); break;
  }
  if (!alive) ImGui::PopStyleColor();
  ImGui::PopID();
}

void setup_columns(ElementKind kind) {
  ImGui::TableSetupScrollFreeze(0, 1);
  ImGui::TableSetupColumn("id");
  switch (kind) {
    case ElementKind::Halfedge:
      for (const char* name : {"next", "twin", "vertex", "edge", "face"}) ImGui::TableSetupColumn(name);
      break;
    case ElementKind::Vertex:
      ImGui::TableSetupColumn("halfedge");
      ImGui::TableSetupColumn("position");
      break;
    default: ImGui::TableSetupColumn("halfedge"); break;
  }
  ImGui::TableHeadersRow();
}

int column_count(ElementKind kind) { return kind == ElementKind::Halfedge ? 6 : kind == ElementKind::Vertex ? 3 : 2; }

// Moves the window of laid-out rows when the scroll enters its first or last quarter, so that the rows on screen
// end up in its middle (far from both ends: no back-and-forth). Called inside the table after its rows are drawn:
// the new start takes effect next frame, and the table's scroll offset moves by the same number of rows right
// now (ImGui's own offset, not a scroll request, which the next mouse-wheel event would overwrite), so next frame
// shows the same rows at the same place and the wheel goes on from there.
void slide_window(TablesState& state, int slot, uint32_t n, uint32_t rows) {
  ImGuiWindow* table_window = ImGui::GetCurrentWindow();
  if (state.row_height <= 0.0f || state.pending_start[slot] >= 0 || table_window->ScrollTarget.y != FLT_MAX) return;
  const int64_t start = state.window_start[slot];
  const float y = table_window->Scroll.y, y_max = table_window->ScrollMax.y;
  if (y_max <= 0.0f || (y > y_max * 0.25f && y < y_max * 0.75f)) return;
  const int64_t wanted = static_cast<int64_t>((y - y_max * 0.5f) / state.row_height);
  const int64_t shift = std::clamp<int64_t>(wanted, -start, int64_t(n) - int64_t(rows) - start);
  if (shift == 0) return;
  state.pending_start[slot] = start + shift;
  table_window->Scroll.y = std::max(0.0f, y - float(shift) * state.row_height);
}

void draw_kind_table(TableContext& c, ElementKind kind) {
  TablesState& state = c.state;
  const uint32_t n = c.doc.mesh.capacity(kind);
  if (n == 0) {
    ImGui::TextDisabled("%s", tr("none"));
    if (state.scroll_to.valid() && state.scroll_to.kind == kind) state.scroll_to = ElementRef();
    return;
  }
  const int slot = kind_slot(kind);
  const uint32_t rows = std::min(n, std::max<uint32_t>(state.window_rows, 1));
  uint32_t& start = state.window_start[slot];
  if (state.pending_start[slot] >= 0) {
    start = static_cast<uint32_t>(state.pending_start[slot]);
    state.pending_start[slot] = -1;
  }
  start = std::min(start, n - rows);

  int forced = -1;  // the row (window-relative) to scroll into view this frame
  if (state.scroll_to.valid() && state.scroll_to.kind == kind) {
    const uint32_t target = std::min(state.scroll_to.index, n - 1);
    if (target < start || target >= start + rows) start = std::min(target - std::min(target, rows / 2), n - rows);
    forced = static_cast<int>(target - start);
    state.scroll_to = ElementRef();
  }

  if (rows < n) {
    ImGui::TextDisabled("%s", tr_format("rows {first}..{last} of {count} (more load as you scroll; type an id above to "
                                        "jump)",
                                        {{"first", format_id(row_ref(kind, start))},
                                         {"last", format_id(row_ref(kind, start + rows - 1))},
                                         {"count", std::to_string(n)}})
                                  .c_str());
  }
  const ImGuiTableFlags flags = ImGuiTableFlags_ScrollY | ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV |
                                ImGuiTableFlags_Resizable | ImGuiTableFlags_SizingStretchSame;
  if (!ImGui::BeginTable(tab_title(tab_for_kind(kind)), column_count(kind), flags)) return;
  setup_columns(kind);

  // Once the row height is known it is passed in, so the clipper does not lay out row 0 every frame to measure
  // it; the pitch of the rows drawn is checked below, so a change of font or style is picked up a frame later.
  ImGuiListClipper clipper;
  clipper.Begin(static_cast<int>(rows), state.row_height > 0.0f ? state.row_height : -1.0f);
  if (forced >= 0) clipper.ForceDisplayRangeByIndices(forced, forced + 1);
  int first_row = -1, last_row = -1;
  float first_y = 0.0f, last_y = 0.0f;
  while (clipper.Step()) {
    for (int r = clipper.DisplayStart; r < clipper.DisplayEnd; ++r) {
      const float y = ImGui::GetCursorScreenPos().y;
      if (first_row < 0 || r < first_row) first_row = r, first_y = y;
      if (r > last_row) last_row = r, last_y = y;
      draw_row(c, kind, start + static_cast<uint32_t>(r), r == forced);
    }
  }
  if (state.row_height <= 0.0f && clipper.ItemsHeight > 0.0f) state.row_height = clipper.ItemsHeight;
  if (last_row > first_row + 1) {
    const float pitch = (last_y - first_y) / float(last_row - first_row);
    if (std::abs(pitch - state.row_height) > 0.5f) state.row_height = pitch;
  }
  if (rows < n && forced < 0) slide_window(state, slot, n, rows);
  ImGui::EndTable();
}

// A value of the Before/After view: a link when it names an element, plain text otherwise.
void change_value(TableContext& c, const std::string& value, const char* name) {
  ImGui::TableNextColumn();
  if (value != "-") {
    if (const std::optional<ElementRef> ref = parse_element(value)) {
      if (element_link(c.doc.mesh, *ref, c.selection, name, c.state.probe)) c.clicked = true;
      return;
    }
  }
  ImGui::TextUnformatted(value.c_str());
}

void draw_changes(TableContext& c) {
  const LastChange& last = c.doc.last;
  if (last.label.empty()) {
    ImGui::TextDisabled("%s", tr("no operation yet: flip, split, collapse or subdivide, and every changed field shows "
                                 "here"));
    return;
  }
  if (!last.recorded) {
    ImGui::TextUnformatted(tr_format("{operation}: changed, but not recorded (memory ran out saving the mesh before "
                                     "it)",
                                     {{"operation", last.label}})
                               .c_str());
    if (c.state.probe) c.state.probe->record_last_item("changes-not-recorded");
    return;
  }
  if (!last.listed) {
    const std::string most = std::to_string(c.doc.limits.max_listed_changes);
    ImGui::TextUnformatted(tr_format("{operation}: more than {count} fields changed, too many to list",
                                     {{"operation", last.label}, {"count", most}})
                               .c_str());
    return;
  }
  ImGui::TextUnformatted(tr_format("{operation}: {count} fields changed",
                                   {{"operation", last.label}, {"count", std::to_string(last.changes.size())}})
                             .c_str());
  const ImGuiTableFlags flags =
      ImGuiTableFlags_ScrollY | ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_Resizable;
  if (!ImGui::BeginTable("changes", 4, flags)) return;
  ImGui::TableSetupScrollFreeze(0, 1);
  for (const char* name : {"element", "field", "before", "after"}) ImGui::TableSetupColumn(tr(name));
  ImGui::TableHeadersRow();
  ImGuiListClipper clipper;
  clipper.Begin(static_cast<int>(std::min<size_t>(last.changes.size(), 0x7fffffff)));
  while (clipper.Step()) {
    for (int r = clipper.DisplayStart; r < clipper.DisplayEnd; ++r) {
      const FieldChange& change = last.changes[static_cast<size_t>(r)];
      ImGui::TableNextRow();
      ImGui::PushID(r);
      ImGui::TableNextColumn();
      if (element_link(c.doc.mesh, change.element, c.selection, "change-element", c.state.probe)) c.clicked = true;
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(change.field.c_str());
      change_value(c, change.before, "change-before");
      change_value(c, change.after, "change-after");
      ImGui::PopID();
    }
  }
  ImGui::EndTable();
}

// Short labels ("h 36", the prefix students know from the ids) so six tabs fit a narrow panel; the ### part keeps
// the tab's identity while its count changes.
std::string tab_label(const MeshDocument& doc, TableTab tab) {
  std::string label;
  if (tab == TableTab::Changes) {
    label = doc.last.listed && doc.last.recorded && !doc.last.label.empty()
                ? tr_format("changes {count}", {{"count", std::to_string(doc.last.changes.size())}})
                : std::string(tr("changes"));
  } else {
    const ElementKind kind = table_kind(tab);
    label = std::string(1, kind_prefix(kind)) + " " + std::to_string(doc.mesh.capacity(kind));
  }
  return label + "###" + tab_title(tab);
}

}  // namespace

bool draw_pointer_tables_contents(MeshDocument& doc, Selection& selection, TablesState& state) {
  const ElementRef before = selection.selected;
  state.rows_drawn = 0;
  if (selection.selected != state.seen_selection) reveal_in_tables(state, selection.selected);
  TableContext c{doc, selection, state};

  ImGui::SetNextItemWidth(std::min(ImGui::GetContentRegionAvail().x, 16.0f * ImGui::GetFontSize()));
  if (ImGui::InputTextWithHint("##filter", tr("go to: h37, v5, b0, or 37"), &state.filter)) {
    const OpResult<ElementRef> found = resolve_table_filter(doc.mesh, state.filter, state.active);
    state.filter_message = found || trim(state.filter).empty() ? std::string() : found.check.reason;
    if (found) {
      selection.selected = found.value;
      c.clicked = true;
      reveal_in_tables(state, found.value);
    }
  }
  if (state.probe) state.probe->record_last_item("filter");
  if (!state.filter_message.empty()) {
    ImGui::SameLine();
    ImGui::TextColored(ui_colors::broken(), "%s", state.filter_message.c_str());
  }

  // A tab to open: the kind of a selection to reveal, or `active` when it was set from outside.
  std::optional<TableTab> request;
  if (state.open_tab_requested && state.scroll_to.valid()) request = tab_for_kind(state.scroll_to.kind);
  else if (static_cast<int>(state.active) != state.shown_tab) request = state.active;
  if (ImGui::BeginTabBar("kinds")) {
    for (const TableTab tab : kTabs) {
      const ImGuiTabItemFlags flags = request && tab == *request ? ImGuiTabItemFlags_SetSelected : 0;
      const std::string label = tab_label(doc, tab);
      const bool visible = ImGui::BeginTabItem(label.c_str(), nullptr, flags);
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tr(tab_title(tab)));
      if (state.probe) state.probe->record_last_item(std::string("tab:") + tab_title(tab));
      if (!visible) continue;
      // ImGui switches tabs a frame after the request; until then the old tab is drawn and the request stays.
      state.shown_tab = static_cast<int>(tab);
      if (!request || tab == *request) {
        state.active = tab;
        state.open_tab_requested = false;
      }
      if (tab == TableTab::Changes) draw_changes(c);
      else draw_kind_table(c, table_kind(tab));
      ImGui::EndTabItem();
    }
    ImGui::EndTabBar();
  }
  state.seen_selection = selection.selected;
  return selection.selected != before;
}

bool draw_pointer_tables(MeshDocument& doc, Selection& selection, TablesState& state) {
  if (!state.open) return false;
  bool changed = false;
  default_window_size(ImVec2(560, 420));
  if (ImGui::Begin(tr_label("Pointer tables"), &state.open)) {
    changed = draw_pointer_tables_contents(doc, selection, state);
  }
  ImGui::End();
  return changed;
}

}  // namespace meshedit
