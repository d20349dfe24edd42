// File > Write-up and File > Use this view in the write-up in the real window under Xvfb: the view saved into the
// student's writeup.json names the camera, the mesh file shown and the edge flipped and split in it, by the file's own
// ids; the write-up is made beside the window by `meshedit writeup` (the same pages the command writes), and the
// status line says where it is and which figures have a problem.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "app/window_test_support.h"
#include "core/mesh_build.h"
#include "core/primitives.h"
#include "io/mesh_file.h"
#include "support/test_support.h"
#include "writeup/writeup_settings.h"

namespace meshedit {
namespace {

using testing::run_window;
using testing::WindowRun;
using testing::XServer;
namespace fs = std::filesystem;

// A student folder holding the solutions, with `replaced` put in place of its file.
fs::path student(const fs::path& dir, const std::string& file = "", const fs::path& replaced = {}) {
  const fs::path folder = dir / "student";
  fs::create_directories(folder);
  for (const auto& entry : fs::directory_iterator(testing::source_dir() / "tests" / "exercise" / "solutions")) {
    fs::copy_file(entry.path(), folder / entry.path().filename(), fs::copy_options::overwrite_existing);
  }
  if (!file.empty()) fs::copy_file(replaced, folder / file, fs::copy_options::overwrite_existing);
  return folder;
}

// An interior edge of `mesh` that is a cell's diagonal, the first found.
uint32_t a_diagonal(const HalfedgeMesh& mesh) {
  for (const EdgeId e : mesh.edges()) {
    const HalfedgeId h = mesh.halfedge(e);
    const glm::dvec3 d = mesh.position(mesh.vertex(h)) - mesh.position(mesh.vertex(mesh.twin(h)));
    if (!mesh.is_boundary(e) && d.x != 0.0 && d.y != 0.0) return e.index;
  }
  return 0;
}

TEST(WindowWriteup, TheSavedViewNamesTheMeshAndItsEditsAndTheWriteupIsMadeBesideTheWindow) {
  XServer x;
  if (x.display().empty()) GTEST_SKIP() << "no X server and no Xvfb";
  const fs::path dir = testing::scratch_dir();
  const fs::path folder = student(dir);
  const fs::path grid = dir / "grid.obj";
  save_mesh(grid, make_grid(5, 4));
  const HalfedgeMesh opened = build_halfedge_mesh(load_mesh(grid));
  const uint32_t flipped = a_diagonal(opened);
  uint32_t split = 0;
  for (const EdgeId e : opened.edges()) {
    if (e.index != flipped && !opened.is_boundary(e)) split = e.index;
  }
  const fs::path cube = dir / "cube.obj";
  save_mesh(cube, make_cube());

  std::ostringstream actions;
  actions << "frames 2\n"
          << "exercise flip " << folder.string() << "\n"
          << "open " << grid.string() << "\n"
          << "select e" << flipped << "\n"
          << "command flip\n"
          << "select e" << split << "\n"
          << "command split\n"
          << "orbit 120 -40\n"
          << "command write-up-view\n"
          << "expect-message Saved for the write-up: the camera, grid.obj, 1 flip (e" << flipped << ") and 1 split (e"
          << split << ") (" << (folder / "writeup.json").string() << ")\n"
          << "command write-up\n"
          << "expect-message Making your write-up from your files\n"
          << "frames 3\n"
          << "screenshot " << (dir / "making.png").string() << "\n"
          << "wait-message 3000 Write-up made, every figure by your code: "
          << (folder / "writeup" / "index.html").string() << "\n"
          << "quit\n";
  const WindowRun run = run_window(x.display(), cube, actions.str(), dir);
  EXPECT_EQ(run.status, 0) << run.output;

  const WriteupSettings saved = read_writeup_settings(folder);
  EXPECT_TRUE(saved.problems.empty()) << saved.problems.front();
  ASSERT_TRUE(saved.mesh);
  EXPECT_EQ(fs::weakly_canonical(*saved.mesh), fs::weakly_canonical(grid));
  EXPECT_EQ(saved.flip_edges, std::vector<uint32_t>{flipped});
  EXPECT_EQ(saved.split_edges, std::vector<uint32_t>{split});
  EXPECT_NE(saved.camera.yaw, WriteupCamera{}.yaw);
  EXPECT_NE(saved.camera.pitch, WriteupCamera{}.pitch);
  // The page the window made is the command's: the figures of the chosen mesh and edges.
  const std::string page = testing::read_text(folder / "writeup" / "index.html");
  EXPECT_NE(page.find("after 1 flip"), std::string::npos);
  EXPECT_NE(page.find("after 1 split"), std::string::npos);
  EXPECT_TRUE(fs::is_regular_file(folder / "writeup" / "writeup.md"));
  EXPECT_TRUE(fs::is_regular_file(folder / "writeup" / "figures" / "4.1-b.png"));
}

TEST(WindowWriteup, AWrongFlipIsNamedInTheStatusLineAndSavingTheViewKeepsTheOtherChoices) {
  XServer x;
  if (x.display().empty()) GTEST_SKIP() << "no X server and no Xvfb";
  const fs::path dir = testing::scratch_dir();
  const fs::path folder =
      student(dir, "flip.lua", testing::source_dir() / "tests" / "grading" / "students" / "flip_forgets_faces.lua");
  std::ofstream(folder / "writeup.json") << "{\"levels\": 2, \"split_edges\": [12]}\n";
  const fs::path cube = dir / "cube.obj";
  save_mesh(cube, make_cube());
  std::ostringstream actions;
  actions << "frames 2\n"
          << "exercise flip " << folder.string() << "\n"
          << "command write-up\n"
          << "wait-message 3000 2 figures have problems (4.1, 5.2), the page says why:\n"
          << "command write-up-view\n"
          << "expect-message cube.obj, no flips and no splits\n"
          << "quit\n";
  const WindowRun run = run_window(x.display(), cube, actions.str(), dir);
  EXPECT_EQ(run.status, 0) << run.output;
  const WriteupSettings saved = read_writeup_settings(folder);
  EXPECT_EQ(saved.levels, 2);  // kept
  EXPECT_TRUE(saved.flip_edges.empty());
  EXPECT_TRUE(saved.split_edges.empty());  // the cube's, none, in place of the grid's e12
  ASSERT_TRUE(saved.mesh);
  EXPECT_EQ(saved.mesh->filename(), "cube.obj");
}

TEST(WindowWriteup, TheItemStopsAWriteupThatRunsAStudentsEndlessLoop) {
  XServer x;
  if (x.display().empty()) GTEST_SKIP() << "no X server and no Xvfb";
  const fs::path dir = testing::scratch_dir();
  const fs::path folder =
      student(dir, "flip.lua", testing::source_dir() / "tests" / "web" / "runaway_student" / "loop" / "flip.lua");
  const fs::path cube = dir / "cube.obj";
  save_mesh(cube, make_cube());
  std::ostringstream actions;
  actions << "frames 2\n"
          << "exercise flip " << folder.string() << "\n"
          << "command write-up\n"
          << "frames 30\n"
          << "expect-message Making your write-up\n"  // the window draws on while the loop runs
          << "command write-up\n"
          << "expect-message The write-up was stopped before it was written\n"
          << "quit\n";
  const WindowRun run = run_window(x.display(), cube, actions.str(), dir);
  EXPECT_EQ(run.status, 0) << run.output;
  EXPECT_FALSE(fs::exists(folder / "writeup" / "index.html"));
}

}  // namespace
}  // namespace meshedit
