// The window's lasting settings: written and read back whole, a hand-edited file's mistakes named by line and kept
// at their defaults, and the text size steps clamped.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>

#include "document/settings.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;

TEST(Settings, WrittenSettingsReadBackTheSame) {
  const fs::path file = testing::scratch_dir() / "sub" / "settings.ini";
  Settings s;
  s.window_width = 1000;
  s.window_height = 700;
  s.font_px = 19;
  s.theme = Theme::Light;
  s.layout.left_ems = 30.5f;
  s.layout.right_ems = 14;
  s.layout.console_ems = 9;
  s.layout.left_open = false;
  ASSERT_EQ(write_settings(file, s), "");
  std::vector<std::string> warnings;
  const Settings r = read_settings(file, warnings);
  EXPECT_TRUE(warnings.empty());
  EXPECT_EQ(r.window_width, 1000);
  EXPECT_EQ(r.window_height, 700);
  EXPECT_EQ(r.font_px, 19);
  EXPECT_EQ(r.theme, Theme::Light);
  EXPECT_EQ(r.layout.left_ems, 30.5f);
  EXPECT_EQ(r.layout.right_ems, 14);
  EXPECT_EQ(r.layout.console_ems, 9);
  EXPECT_FALSE(r.layout.left_open);
  EXPECT_TRUE(r.layout.right_open);
}

TEST(Settings, AMissingFileGivesTheDefaults) {
  std::vector<std::string> warnings;
  const Settings r = read_settings(testing::scratch_dir() / "none.ini", warnings);
  EXPECT_TRUE(warnings.empty());
  EXPECT_EQ(r.window_width, Settings::kDefaultWindowWidth);
  EXPECT_EQ(r.font_px, Settings::kDefaultFontPx);
}

TEST(Settings, BadLinesAreNamedAndKeepTheirDefaults) {
  std::vector<std::string> warnings;
  const Settings r = parse_settings(
      "# comment\nfont_px = 500\nwindow_width = 900\nbogus\ncolour = red\ntheme = purple\nleft_column_open = yes\n"
      "window_height = nan\nright_column_ems = 20\n",
      "settings.ini", warnings);
  ASSERT_EQ(warnings.size(), 6u);
  EXPECT_EQ(warnings[0], "settings.ini:2: font_px must be a text size in pixels, not '500'; kept the default");
  EXPECT_EQ(warnings[1], "settings.ini:4: not a 'key = value' line");
  EXPECT_EQ(warnings[2], "settings.ini:5: unknown setting 'colour'");
  EXPECT_NE(warnings[3].find("settings.ini:6: theme must be dark or light"), std::string::npos);
  EXPECT_NE(warnings[4].find("settings.ini:7:"), std::string::npos);
  EXPECT_NE(warnings[5].find("settings.ini:8:"), std::string::npos);
  EXPECT_EQ(r.font_px, Settings::kDefaultFontPx);
  EXPECT_EQ(r.window_width, 900);
  EXPECT_EQ(r.window_height, Settings::kDefaultWindowHeight);
  EXPECT_EQ(r.theme, Theme::Dark);
  EXPECT_TRUE(r.layout.left_open);
  EXPECT_EQ(r.layout.right_ems, 20);
}

TEST(Settings, AnimateEditsIsOnByDefaultAndReadsBackOff) {
  EXPECT_TRUE(Settings{}.animate_edits);
  Settings s;
  s.animate_edits = false;
  EXPECT_NE(format_settings(s).find("animate_edits = false\n"), std::string::npos);
  std::vector<std::string> warnings;
  EXPECT_FALSE(parse_settings(format_settings(s), "settings.ini", warnings).animate_edits);
  EXPECT_TRUE(warnings.empty());
  EXPECT_TRUE(parse_settings("animate_edits = true\n", "settings.ini", warnings).animate_edits);
  EXPECT_TRUE(parse_settings("animate_edits = no\n", "settings.ini", warnings).animate_edits);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], "settings.ini:1: animate_edits must be true or false, not 'no'; kept the default");
}

TEST(Settings, StudentCodeSecondsReadsBackAndGivesTheWindowsDeadline) {
  EXPECT_EQ(Settings{}.student_code_seconds, 5.0);
  Settings s;
  s.student_code_seconds = 2.5;
  EXPECT_NE(format_settings(s).find("student_code_seconds = 2.5\n"), std::string::npos) << format_settings(s);
  std::vector<std::string> warnings;
  EXPECT_EQ(parse_settings(format_settings(s), "settings.ini", warnings).student_code_seconds, 2.5);
  EXPECT_TRUE(warnings.empty());
  EXPECT_EQ(parse_settings("student_code_seconds = 0\n", "settings.ini", warnings).student_code_seconds, 5.0);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("settings.ini:1: student_code_seconds"), std::string::npos) << warnings[0];
  const LuaLimits limits = window_student_limits(2.5);
  EXPECT_EQ(limits.wall_seconds, 2.5);
  EXPECT_EQ(limits.instructions, std::numeric_limits<uint64_t>::max());
  EXPECT_EQ(limits.memory_bytes, LuaLimits{}.memory_bytes);
}

TEST(Settings, AnUnwritableFolderIsReportedNotThrown) {
  const fs::path blocker = testing::scratch_dir() / "file";
  std::ofstream(blocker) << "x";
  EXPECT_NE(write_settings(blocker / "meshedit" / "settings.ini", Settings{}), "");
}

TEST(Settings, ThePathFollowsXdgConfigHomeThenHome) {
  const char* old_xdg = std::getenv("XDG_CONFIG_HOME");
  const std::string saved = old_xdg ? old_xdg : "";
  ::setenv("XDG_CONFIG_HOME", "/tmp/xdg", 1);
  EXPECT_EQ(settings_path(), fs::path("/tmp/xdg/meshedit/settings.ini"));
  ::unsetenv("XDG_CONFIG_HOME");
  ::setenv("HOME", std::getenv("HOME") ? std::getenv("HOME") : "/root", 1);
  EXPECT_EQ(settings_path(), fs::path(std::getenv("HOME")) / ".config" / "meshedit" / "settings.ini");
  if (old_xdg) ::setenv("XDG_CONFIG_HOME", saved.c_str(), 1);
}

TEST(Settings, TextSizeStepsStayInRange) {
  EXPECT_EQ(stepped_font_px(16, 1), 17);
  EXPECT_EQ(stepped_font_px(16, -1), 15);
  EXPECT_EQ(stepped_font_px(Settings::kMaxFontPx, 1), Settings::kMaxFontPx);
  EXPECT_EQ(stepped_font_px(Settings::kMinFontPx, -3), Settings::kMinFontPx);
  EXPECT_EQ(stepped_font_px(std::nanf(""), 1), Settings::kDefaultFontPx + 1);
}

}  // namespace
}  // namespace meshedit
