// The real window: after File > Open a repaired copy, clicking a change in the Repairs tab selects its spot in the
// repaired mesh; once the mesh is edited the rows no longer select, and another file opened drops them (scripted
// actions under Xvfb; skips without Xvfb).
#include <gtest/gtest.h>

#include <fstream>

#include "app/window_test_support.h"
#include "core/primitives.h"
#include "io/mesh_file.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

using testing::run_window;
using testing::WindowRun;
using testing::XServer;
namespace fs = std::filesystem;

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(WindowRepairSpots, ClickingTheBowTiesRowSelectsTheSplitVertex) {
  XServer x;
  if (x.display().empty()) GTEST_SKIP() << "no X server and no Xvfb";
  const fs::path dir = testing::scratch_dir();
  const fs::path file = dir / "cube.obj";
  save_mesh(file, make_cube());
  // Two triangles touching only at file vertex 1 (at 0.5 0.25 0): repaired, it is v0 and its copy for face 1 is v5.
  // Built (mesh_build.h): face 0 is h0 (v0->v1) h1 h2 (v2->v0); its boundary loop starts at h0's twin h6 (v1->v0),
  // then h7 (v0->v2), v0's outgoing boundary halfedge and so its halfedge.
  const fs::path bowtie = dir / "bowtie.obj";
  std::ofstream(bowtie) << "v 0.5 0.25 0\nv 1.5 0.25 0\nv 1.5 1.25 0\nv -0.5 0.25 0\nv -0.5 -0.75 0\n"
                           "f 1 2 3\nf 1 4 5\n";
  const std::string actions =
      "frames 2\nopen " + bowtie.string() +
      "\n"  // line 2: refused
      "open-repaired\nframes 2\n"
      "expect-message the Repairs tab lists each change\n"
      "expect-selected -\n"
      "repair-row 1\nframes 1\n"
      "expect-selected v0\n"
      "expect-field v0 halfedge h7\n"
      "expect-field h7 vertex v0\n"
      "expect-field h7 next h8\n"
      "console string.format('%s at %g %g %g', tostring(selected), selected.position.x, selected.position.y, "
      "selected.position.z)\n"
      "expect-console v0 at 0.5 0.25 0\n"
      "console tostring(selected.halfedge.twin.face)\n"
      "expect-console f0\n"
      "repair-row 2\n"  // line 17: there is one change only
      "select e0\nkey S\nframes 1\nselect v1\n"
      "repair-row 1\n"  // line 22: the mesh was edited, the spots are stale
      "expect-selected v1\n"
      "open " +
      file.string() +
      "\n"
      "repair-row 1\n"  // line 25: another file is open, the Repairs tab is gone
      "quit\n";
  const WindowRun run = run_window(x.display(), file, actions, dir);
  EXPECT_EQ(run.status, 3) << run.output;  // the refused `open` and the two refused rows are failures by design
  EXPECT_TRUE(has(run.output, "actions.txt:2: open failed")) << run.output;
  EXPECT_FALSE(has(run.output, "open-repaired failed")) << run.output;
  EXPECT_FALSE(has(run.output, "expect-message failed")) << run.output;
  EXPECT_FALSE(has(run.output, "expect-selected failed")) << run.output;
  EXPECT_FALSE(has(run.output, "expect-field failed")) << run.output;
  EXPECT_FALSE(has(run.output, "expect-console failed")) << run.output;
  EXPECT_FALSE(has(run.output, "actions.txt:7: repair-row failed")) << run.output;
  EXPECT_TRUE(has(run.output, "actions.txt:17: repair-row failed")) << run.output;
  EXPECT_TRUE(has(run.output, "the Repairs tab has no change 2")) << run.output;
  EXPECT_TRUE(has(run.output, "actions.txt:22: repair-row failed")) << run.output;
  EXPECT_TRUE(has(run.output, "the repaired spots are gone")) << run.output;
  EXPECT_FALSE(has(run.output, "actions.txt:24: open failed")) << run.output;
  EXPECT_TRUE(has(run.output, "actions.txt:25: repair-row failed: the Repairs tab has no change 1")) << run.output;
}

}  // namespace
}  // namespace meshedit
