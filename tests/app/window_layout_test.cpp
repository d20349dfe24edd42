// The window's layout in the real binary under Xvfb, read back with the `layout-json` action: on a 1280x800 and a
// 1024x640 screen, every lesson's first step and the mesh, curve and patch views keep the lesson's text and its
// buttons and the view clear of every other panel, inside the screen, in type of at least 15 px. The keys that
// change the layout (columns, text size) work, and what they chose is there at the next start.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/window_test_support.h"
#include "core/primitives.h"
#include "io/mesh_file.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

using nlohmann::json;
using testing::run_window;
using testing::WindowRun;
using testing::XServer;
namespace fs = std::filesystem;

struct Rect {
  double x = 0, y = 0, w = 0, h = 0;
  bool overlaps(const Rect& r) const { return x < r.x + r.w && r.x < x + w && y < r.y + r.h && r.y < y + h; }
  bool inside(const Rect& r) const { return x >= r.x && y >= r.y && x + w <= r.x + r.w && y + h <= r.y + r.h; }
};

Rect rect_of(const json& j) {
  return {j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>(), j.at(3).get<double>()};
}

std::string describe(const Rect& r) {
  std::ostringstream out;
  out << "[" << r.x << ", " << r.y << ", " << r.w << " x " << r.h << "]";
  return out.str();
}

json read_json(const fs::path& path) {
  std::ifstream in(path);
  return json::parse(in);
}

// Opens `file` on a screen of `screen` ("1024x640") with no --size (the window fits the screen) and returns the
// layout after a few frames, after `before` (more actions).
json layout_of(const XServer& x, const fs::path& file, const fs::path& dir, const std::string& before = "") {
  const fs::path out = dir / "layout.json";
  const WindowRun run = run_window(
      x.display(), file, "frames 4\n" + before + "frames 2\nlayout-json " + out.string() + "\nquit\n", dir, "");
  EXPECT_EQ(run.status, 0) << run.output;
  return fs::exists(out) ? read_json(out) : json::object();
}

// What every screen must keep: the view and the lesson (when there is one) inside the display and clear of every
// other panel, the text at least 15 px high.
void expect_clear_layout(const json& layout, const std::string& what, int screen_width, int screen_height) {
  SCOPED_TRACE(what);
  ASSERT_TRUE(layout.contains("view")) << layout.dump();
  const Rect display{0, 0, layout["display"][0].get<double>(), layout["display"][1].get<double>()};
  EXPECT_LE(display.w, screen_width);
  EXPECT_LE(display.h, screen_height);
  EXPECT_GE(display.w, screen_width * 0.9) << "the window should take the screen it fits";
  EXPECT_GE(layout["font_px"].get<double>(), 15.0);

  const Rect view = rect_of(layout["view"]);
  EXPECT_GT(view.w, display.w * 0.3) << describe(view);
  EXPECT_GT(view.h, display.h * 0.5) << describe(view);
  EXPECT_TRUE(view.inside(display)) << describe(view);

  Rect left{};
  bool has_left = false;
  for (const json& panel : layout["panels"]) {
    const Rect r = rect_of(panel["rect"]);
    const std::string name = panel["name"];
    EXPECT_TRUE(r.inside(display)) << name << " " << describe(r);
    EXPECT_FALSE(r.overlaps(view)) << name << " " << describe(r) << " covers the view " << describe(view);
    if (name == "left column") {
      left = r;
      has_left = true;
    }
  }
  for (const json& splitter : layout["splitters"]) {
    EXPECT_FALSE(rect_of(splitter["rect"]).overlaps(view)) << splitter.dump();
  }
  if (!layout["lesson"].contains("next")) return;
  ASSERT_TRUE(has_left) << "a lesson runs, but there is no left column";
  for (const char* part : {"text", "back", "next"}) {
    ASSERT_TRUE(layout["lesson"].contains(part)) << part;
    const Rect r = rect_of(layout["lesson"][part]);
    EXPECT_TRUE(r.inside(left)) << part << " " << describe(r) << " sticks out of the left column " << describe(left);
    EXPECT_TRUE(r.inside(display)) << part << " " << describe(r);
    EXPECT_GT(r.w, 0.0);
    for (const json& panel : layout["panels"]) {
      if (panel["name"] == "left column") continue;
      EXPECT_FALSE(rect_of(panel["rect"]).overlaps(r)) << panel["name"] << " covers the lesson's " << part;
    }
  }
}

struct Screen {
  int width, height;
};

