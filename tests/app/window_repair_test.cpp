// The real window: a file that is not a manifold is refused, File > Open a repaired copy opens it repaired, and
// Edit > Triangulate makes a quad mesh Loop-subdividable (scripted actions under Xvfb; skips without Xvfb).
#include <gtest/gtest.h>

#include <fstream>

#include "app/window_test_support.h"
#include "core/primitives.h"
#include "io/mesh_file.h"
#include "render/image_file.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

using testing::run_window;
using testing::WindowRun;
using testing::XServer;
namespace fs = std::filesystem;

TEST(WindowRepair, ARefusedFileOpensAsARepairedCopy) {
  XServer x;
  if (x.display().empty()) GTEST_SKIP() << "no X server and no Xvfb";
  const fs::path dir = testing::scratch_dir();
  const fs::path file = dir / "cube.obj";
  save_mesh(file, make_cube());
  const fs::path bowtie = dir / "bowtie.obj";
  std::ofstream(bowtie) << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv -1 0 0\nv -1 -1 0\nf 1 2 3\nf 1 4 5\n";
  const std::string actions = "frames 2\nopen " + bowtie.string() +
                              "\nexpect-message File > Open a repaired copy\n"
                              "open-repaired\nframes 2\n"
                              "expect-message opened a repaired copy of\n"
                              "expect-message repaired: 1 bow-tie vertex split\n"
                              "expect-valid\nselect v5\nquit\n";
  const WindowRun run = run_window(x.display(), file, actions, dir);
  EXPECT_EQ(run.status, 3) << run.output;  // the refused `open` is an action failure by design
  EXPECT_NE(run.output.find("actions.txt:2: open failed"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("open-repaired failed"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("expect-message failed"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("expect-valid failed"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("select failed"), std::string::npos) << run.output;
}

TEST(WindowRepair, TriangulateThenLoopSubdivideAQuadCube) {
  XServer x;
  if (x.display().empty()) GTEST_SKIP() << "no X server and no Xvfb";
  const fs::path dir = testing::scratch_dir();
  const fs::path file = dir / "quads.obj";
  save_mesh(file, make_cube_quads());
  const std::string actions =
      "frames 2\nkey L\nexpect-message Edit > Triangulate\ntriangulate\nframes 1\n"
      "expect-message 6 faces split into 12 triangles\nkey L\nframes 1\nexpect-message Loop subdivision\n"
      "expect-valid\nselect f47\nkey ctrl+Z\nkey ctrl+Z\nselect f5\nquit\n";
  const WindowRun run = run_window(x.display(), file, actions, dir);
  EXPECT_EQ(run.status, 0) << run.output;
}

// Blender's STL of Suzanne (tests/data/from_tools): refused (joining corners by position joins two of her eyes' rim
// vertices to the head's: two bow-ties), opened as a repaired copy, then Catmull-Clark and Loop subdivided and drawn:
// the picture has Suzanne in it.
TEST(WindowRepair, ABlenderStlOpensRepairedSubdividesAndDraws) {
  XServer x;
  if (x.display().empty()) GTEST_SKIP() << "no X server and no Xvfb";
  const fs::path dir = testing::scratch_dir();
  const fs::path file = testing::source_dir() / "tests" / "data" / "from_tools" / "suzanne.stl";
  const fs::path shot = dir / "suzanne.png";
  const std::string actions =
      "frames 2\nexpect-message File > Open a repaired copy\n"
      "open-repaired\nframes 1\n"
      "expect-message repaired: 2 bow-tie vertices split\n"
      "subdivide catmull-clark\nexpect-valid\nexpect-message Catmull-Clark subdivision\n"
      "triangulate\nsubdivide loop\nexpect-valid\nframes 2\n"
      "screenshot " +
      shot.string() + "\nframes 2\nquit\n";
  const WindowRun run = run_window(x.display(), file, actions, dir);
  EXPECT_EQ(run.status, 0) << run.output;
  const Image image = read_png(shot);
  ASSERT_GT(image.width, 0);
  // Suzanne, fitted to the view, is drawn lit grey over the dark background: a good part of the window's middle is her
  // (the view is not centred in the window, and her shaded side is darker than the bar).
  size_t lit = 0, box = 0;
  for (int row = image.height * 2 / 5; row < image.height * 3 / 5; ++row) {
    for (int column = image.width * 9 / 20; column < image.width * 11 / 20; ++column, ++box) {
      const uint8_t* p = &image.rgba[(size_t(row) * size_t(image.width) + size_t(column)) * 4];
      lit += p[0] > 90 && p[1] > 90 && p[2] > 90;
    }
  }
  EXPECT_GT(lit, box / 8) << "lit pixels in the middle: " << lit << " of " << box;
}

}  // namespace
}  // namespace meshedit
