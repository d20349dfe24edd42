// The real window under Xvfb and the up axis: a file is shown with its own (Y for .obj, the tag for COLLADA, Z for the
// course's files), View > Up axis turns the view and refits it (a click lands on the vertex the turned camera puts
// there), and opening a file or a lesson goes back to the file's. Skips without Xvfb; the course-file part skips when
// the course files are absent.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "app/editor_app.h"
#include "app/window_test_support.h"
#include "core/mesh_build.h"
#include "core/primitives.h"
#include "io/file_access.h"
#include "io/mesh_file.h"
#include "render/camera.h"
#include "render/mesh_geometry.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

using testing::run_window;
using testing::WindowRun;
using testing::XServer;
namespace fs = std::filesystem;

// The view's size in pixels when the window shows `file` at 1280x800 (its layout, read back with layout-json).
Viewport view_size(const std::string& display, const fs::path& file, const fs::path& scratch) {
  const fs::path dir = scratch / "view_size";
  fs::create_directories(dir);
  const fs::path out = dir / "layout.json";
  const WindowRun run = run_window(display, file, "frames 2\nlayout-json " + out.string() + "\nquit\n", dir);
  EXPECT_EQ(run.status, 0) << run.output;
  std::ifstream in(out);
  const nlohmann::json layout = nlohmann::json::parse(in);
  return {int(layout["view"][2].get<double>()), int(layout["view"][3].get<double>())};
}

// Where the window's fitted camera with `up` puts vertex v of the cube in a view of that size, as "X Y" view pixels.
std::string cube_vertex_pixel(UpAxis up, VertexId v, Viewport view) {
  const HalfedgeMesh cube = build_halfedge_mesh(make_cube());
  OrbitCamera camera;
  camera.set_up_axis(up);
  camera.fit(mesh_bounds(cube));
  const ScreenPoint p = camera.project(cube.position(v), view);
  EXPECT_TRUE(p.in_front);
  return std::to_string(int(p.pixel.x)) + " " + std::to_string(int(p.pixel.y));
}

// A one-triangle COLLADA file tagged `up_axis`.
std::string tagged_triangle(const std::string& up_axis) {
  return "<COLLADA version=\"1.4.1\">\n<asset><up_axis>" + up_axis +
         "</up_axis></asset>\n<library_geometries>\n<geometry id=\"T\"><mesh><source id=\"T-pos\">"
         "<float_array id=\"a\" count=\"9\">0 0 0 1 0 0 0 1 0</float_array></source><vertices id=\"T-vtx\">"
         "<input semantic=\"POSITION\" source=\"#T-pos\"/></vertices><triangles count=\"1\">"
         "<input semantic=\"VERTEX\" source=\"#T-vtx\" offset=\"0\"/><p>0 1 2</p></triangles></mesh></geometry>\n"
         "</library_geometries>\n</COLLADA>\n";
}

TEST(WindowUpAxis, FilesShowTheirUpAxisAndTheViewMenuTurnsAndRefits) {
  XServer x;
  if (x.display().empty()) GTEST_SKIP() << "no X server and no Xvfb";
  const fs::path dir = testing::scratch_dir();
  const fs::path obj = dir / "cube.obj";
  save_mesh(obj, make_cube());
  write_file(dir / "x.dae", tagged_triangle("X_UP"));
  const fs::path lesson = testing::source_dir() / "lessons" / "welcome.lua";
  // v6 is on the silhouette in both views, at different pixels: a click there picks it only in the view it was
  // computed for.
  const Viewport view = view_size(x.display(), obj, dir);
  const std::string y_pixel = cube_vertex_pixel(UpAxis::Y, VertexId(6), view);
  const std::string z_pixel = cube_vertex_pixel(UpAxis::Z, VertexId(6), view);
  ASSERT_NE(y_pixel, z_pixel);

  std::ostringstream actions;
  actions << "frames 2\n"
          << "expect-up-axis Y Y up (from the file)\n"
          << "click " << y_pixel << "\n"
          << "expect-selected v6\n"
          << "orbit 150 40\n"  // choosing refits: the orbit is gone
          << "up-axis z\n"
          << "expect-up-axis Z Z up (View menu)\n"
          << "frames 2\n"
          << "click " << z_pixel << "\n"
          << "expect-selected v6\n"
          << "up-axis from-file\n"
          << "expect-up-axis Y Y up (from the file)\n"
          << "up-axis z\n"
          << "open " << (dir / "x.dae").string() << "\n"  // a file opened goes back to the file's
          << "expect-up-axis X X up (from the file)\n"
          << "up-axis y\n"
          << "expect-up-axis Y View menu\n"
          << "open " << lesson.string() << "\n"  // a lesson's meshes are Z-up whatever the file before was turned to
          << "frames 2\n"
          << "expect-up-axis Z Z up\n";
  if (const auto data = testing::course_data_dir()) {
    actions << "open " << (*data / "dae" / "cow.dae").string() << "\n"
            << "expect-up-axis Z Z up (course file)\n"
            << "open " << (*data / "dae" / "weird.dae").string() << "\n"
            << "expect-up-axis Z Z up (from the file)\n";
  }
  actions << "quit\n";
  const WindowRun run = run_window(x.display(), obj, actions.str(), dir);
  EXPECT_EQ(run.status, 0) << run.output;
}

TEST(WindowUpAxis, ALessonShowsAMeshReadFromAFileWithTheUpAxisItGives) {
  XServer x;
  if (x.display().empty()) GTEST_SKIP() << "no X server and no Xvfb";
  const fs::path dir = testing::scratch_dir();
  const fs::path lesson = dir / "upright.lua";
  write_file(lesson, R"lua(step("Upright", function()
  show(meshedit.cube(), { up = "y" })
  say "Y up"
end)
step("Made here", function()
  show(meshedit.cube())
  say "Z up"
end)
)lua");
  const Viewport view = view_size(x.display(), lesson, dir);
  std::ostringstream actions;
  actions << "frames 2\n"
          << "expect-up-axis Y Y up (the lesson's)\n"
          << "click " << cube_vertex_pixel(UpAxis::Y, VertexId(6), view) << "\n"  // the camera turned and refitted
          << "expect-selected v6\n"
          << "up-axis z\n"  // the student may still turn it
          << "expect-up-axis Z Z up (View menu)\n"
          << "up-axis from-file\n"
          << "expect-up-axis Y Y up (the lesson's)\n"
          << "lesson-next\n"
          << "frames 2\n"
          << "expect-up-axis Z Z up\n"
          << "lesson-back\n"
          << "frames 2\n"
          << "expect-up-axis Y Y up (the lesson's)\n"
          << "quit\n";
  const WindowRun run = run_window(x.display(), lesson, actions.str(), dir);
  EXPECT_EQ(run.status, 0) << run.output;
}

}  // namespace
}  // namespace meshedit
