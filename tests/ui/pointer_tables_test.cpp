// The pointer tables: the filter parser, clicking rows and cells, revealing a selection made elsewhere, the
// Changes view (and what it says of a change memory ran out to record), and a million-triangle torus drawn by visible
// rows only (rows counted, not timed).
#include <algorithm>

#include <gtest/gtest.h>

#include "core/mesh_ops.h"
#include "document/document_actions.h"
#include "support/failing_snapshots.h"
#include "ui/pointer_tables.h"
#include "ui_test_support.h"

namespace meshedit {
namespace {

using namespace ui_testing;
using namespace document_testing;

std::string parsed(std::string_view text, TableTab tab) {
  const OpResult<ElementRef> r = parse_table_filter(text, tab);
  return r ? format_id(r.value) : "refused: " + r.check.reason;
}

TEST(TableFilter, ParsesIdsAndBareNumbers) {
  EXPECT_EQ(parsed("h37", TableTab::Vertices), "h37");
  EXPECT_EQ(parsed("37", TableTab::Vertices), "v37");
  EXPECT_EQ(parsed("37", TableTab::Halfedges), "h37");
  EXPECT_EQ(parsed("37", TableTab::Boundaries), "b37");
  EXPECT_EQ(parsed("b0", TableTab::Faces), "b0");
  EXPECT_EQ(parsed("  F12 ", TableTab::Edges), "f12");
  EXPECT_EQ(parsed("0", TableTab::Edges), "e0");
  const std::string hint = "' is not an id: type h37, v5, e2, f0, b0 or a number";
  EXPECT_EQ(parsed("garbage", TableTab::Halfedges), "refused: 'garbage" + hint);
  EXPECT_EQ(parsed("h", TableTab::Halfedges), "refused: 'h" + hint);
  EXPECT_EQ(parsed("h-1", TableTab::Halfedges), "refused: 'h-1" + hint);
  EXPECT_EQ(parsed("37x", TableTab::Halfedges), "refused: '37x" + hint);
  EXPECT_EQ(parsed("h 3", TableTab::Halfedges), "refused: 'h 3" + hint);
  EXPECT_EQ(parsed("99999999999", TableTab::Halfedges), "refused: '99999999999" + hint);
  EXPECT_EQ(parsed("4294967295", TableTab::Halfedges), "refused: '4294967295" + hint);  // the null id
  EXPECT_EQ(parsed("", TableTab::Halfedges), "refused: type an id: h37, v5, e2, f0, b0, or a number for the open tab");
  EXPECT_EQ(parsed("37", TableTab::Changes), "refused: a bare number needs a kind here: type h37, v5, e2, f0 or b0");
  EXPECT_EQ(parsed("e3", TableTab::Changes), "e3");
}

TEST(TableFilter, ResolvesAgainstTheMesh) {
  HalfedgeMesh m = grid_1x1();
  m.delete_element(H(5));
  EXPECT_EQ(format_id(resolve_table_filter(m, "h5", TableTab::Vertices).value), "h5");  // dead rows are shown
  const OpResult<ElementRef> missing = resolve_table_filter(m, "37", TableTab::Halfedges);
  EXPECT_FALSE(missing.ok());
  EXPECT_EQ(missing.check.reason, "h37 does not exist (halfedges h0..h9)");
  EXPECT_FALSE(resolve_table_filter(m, "b1", TableTab::Halfedges).ok());
  EXPECT_TRUE(resolve_table_filter(m, "b0", TableTab::Halfedges).ok());
}

TEST(TableTabs, KindsRoundTrip) {
  for (ElementKind k :
       {ElementKind::Vertex, ElementKind::Halfedge, ElementKind::Edge, ElementKind::Face, ElementKind::Boundary})
    EXPECT_EQ(table_kind(tab_for_kind(k)), k);
}

struct TablesFixture {
  MeshDocument doc;
  Selection sel;
  TablesState state;
  UiProbe probe;
  ImGuiHarness imgui;
  explicit TablesFixture(HalfedgeMesh mesh) : doc(make_document(std::move(mesh))) { state.probe = &probe; }
  void draw() {
    probe.clear();
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    draw_pointer_tables(doc, sel, state);
  }
  int frame() {
    return imgui.frame([&] { draw(); });
  }
  void click(const UiProbe::Item& item) {
    imgui.click(item.center(), [&] { draw(); });
  }
  // Draws the document's last change (two frames, the tab request dropped), then clicks the Changes tab open.
  void open_changes_tab() {
    frame();
    frame();
    state.open_tab_requested = false;
    const UiProbe::Item* tab = probe.find("tab:changes");
    ASSERT_NE(tab, nullptr);
    click(*tab);
    frame();
    EXPECT_EQ(state.active, TableTab::Changes);
  }
  std::vector<const UiProbe::Item*> rows() const {
    std::vector<const UiProbe::Item*> out;
    for (const UiProbe::Item& item : probe.items)
      if (item.name == "row") out.push_back(&item);
    return out;
  }
};

TEST(PointerTables, ClickingRowsAndCellsSelects) {
  TablesFixture t(grid_1x1());
  t.frame();
  EXPECT_GT(t.frame(), 0);
  EXPECT_EQ(t.rows().size(), 10u);  // every halfedge fits
  EXPECT_EQ(t.state.rows_drawn, 10u);
  const UiProbe::Item* row = t.probe.find("row", H(3));
  ASSERT_NE(row, nullptr);
  // Click the row's id text (the left end), not a cell link.
  t.imgui.click(ImVec2(row->min.x + 4, row->center().y), [&] { t.draw(); });
  EXPECT_REF(t.sel.selected, H(3));

  t.frame();
  const UiProbe::Item* twin = t.probe.find("cell:twin", H(6));  // h0's twin cell
  ASSERT_NE(twin, nullptr);
  t.click(*twin);
  EXPECT_REF(t.sel.selected, H(6));
  EXPECT_EQ(t.state.active, TableTab::Halfedges);  // a click inside the tables does not switch tabs

  t.frame();
  const UiProbe::Item* face = t.probe.find("cell:face", B(0));
  ASSERT_NE(face, nullptr);
  t.click(*face);
  EXPECT_REF(t.sel.selected, B(0));
  t.frame();
  t.frame();
  EXPECT_EQ(t.state.active, TableTab::Boundaries);  // reveal: the boundary tab opened, its row is drawn
  EXPECT_NE(t.probe.find("row", B(0)), nullptr);
}

TEST(PointerTables, SelectionMadeElsewhereOpensItsTabAndRow) {
  TablesFixture t(build_halfedge_mesh(make_grid(20, 20)));
  t.frame();
  t.frame();
  t.sel.selected = V(400);  // far down the vertex list, beyond the first screenful
  t.frame();
  t.frame();
  t.frame();
  EXPECT_EQ(t.state.active, TableTab::Vertices);
  const UiProbe::Item* row = t.probe.find("row", V(400));
  ASSERT_NE(row, nullptr);
  EXPECT_GE(row->min.y, 0.0f);
  EXPECT_LE(row->max.y, 420.0f);                  // inside the window
  EXPECT_EQ(t.probe.find("row", V(0)), nullptr);  // scrolled away from the top
}

TEST(PointerTables, TypingInTheFilterJumpsAndSelects) {
  TablesFixture t(grid_1x1());
  t.frame();
  t.frame();
  const UiProbe::Item* filter = t.probe.find("filter");
  ASSERT_NE(filter, nullptr);
  t.click(*filter);
  t.imgui.type("e3", [&] { t.draw(); });
  EXPECT_REF(t.sel.selected, E(3));
  t.frame();
  t.frame();
  EXPECT_EQ(t.state.active, TableTab::Edges);
  EXPECT_NE(t.probe.find("row", E(3)), nullptr);
  t.imgui.type("9", [&] { t.draw(); });  // "e39" does not exist: the selection stays, the reason shows
  EXPECT_REF(t.sel.selected, E(3));
  EXPECT_EQ(t.state.filter_message, "e39 does not exist (edges e0..e4)");
}

TEST(PointerTables, ChangesViewListsTheDiffWithLinks) {
  TablesFixture t(grid_1x1());
  t.sel.selected = E(2);
  ASSERT_TRUE(flip_selected(t.doc, t.sel).ok);
  ASSERT_NO_FATAL_FAILURE(t.open_changes_tab());
  size_t elements = 0;
  for (const UiProbe::Item& item : t.probe.items) elements += item.name == "change-element";
  EXPECT_EQ(elements, 11u);
  const UiProbe::Item* after = t.probe.find("change-after", V(2));  // h2.vertex: v3 -> v2
  ASSERT_NE(after, nullptr);
  t.click(*after);
  EXPECT_REF(t.sel.selected, V(2));
  EXPECT_EQ(t.state.active, TableTab::Changes);  // clicks inside do not switch tabs
}

TEST(PointerTables, ChangesViewSaysWhenAChangeWasNotRecorded) {
  TablesFixture t(grid_1x1());
  {
    const testing::FailingSnapshots failing;
    ASSERT_TRUE(apply_operation(t.doc, "replace", [](HalfedgeMesh& m) {
                  m = build_halfedge_mesh(make_grid(2, 1));
                  return Check::yes();
                }).ok);
  }
  ASSERT_FALSE(t.doc.last.recorded);
  ASSERT_NO_FATAL_FAILURE(t.open_changes_tab());
  EXPECT_NE(t.probe.find("changes-not-recorded"), nullptr);
  EXPECT_EQ(t.probe.find("change-element"), nullptr);
}

TEST(PointerTables, ChangedCellsComeFromTheDocumentIndex) {
  TablesFixture t(grid_1x1());
  t.sel.selected = E(2);
  ASSERT_TRUE(flip_selected(t.doc, t.sel).ok);
  // The table looks cells up in doc.last.index; check the lookups it makes for h2's row.
  const ChangeIndex& index = t.doc.last.index;
  EXPECT_TRUE(index.contains(H(2), MeshField::Next));
  EXPECT_FALSE(index.contains(H(2), MeshField::Twin));
  EXPECT_TRUE(index.contains(H(2), MeshField::Vertex));
  EXPECT_FALSE(index.contains(H(2), MeshField::Edge));
  EXPECT_FALSE(index.contains(H(2), MeshField::Face));
  EXPECT_FALSE(index.contains(H(2), MeshField::Alive));
  // Drawing with highlights produces more geometry than without (the cell backgrounds).
  t.frame();
  const int with = t.frame();
  replace_mesh(t.doc, t.doc.mesh, "");
  t.frame();
  const int without = t.frame();
  EXPECT_GT(with, without);
}

TEST(PointerTables, DeadRowsAreDrawnAndSelectable) {
  // make_grid(2, 2): e2 = v4-v0 with e2.halfedge = h2; collapsing e2 kills h2 (and keeps its stale fields).
  TablesFixture t(build_halfedge_mesh(make_grid(2, 2)));
  t.sel.selected = E(2);
  ASSERT_TRUE(collapse_selected(t.doc, t.sel).ok);
  ASSERT_FALSE(t.doc.mesh.alive(H(2)));
  t.sel.selected = ElementRef();
  t.frame();
  t.frame();
  EXPECT_EQ(t.state.active, TableTab::Halfedges);
  const UiProbe::Item* dead = t.probe.find("row", H(2));
  ASSERT_NE(dead, nullptr);
  // Dead rows show their stale pointers as text, live rows as links: count the links on each row.
  size_t dead_links = 0, live_rows_with_links = 0;
  for (const UiProbe::Item& row : t.probe.items) {
    if (row.name != "row") continue;
    size_t links = 0;
    for (const UiProbe::Item& item : t.probe.items)
      links += item.name.rfind("cell:", 0) == 0 && item.min.y == row.min.y;
    if (t.doc.mesh.alive(row.element)) live_rows_with_links += links == 5;
    else dead_links += links;
  }
  EXPECT_EQ(dead_links, 0u);
  EXPECT_GT(live_rows_with_links, 10u);
  t.imgui.click(ImVec2(dead->min.x + 4, dead->center().y), [&] { t.draw(); });
  EXPECT_REF(t.sel.selected, H(2));
}

TEST(PointerTables, AMillionTrianglesDrawOnlyVisibleRows) {
  TablesFixture t(build_halfedge_mesh(make_torus_with_faces(1000000)));
  const uint32_t n = t.doc.mesh.halfedge_capacity();
  ASSERT_GE(n, 3000000u);
  t.frame();
  t.frame();
  EXPECT_GT(t.state.rows_drawn, 5u);
  EXPECT_LT(t.state.rows_drawn, 60u);  // a 420-pixel window shows a few dozen rows
  EXPECT_GT(t.state.row_height, 0.0f);

  // Jump to the last halfedge: the window slides there; still only visible rows are read.
  t.sel.selected = H(n - 1);
  for (int i = 0; i < 3; ++i) t.frame();
  EXPECT_LT(t.state.rows_drawn, 60u);
  const UiProbe::Item* last = t.probe.find("row", H(n - 1));
  ASSERT_NE(last, nullptr);
  EXPECT_GT(last->min.y, 0.0f);
  EXPECT_LT(last->max.y, 420.0f);
  EXPECT_EQ(t.state.window_start[int(ElementKind::Halfedge)], n - t.state.window_rows);

  // The visible rows are consecutive ids, one row height apart (float layout stays exact).
  const auto rows = t.rows();
  ASSERT_GE(rows.size(), 2u);
  for (size_t i = 1; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i]->element.index, rows[i - 1]->element.index + 1);
    EXPECT_NEAR(rows[i]->min.y - rows[i - 1]->min.y, t.state.row_height, 0.01f);
  }

