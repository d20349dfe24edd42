// Parts 1 and 2 in the real window under Xvfb: M in the curve view makes E's levels the student's evaluate_step
// (a wrong point is named with both values, the solution matches down to the curve point); M in the patch view
// checks the probe point (a Lua error keeps patch.lua:LINE, the solution matches).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "app/window_test_support.h"
#include "render/image_file.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

using testing::run_window;
using testing::WindowRun;
using testing::XServer;
namespace fs = std::filesystem;

using testing::read_text;

TEST(WindowBezierMine, CurveLevelsAndThePatchProbeComeFromTheStudentsFiles) {
  XServer x;
  if (x.display().empty()) GTEST_SKIP() << "no X server and no Xvfb";
  const fs::path dir = testing::scratch_dir();
  const fs::path source = testing::source_dir();
  const fs::path solutions = source / "tests" / "exercise" / "solutions";
  // A student whose step pushes the second point of every level up by 0.25, and whose patch evaluate fails.
  const fs::path buggy = dir / "student";
  fs::create_directories(buggy);
  std::string curve = read_text(solutions / "curve.lua");
  const std::string line = "    result[i] = (1 - t) * points[i] + t * points[i + 1]\n";
  ASSERT_NE(curve.find(line), std::string::npos);
  curve.insert(curve.find(line) + line.size(),
               "    if i == 2 then result[i] = result[i] + meshedit.vec3(0, 0.25, 0) end\n");
  std::ofstream(buggy / "curve.lua") << curve;
  std::ofstream(buggy / "patch.lua") << "function evaluate(patch, u, v)\n  return patch.points[1] + nil\nend\n";

  std::ostringstream actions;
  actions << "frames 2\n"
          << "exercise curve " << buggy.string() << "\n"
          << "key M\n"
          << "key E\n"
          << "frames 2\n"
          // assets/curve_cubic.bzc at t = 0.5: level 1's second point is (0.5, 0.5); yours is 0.25 higher.
          << "expect-mine level 1, point 2 of 3: yours is (0.5, 0.75, 0), the reference's is (0.5, 0.5, 0)\n"
          << "screenshot " << (dir / "curve_mine.png").string() << "\n"
          << "frames 2\n"
          << "exercise curve " << solutions.string() << "\n"
          << "key E\n"
          << "key E\n"
          << "frames 2\n"
          << "expect-mine levels 1 to 3 are the reference's: your curve point is right\n"
          << "open " << (source / "assets" / "teapot.bez").string() << "\n"
          << "exercise patch " << buggy.string() << "\n"
          << "key M\n"
          << "frames 2\n"
          << "expect-mine patch.lua:2:\n"
          << "exercise patch " << solutions.string() << "\n"
          << "frames 2\n"
          << "expect-mine yours is the reference's P(0.5, 0.5)\n"
          << "screenshot " << (dir / "patch_mine.png").string() << "\n"
          << "frames 2\n"
          << "quit\n";
  const WindowRun run = run_window(x.display(), source / "assets" / "curve_cubic.bzc", actions.str(), dir);
  EXPECT_EQ(run.status, 0) << run.output;
  EXPECT_EQ(read_png(dir / "curve_mine.png").width, 1280);
  EXPECT_EQ(read_png(dir / "patch_mine.png").width, 1280);
}

}  // namespace
}  // namespace meshedit
