// The pointer tables: one tab per element kind with every stored field (`h37: next h12, twin h38, vertex v5,
// edge e18, face f6`), and a Changes tab listing what the last operation changed (element, field, before, after), or
// saying that it was not recorded (LastChange::recorded: memory ran out saving the state before it).
//
// Invariants:
// - Only the rows on screen read the mesh (ImGuiListClipper): a frame costs O(visible rows), whatever the size.
//   TablesState::rows_drawn counts the rows read in the last frame.
// - ImGui positions rows with floats, which stop being exact past ~2^24 pixels (about a million rows). So a
//   tab lays out at most TablesState::window_rows rows at a time, a sliding window over the ids that moves
//   (between frames, together with the scroll position, so nothing jumps) when the scroll nears its ends.
// - Changed cells are looked up in the document's ChangeIndex (built once per change): O(1) per visible cell.
// - References are links (element_link): dead, missing or null ones are red and never followed.
// - When the selection changes elsewhere (the mesh view, the inspector, a key) or a reference cell is clicked, the
//   tab of its kind opens and its row scrolls into view; clicking a row, or a link in the Changes tab, does not
//   scroll or switch tabs.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "core/check.h"
#include "core/halfedge_mesh.h"
#include "document/mesh_document.h"
#include "document/selection.h"
#include "ui/element_link.h"

namespace meshedit {

enum class TableTab { Vertices, Halfedges, Edges, Faces, Boundaries, Changes };
inline constexpr int kTableTabCount = 6;
ElementKind table_kind(TableTab tab);  // the kind a tab lists (Changes: Halfedge, unused)
TableTab tab_for_kind(ElementKind kind);

// The filter box: "h37" (any kind, by its prefix; case-insensitive), "37" (the current tab's kind), with
// surrounding spaces ignored. Refused with a sentence for anything else, or for a bare number on the Changes
// tab. Says nothing about whether the element exists: see resolve_table_filter.
OpResult<ElementRef> parse_table_filter(std::string_view text, TableTab current);
// parse_table_filter, then refused when the element does not exist in `mesh` (dead elements are accepted:
// their rows are shown greyed).
OpResult<ElementRef> resolve_table_filter(const HalfedgeMesh& mesh, std::string_view text, TableTab current);

struct TablesState {
  bool open = true;
  TableTab active = TableTab::Halfedges;
  std::string filter;             // the filter box's text
  std::string filter_message;     // why the filter text was refused ("" when it was not)
  uint32_t window_rows = 100000;  // rows laid out at a time per tab (see the header comment)
  UiProbe* probe = nullptr;       // tests: where rows and links were drawn

  // Read after a frame (tests, benchmarks).
  size_t rows_drawn = 0;    // rows whose fields were read in the last frame
  float row_height = 0.0f;  // measured by the clipper

  // Internal bookkeeping, kept between frames.
  ElementRef seen_selection;  // the selection at the end of the last frame
  int shown_tab = -1;         // the tab drawn last frame; when `active` differs, that tab is opened
  ElementRef scroll_to;       // a row to bring into view on its tab's next frame
  bool open_tab_requested = false;
  std::array<uint32_t, kElementKindCount> window_start{};  // first id laid out, per kind
  // Window moves applied on the next frame, per kind; -1 for none.
  std::array<int64_t, kElementKindCount> pending_start = [] {
    std::array<int64_t, kElementKindCount> none;
    none.fill(-1);
    return none;
  }();
};

// Draws the "Pointer tables" window (nothing when state.open is false). Clicks select; returns true when the
// selection changed.
bool draw_pointer_tables(MeshDocument& doc, Selection& selection, TablesState& state);
bool draw_pointer_tables_contents(MeshDocument& doc, Selection& selection, TablesState& state);

// Asks the tables to open `element`'s tab and scroll its row into view on the next frame (the filter and
// selection changes made elsewhere do this themselves).
void reveal_in_tables(TablesState& state, ElementRef element);

}  // namespace meshedit