  // A flip on the big mesh lists its 11 fields and highlights them.
  t.sel.selected = H(0);
  ASSERT_TRUE(flip_selected(t.doc, t.sel).ok);
  EXPECT_TRUE(t.doc.last.listed);
  EXPECT_LE(t.doc.last.changes.size(), 14u);
  t.frame();
  t.frame();
  EXPECT_LT(t.state.rows_drawn, 60u);
  EXPECT_NE(t.probe.find("row", H(0)), nullptr);
}

// The ids of the rows drawn in the table's visible area (below the filter, tabs and header), in screen order.
std::vector<uint32_t> visible_ids(const TablesFixture& t) {
  std::vector<uint32_t> ids;
  for (const UiProbe::Item* r : t.rows())
    if (r->min.y >= 85.0f && r->max.y <= 420.0f) ids.push_back(r->element.index);
  return ids;
}

TEST(PointerTables, TheRowWindowSlidesSmoothlyWhileScrolling) {
  TablesFixture t(build_halfedge_mesh(make_grid(10, 10)));  // 440 halfedges
  t.state.window_rows = 60;                                 // force the sliding window on a small mesh
  t.frame();
  t.frame();
  ImGuiIO& io = ImGui::GetIO();
  const int slot = int(ElementKind::Halfedge);
  uint32_t previous_top = 0, max_start = 0;
  for (int i = 0; i < 150; ++i) {  // scroll down
    io.MousePos = ImVec2(200, 250);
    io.MouseWheel = -1.0f;
    t.frame();
    const std::vector<uint32_t> ids = visible_ids(t);
    ASSERT_GE(ids.size(), 10u);
    // Rows on screen are always consecutive ids, and one wheel step moves the top row by a few rows at most:
    // sliding the window never makes the view jump.
    for (size_t k = 1; k < ids.size(); ++k) ASSERT_EQ(ids[k], ids[k - 1] + 1) << "frame " << i;
    ASSERT_GE(ids.front(), previous_top) << "frame " << i;
    ASSERT_LE(ids.front(), previous_top + 6) << "frame " << i;
    previous_top = ids.front();
    max_start = std::max(max_start, t.state.window_start[slot]);
  }
  EXPECT_GT(max_start, 0u);
  EXPECT_GT(previous_top, 300u);   // far past the first window of 60 rows
  for (int i = 0; i < 150; ++i) {  // and back up to the top
    io.MousePos = ImVec2(200, 250);
    io.MouseWheel = 1.0f;
    t.frame();
    const std::vector<uint32_t> ids = visible_ids(t);
    ASSERT_GE(ids.size(), 10u);
    ASSERT_LE(ids.front(), previous_top) << "frame " << i;
    ASSERT_GE(ids.front() + 6, previous_top) << "frame " << i;
    previous_top = ids.front();
  }
  io.MouseWheel = 0.0f;
  EXPECT_EQ(previous_top, 0u);
  EXPECT_EQ(t.state.window_start[slot], 0u);
}

TEST(PointerTables, BrokenMeshesStillDraw) {
  TablesFixture t(grid_1x1());
  t.doc.mesh.set_next(H(2), H(1));            // rho cycle in f0
  t.doc.mesh.set_twin(H(0), HalfedgeId(50));  // missing
  t.doc.mesh.delete_element(V(2));            // dead vertex still referenced
  t.doc.mesh.set_halfedge(F(1), HalfedgeId());
  for (TableTab tab :
       {TableTab::Vertices, TableTab::Halfedges, TableTab::Edges, TableTab::Faces, TableTab::Boundaries}) {
    t.sel.selected = ElementRef(table_kind(tab), 0);
    t.frame();
    EXPECT_GT(t.frame(), 0);
    EXPECT_EQ(t.state.active, tab);
  }
  t.sel.selected = H(0);
  t.frame();
  t.frame();
  ASSERT_NE(t.probe.find("cell:twin", H(50)), nullptr);
  t.click(*t.probe.find("cell:twin", H(50)));
  EXPECT_REF(t.sel.selected, H(0));  // not followed
}

}  // namespace
}  // namespace meshedit
