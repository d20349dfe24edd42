// The real window under Xvfb in two languages: View > Language switches the window and the lesson at once, keeping the
// step and what the student did in it; the choice is kept in the settings file and the next start shows it; a window
// with no language chosen follows the system's locale; and a missing Chinese font is said in the status line. Skips
// without Xvfb.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "app/window_test_support.h"
#include "io/file_access.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

using testing::run_window;
using testing::WindowRun;
using testing::XServer;
namespace fs = std::filesystem;

TEST(WindowLanguage, SwitchingKeepsTheStepAndItsAnswersAndTheChoiceLastsToTheNextStart) {
  XServer x;
  if (x.display().empty()) GTEST_SKIP() << "no X server and no Xvfb";
  const fs::path dir = testing::scratch_dir();
  const fs::path lesson = testing::source_dir() / "lessons" / "welcome.lua";
  std::ostringstream actions;
  actions << "frames 2\n"
          << "expect-lesson-step 1 finished\n"
          << "lesson-next\n"
          << "expect-lesson-step 2 waiting\n"
          << "key W\n"
          << "expect-lesson-step 2 finished\n"
          << "expect-lesson-shown Well done. Keep the wireframe on\n"
          << "language zh\n"
          << "frames 2\n"
          << "expect-lesson-step 2 finished\n"  // the same step, its wait met: nothing ran again
          << "expect-lesson-shown 很好。让线框一直开着\n"
          << "expect-lesson-said Well done. Keep the wireframe on\n"  // the lesson's logic keeps the English
          << "screenshot " << (dir / "zh.png").string() << "\n"
          << "quit\n";
  const WindowRun run = run_window(x.display(), lesson, actions.str(), dir);
  ASSERT_EQ(run.status, 0) << run.output;
  EXPECT_NE(read_file(dir / "meshedit" / "settings.ini").find("language = zh"), std::string::npos);

  // The next start reads the choice, whatever the locale says.
  const WindowRun again = run_window(x.display(), lesson,
                                     "frames 2\nexpect-lesson-shown 欢迎\nlanguage en\nframes 1\n"
                                     "expect-lesson-shown # Welcome\nquit\n",
                                     dir);
  EXPECT_EQ(again.status, 0) << again.output;
}

TEST(WindowLanguage, AWindowWithNoLanguageChosenFollowsTheLocaleAndAMissingFontIsSaid) {
  XServer x;
  if (x.display().empty()) GTEST_SKIP() << "no X server and no Xvfb";
  const fs::path dir = testing::scratch_dir();
  const fs::path fonts = dir / "fonts";  // DejaVu without the Chinese font
  fs::create_directories(fonts);
  for (const char* font : {"DejaVuSans.ttf", "DejaVuSansMono.ttf"}) {
    fs::copy_file(fs::path("/usr/share/fonts/truetype/dejavu") / font, fonts / font,
                  fs::copy_options::overwrite_existing);
  }
  const fs::path lesson = testing::source_dir() / "lessons" / "welcome.lua";
  const WindowRun run = run_window(x.display(), lesson,
                                   "frames 2\nexpect-lesson-shown 欢迎\n"
                                   "expect-message install fonts-wqy-microhei\nquit\n",
                                   dir, "1280x800", "LANG=zh_CN.UTF-8 MESHEDIT_FONT_DIR='" + fonts.string() + "'");
  EXPECT_EQ(run.status, 0) << run.output;
}

}  // namespace
}  // namespace meshedit
