// compute_layout: the rectangles of the window's fixed layout, at the sizes students' screens have and at the odd
// ones (minimised, tiny, huge text), with the columns open, folded and dragged.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "document/window_layout.h"

namespace meshedit {
namespace {

std::vector<ScreenRect> parts(const WindowLayout& l) { return {l.menu, l.status, l.left, l.right, l.console, l.view}; }

void expect_tiles(const WindowLayout& l) {
  const std::vector<ScreenRect> all = parts(l);
  for (size_t i = 0; i < all.size(); ++i) {
    EXPECT_TRUE(all[i].empty() || l.display.contains(all[i])) << "part " << i;
    for (size_t j = i + 1; j < all.size(); ++j) EXPECT_FALSE(all[i].overlaps(all[j])) << i << " and " << j;
  }
  for (const ScreenRect& s : {l.left_splitter, l.right_splitter}) EXPECT_FALSE(s.overlaps(l.view));
  if (!l.left.empty()) EXPECT_TRUE(l.left.contains(l.left_splitter));
  if (!l.right.empty()) EXPECT_TRUE(l.right.contains(l.right_splitter));
  if (!l.console.empty()) EXPECT_TRUE(l.console.contains(l.console_splitter));
}

TEST(WindowLayout, At1280x800TheColumnsTakeTheirPreferredWidthsAndTheViewTheRest) {
  const LayoutPrefs prefs;
  const WindowLayout l = compute_layout(1280, 800, 22, 40, prefs, 16, false);
  expect_tiles(l);
  EXPECT_FLOAT_EQ(l.left.width, LayoutPrefs::kDefaultLeftEms * 16);
  EXPECT_FLOAT_EQ(l.right.width, LayoutPrefs::kDefaultRightEms * 16);
  EXPECT_FLOAT_EQ(l.view.x, l.left.width);
  EXPECT_FLOAT_EQ(l.view.y, 22);
  EXPECT_FLOAT_EQ(l.view.width, 1280 - l.left.width - l.right.width);
  EXPECT_FLOAT_EQ(l.view.height, 800 - 22 - 40);
  EXPECT_FLOAT_EQ(l.right.right(), 1280);
  EXPECT_FLOAT_EQ(l.status.y, 760);
}

TEST(WindowLayout, OnASmallScreenTheColumnsShrinkAndTheViewKeepsItsShare) {
  const WindowLayout l = compute_layout(1024, 640, 22, 40, LayoutPrefs{}, 16, false);
  expect_tiles(l);
  EXPECT_GE(l.view.width, 1024 * WindowLayout::kMinViewShare - 0.5f);
  EXPECT_GE(l.left.width, WindowLayout::kMinColumnEms * 16);
  EXPECT_GE(l.right.width, WindowLayout::kMinColumnEms * 16);
  // In proportion: the right column stays wider, as preferred.
  EXPECT_GT(l.right.width, l.left.width);
}

TEST(WindowLayout, FoldedColumnsGiveTheViewTheirRoom) {
  LayoutPrefs prefs;
  prefs.left_open = false;
  WindowLayout l = compute_layout(1280, 800, 22, 40, prefs, 16, false);
  expect_tiles(l);
  EXPECT_TRUE(l.left.empty());
  EXPECT_TRUE(l.left_splitter.empty());
  EXPECT_FLOAT_EQ(l.view.x, 0);
  prefs.right_open = false;
  l = compute_layout(1280, 800, 22, 40, prefs, 16, false);
  EXPECT_FLOAT_EQ(l.view.width, 1280);
}

TEST(WindowLayout, TheConsoleTakesTheBottomOfTheCentreAtMostHalfOfIt) {
  LayoutPrefs prefs;
  WindowLayout l = compute_layout(1280, 800, 22, 40, prefs, 16, true);
  expect_tiles(l);
  EXPECT_FLOAT_EQ(l.console.x, l.view.x);
  EXPECT_FLOAT_EQ(l.console.width, l.view.width);
  EXPECT_FLOAT_EQ(l.console.y, l.view.bottom());
  EXPECT_FLOAT_EQ(l.console.height, LayoutPrefs::kDefaultConsoleEms * 16);
  prefs.console_ems = 60;
  l = compute_layout(1280, 800, 22, 40, prefs, 16, true);
  EXPECT_FLOAT_EQ(l.console.height, (800 - 62) * 0.5f);
}

TEST(WindowLayout, MinimisedTinyAndNonsenseSizesStillTile) {
  LayoutPrefs huge;
  huge.left_ems = 1e9f;
  huge.right_ems = -5;
  for (const auto& [w, h] :
       std::vector<std::pair<float, float>>{{0, 0}, {1, 1}, {200, 150}, {640, 400}, {7680, 4320}}) {
    for (const LayoutPrefs& prefs : {LayoutPrefs{}, huge}) {
      const WindowLayout l = compute_layout(w, h, 22, 40, prefs, 16, true);
      SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h));
      expect_tiles(l);
      EXPECT_GE(l.view.width, 0);
      EXPECT_GE(l.view.height, 0);
    }
  }
  const WindowLayout nan = compute_layout(1280, 800, 22, 40, LayoutPrefs{}, std::nanf(""), false);
  expect_tiles(nan);
}

TEST(WindowLayout, ColumnsGrowWithTheText) {
  const WindowLayout small = compute_layout(1920, 1080, 22, 40, LayoutPrefs{}, 16, false);
  const WindowLayout large = compute_layout(1920, 1080, 22, 40, LayoutPrefs{}, 20, false);
  EXPECT_FLOAT_EQ(large.left.width / small.left.width, 20.0f / 16.0f);
}

TEST(WindowLayout, ASplitterDragStartsFromTheWidthShownAndStaysInRange) {
  EXPECT_FLOAT_EQ(dragged_ems(320, 32, 16, WindowLayout::kMinColumnEms), 22.0f);
  EXPECT_FLOAT_EQ(dragged_ems(320, -1000, 16, WindowLayout::kMinColumnEms), WindowLayout::kMinColumnEms);
  EXPECT_FLOAT_EQ(dragged_ems(320, 1e6f, 16, WindowLayout::kMinColumnEms), kMaxPanelEms);
  EXPECT_FLOAT_EQ(dragged_ems(320, std::nanf(""), 16, WindowLayout::kMinColumnEms), 20.0f);
}

}  // namespace
}  // namespace meshedit