class WindowLayoutOnScreen : public ::testing::TestWithParam<Screen> {
 protected:
  std::string screen() const { return std::to_string(GetParam().width) + "x" + std::to_string(GetParam().height); }
};

TEST_P(WindowLayoutOnScreen, EveryLessonsFirstStepKeepsItsTextButtonsAndViewClear) {
  XServer x(screen());
  if (x.display().empty()) GTEST_SKIP() << "no Xvfb";
  std::vector<fs::path> lessons;
  for (const auto& entry : fs::directory_iterator(testing::source_dir() / "lessons")) {
    if (entry.path().extension() == ".lua") lessons.push_back(entry.path());
  }
  ASSERT_GE(lessons.size(), 8u);
  for (const fs::path& lesson : lessons) {
    const fs::path dir = testing::scratch_dir();
    const json layout = layout_of(x, lesson, dir);
    expect_clear_layout(layout, lesson.filename().string() + " at " + screen(), GetParam().width, GetParam().height);
    EXPECT_TRUE(layout["lesson"].contains("next")) << lesson << ": the lesson's Next button was not drawn";
  }
}

TEST_P(WindowLayoutOnScreen, TheMeshCurveAndPatchViewsKeepTheViewClear) {
  XServer x(screen());
  if (x.display().empty()) GTEST_SKIP() << "no Xvfb";
  const fs::path dir = testing::scratch_dir();
  const fs::path cube = dir / "cube.obj";
  save_mesh(cube, make_cube());
  const fs::path assets = testing::source_dir() / "assets";
  const std::pair<fs::path, std::string> files[] = {
      {cube, "mesh"}, {assets / "curve_cubic.bzc", "curve"}, {assets / "teapot.bez", "patches"}};
  for (const auto& [file, mode] : files) {
    const fs::path run_dir = testing::scratch_dir();
    const json layout = layout_of(x, file, run_dir);
    expect_clear_layout(layout, file.filename().string() + " at " + screen(), GetParam().width, GetParam().height);
    EXPECT_EQ(layout.value("mode", ""), mode);
    // The view's controls sit beside it, in the right column.
    bool right = false;
    for (const json& panel : layout["panels"]) right = right || panel["name"] == "right column";
    EXPECT_TRUE(right) << file;
  }
}

INSTANTIATE_TEST_SUITE_P(Screens, WindowLayoutOnScreen, ::testing::Values(Screen{1280, 800}, Screen{1024, 640}),
                         [](const ::testing::TestParamInfo<Screen>& screen) {
                           return std::to_string(screen.param.width) + "x" + std::to_string(screen.param.height);
                         });

TEST(WindowLayout, TheFlipAndSplitLessonsLabelsNeverOverlapAndStayInTheView) {
  XServer x("1280x800");
  if (x.display().empty()) GTEST_SKIP() << "no Xvfb";
  for (const char* name : {"4_edge_flip.lua", "5_edge_split.lua"}) {
    SCOPED_TRACE(name);
    const json layout = layout_of(x, testing::source_dir() / "lessons" / name, testing::scratch_dir());
    const Rect view = rect_of(layout["view"]);
    const json& drawn = layout["labels"]["drawn"];
    ASSERT_GE(drawn.size(), 10u) << layout["labels"].dump();
    size_t lesson_labels = 0;
    for (size_t i = 0; i < drawn.size(); ++i) {
      const Rect r = rect_of(drawn[i]["rect"]);
      EXPECT_TRUE(r.inside(view)) << drawn[i].dump();
      lesson_labels += drawn[i]["source"] == "lesson";
      for (size_t j = i + 1; j < drawn.size(); ++j) {
        EXPECT_FALSE(r.overlaps(rect_of(drawn[j]["rect"]))) << drawn[i].dump() << " and " << drawn[j].dump();
      }
    }
    EXPECT_GT(lesson_labels, 0u);
  }
}

