// The web page's end-to-end script (tests/web/lesson4_flip.txt, which scripts/web_test.sh plays in headless
// Chromium) played in the desktop window under Xvfb: the same file of actions holds in both. The page starts in its
// packaged source tree, so the script names the student folder relative to the top of a checkout; here that folder
// is the source tree's.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "app/window_test_support.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

using testing::run_window;
using testing::WindowRun;
using testing::XServer;
namespace fs = std::filesystem;

TEST(WindowWebActions, TheWebPagesLessonFourScriptHoldsInTheDesktopWindow) {
  XServer x;
  if (x.display().empty()) GTEST_SKIP() << "no X server and no Xvfb";
  const fs::path dir = testing::scratch_dir();
  std::ifstream in(testing::source_dir() / "tests" / "web" / "lesson4_flip.txt");
  ASSERT_TRUE(in) << "tests/web/lesson4_flip.txt";
  std::ostringstream script;
  for (std::string line; std::getline(in, line);) {
    const std::string relative = "exercise flip scripts/student";
    if (line == relative) line = "exercise flip " + (testing::source_dir() / "scripts" / "student").string();
    script << line << "\n";
  }
  const WindowRun run =
      run_window(x.display(), testing::source_dir() / "lessons" / "4_edge_flip.lua", script.str(), dir);
  EXPECT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("actions: all expectations held"), std::string::npos) << run.output;
}

}  // namespace
}  // namespace meshedit