TEST(WindowLayout, ColumnsFoldAndTextSizeChangesAndBothLastToTheNextStart) {
  XServer x("1280x800");
  if (x.display().empty()) GTEST_SKIP() << "no Xvfb";
  const fs::path dir = testing::scratch_dir();
  const fs::path lesson = testing::source_dir() / "lessons" / "4_edge_flip.lua";

  const json start = layout_of(x, lesson, dir);
  const double px = start["font_px"].get<double>();
  const Rect view = rect_of(start["view"]);

  // Ctrl+= twice: bigger text; [ folds the left column, and the view takes its room.
  const json changed = layout_of(x, lesson, dir, "key ctrl+equal\nframes 2\nkey ctrl+equal\nframes 2\nkey [\n");
  EXPECT_EQ(changed["font_px"].get<double>(), px + 2.0);
  const Rect wider = rect_of(changed["view"]);
  EXPECT_EQ(wider.x, 0.0);
  EXPECT_GT(wider.w, view.w + 200.0);
  for (const json& panel : changed["panels"]) EXPECT_NE(panel["name"], "left column");

  // The next start (same settings folder) opens as the last one closed.
  const json again = layout_of(x, lesson, dir);
  EXPECT_EQ(again["font_px"].get<double>(), px + 2.0);
  EXPECT_EQ(rect_of(again["view"]).x, 0.0);

  // Ctrl+0 and ] bring back the default size and fold the right column; [ brings the left one back.
  const json reset = layout_of(x, lesson, dir, "key ctrl+0\nframes 2\nkey ]\nframes 2\nkey [\n");
  EXPECT_EQ(reset["font_px"].get<double>(), px);
  const Rect no_right = rect_of(reset["view"]);
  EXPECT_GT(no_right.x, 0.0);
  EXPECT_DOUBLE_EQ(no_right.x + no_right.w, reset["display"][0].get<double>());
}

TEST(WindowLayout, AResizedWindowKeepsItsLayoutClear) {
  XServer x("1280x800");
  if (x.display().empty()) GTEST_SKIP() << "no Xvfb";
  const fs::path dir = testing::scratch_dir();
  const fs::path lesson = testing::source_dir() / "lessons" / "4_edge_flip.lua";
  const std::pair<int, int> sizes[] = {{1024, 640}, {640, 400}, {1280, 800}};
  std::string actions = "frames 3\n";
  for (const auto& [w, h] : sizes) {
    actions += "window-size " + std::to_string(w) + " " + std::to_string(h) + "\nframes 4\nlayout-json " +
               (dir / ("layout-" + std::to_string(w) + ".json")).string() + "\n";
  }
  const WindowRun run = run_window(x.display(), lesson, actions + "quit\n", dir, "");
  EXPECT_EQ(run.status, 0) << run.output;
  for (const auto& [w, h] : sizes) {
    const json layout = read_json(dir / ("layout-" + std::to_string(w) + ".json"));
    EXPECT_EQ(layout["display"][0].get<double>(), w);
    EXPECT_EQ(layout["display"][1].get<double>(), h);
    expect_clear_layout(layout, "resized to " + std::to_string(w), w, h);
  }
}

TEST(WindowLayout, OnAHiDpiScreenTheTextAndColumnsScaleAndTheButtonsStayInside) {
  XServer x("1280x800");
  if (x.display().empty()) GTEST_SKIP() << "no Xvfb";
  if (std::system("command -v xprop >/dev/null 2>&1") != 0) GTEST_SKIP() << "no xprop (x11-utils)";
  // GLFW reads the content scale from Xft.dpi: 192 dpi is a scale of 2.
  const std::string set_dpi =
      "DISPLAY=" + x.display() + " xprop -root -f RESOURCE_MANAGER 8s -set RESOURCE_MANAGER 'Xft.dpi: 192'";
  ASSERT_EQ(std::system(set_dpi.c_str()), 0);
  const json layout = layout_of(x, testing::source_dir() / "lessons" / "4_edge_flip.lua", testing::scratch_dir());
  EXPECT_EQ(layout["font_px"].get<double>(), 32.0);
  expect_clear_layout(layout, "content scale 2", 1280, 800);
  EXPECT_TRUE(layout["lesson"].contains("next"));
}

TEST(WindowLayout, WithoutTheFontFilesImGuisFontStandsInWithAWarning) {
  XServer x("1280x800");
  if (x.display().empty()) GTEST_SKIP() << "no Xvfb";
  const fs::path dir = testing::scratch_dir();
  const fs::path out = dir / "layout.json";
  const WindowRun run = run_window(x.display(), testing::source_dir() / "lessons" / "welcome.lua",
                                   "frames 3\nexpect-message DejaVuSans.ttf\nlayout-json " + out.string() + "\nquit\n",
                                   dir, "", "MESHEDIT_FONT_DIR='" + (dir / "no fonts here").string() + "'");
  EXPECT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("fonts-dejavu-core"), std::string::npos) << run.output;
  ASSERT_TRUE(fs::exists(out));
  EXPECT_GE(read_json(out)["font_px"].get<double>(), 15.0);  // the built-in font, at the size asked for
}

}  // namespace
}  // namespace meshedit
