// The real window under Xvfb, driven by scripted actions (engine/app/scripted_actions.h): pick a vertex by
// clicking where it is drawn, select an edge, flip it with F, check every pointer the flip wrote, undo it
// with Ctrl+Z and check they are back, and save a screenshot. Starts its own Xvfb when DISPLAY is unset;
// skips when there is no Xvfb at all.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <set>
#include <sstream>

#include "app/editor_app.h"
#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/primitives.h"
#include "io/mesh_file.h"
#include "render/camera.h"
#include "render/image_file.h"
#include "render/mesh_geometry.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;

// An X server for the test: the existing DISPLAY, or an Xvfb started here and stopped at the end.
class XServer {
 public:
  XServer() {
    if (const char* display = std::getenv("DISPLAY"); display && *display) {
      display_ = display;
      return;
    }
    if (std::system("command -v Xvfb >/dev/null 2>&1") != 0) return;
    for (int number = 90 + int(::getpid() % 50); number < 200; ++number) {
      if (fs::exists("/tmp/.X11-unix/X" + std::to_string(number)) || fs::exists("/tmp/.X" + std::to_string(number) + "-lock")) continue;
      pid_ = ::fork();
      if (pid_ == 0) {
        const std::string name = ":" + std::to_string(number);
        ::execlp("Xvfb", "Xvfb", name.c_str(), "-screen", "0", "1280x800x24", "-nolisten", "tcp", (char*)nullptr);
        ::_exit(127);
      }
      for (int tries = 0; tries < 100 && !fs::exists("/tmp/.X11-unix/X" + std::to_string(number)); ++tries) {
        ::usleep(50000);
      }
      if (fs::exists("/tmp/.X11-unix/X" + std::to_string(number))) display_ = ":" + std::to_string(number);
      return;
    }
  }
  ~XServer() {
    if (pid_ > 0) {
      ::kill(pid_, SIGTERM);
      ::waitpid(pid_, nullptr, 0);
    }
  }
  const std::string& display() const { return display_; }

 private:
  std::string display_;
  pid_t pid_ = -1;
};

struct WindowRun {
  int status = -1;
  std::string output;
};

WindowRun run_window(const std::string& display, const fs::path& mesh, const std::string& actions, const fs::path& dir) {
  const fs::path script = dir / "actions.txt";
  std::ofstream(script) << actions;
  const fs::path log = dir / "log.txt";
  const std::string command = "DISPLAY=" + display + " timeout 120 '" + std::string(MESHEDIT_BINARY) + "' '" +
                              mesh.string() + "' --size 1280x800 --actions '" + script.string() + "' >'" +
                              log.string() + "' 2>&1";
  WindowRun run;
  const int raw = std::system(command.c_str());
  run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  run.output = text.str();
  return run;
}

// `expect-field` lines for every pointer of every live element of `mesh`.
std::string expect_every_pointer(const HalfedgeMesh& mesh) {
  std::ostringstream out;
  for (HalfedgeId h : mesh.halfedges()) {
    out << "expect-field " << format_id(h) << " next " << format_id(mesh.next(h)) << "\n"
        << "expect-field " << format_id(h) << " twin " << format_id(mesh.twin(h)) << "\n"
        << "expect-field " << format_id(h) << " vertex " << format_id(mesh.vertex(h)) << "\n"
        << "expect-field " << format_id(h) << " edge " << format_id(mesh.edge(h)) << "\n"
        << "expect-field " << format_id(h) << " face " << format_id(mesh.face(h)) << "\n";
  }
  for (VertexId v : mesh.vertices()) out << "expect-field " << format_id(v) << " halfedge " << format_id(mesh.halfedge(v)) << "\n";
  for (FaceId f : mesh.faces()) out << "expect-field " << format_id(f) << " halfedge " << format_id(mesh.halfedge(f)) << "\n";
  return out.str();
}

TEST(Window, PickFlipUndoAndScreenshotOnTheCube) {
  XServer x;
  if (x.display().empty()) GTEST_SKIP() << "no X server and no Xvfb";
  const fs::path dir = testing::scratch_dir();
  const fs::path file = dir / "cube.obj";
  save_mesh(file, make_cube());

  // Where v7 lands on screen: the window fits its camera (Z up, the default) the same way at 1280x800.
  const HalfedgeMesh before = build_halfedge_mesh(make_cube());
  OrbitCamera camera;
  camera.fit(mesh_bounds(before));
  camera.zoom(-EditorApp::kFitZoomOutSteps);
  const ScreenPoint v7 = camera.project(before.position(VertexId(7)), {1280, 800});
  ASSERT_TRUE(v7.in_front);

  HalfedgeMesh flipped = before;
  const EdgeId e(7);
  ASSERT_TRUE(flip(flipped, e).ok());

  std::ostringstream actions;
  actions << "frames 3\n"
          << "click " << int(v7.pixel.x) << " " << int(v7.pixel.y) << "\n"
          << "expect-selected v7\n"
          << "select e7\n"
          << "key F\n"
          << "expect-selected e7\n"
          << "expect-changed h" << before.halfedge(e).index << " next\n"
          << expect_every_pointer(flipped) << "expect-valid\n"
          << "frames 2\n"
          << "screenshot " << (dir / "flipped.png").string() << "\n"
          << "frames 2\n"
          << "key ctrl+Z\n"
          << expect_every_pointer(before) << "expect-message undo flip e7\n"
          << "quit\n";
  const WindowRun run = run_window(x.display(), file, actions.str(), dir);
  EXPECT_EQ(run.status, 0) << run.output;

  const Image shot = read_png(dir / "flipped.png");
  EXPECT_EQ(shot.width, 1280);
  EXPECT_EQ(shot.height, 800);
  // Not blank: the background, the faces, the panels and the highlight give many distinct colours.
  std::set<uint32_t> colours;
  for (size_t i = 0; i + 3 < shot.rgba.size(); i += 4 * 97) {
    colours.insert(uint32_t(shot.rgba[i]) << 16 | uint32_t(shot.rgba[i + 1]) << 8 | shot.rgba[i + 2]);
  }
  EXPECT_GT(colours.size(), 20u);
}

TEST(Window, ABadFileKeepsTheCurrentMeshAndSaysWhy) {
  XServer x;
  if (x.display().empty()) GTEST_SKIP() << "no X server and no Xvfb";
  const fs::path dir = testing::scratch_dir();
  const fs::path file = dir / "cube.obj";
  save_mesh(file, make_cube());
  const fs::path bad = dir / "bad.obj";
  std::ofstream(bad) << "v 0 0 0\nv 1 0 0\nf 1 2 3\n";
  const std::string actions = "frames 2\nselect e3\nopen " + bad.string() +
                              "\nexpect-message bad.obj:3\nexpect-selected e3\nexpect-valid\n"
                              "open /no/such/file.obj\nexpect-message cannot open\nquit\n";
  // `open` of a bad file is an action failure by design: the run reports it, and the state must survive.
  const WindowRun run = run_window(x.display(), file, actions, dir);
  EXPECT_EQ(run.status, 3) << run.output;
  EXPECT_NE(run.output.find("actions.txt:3: open failed"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("expect-selected failed"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("expect-valid failed"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("expect-message failed"), std::string::npos) << run.output;
}

TEST(Window, TheConsoleFlipsTheSelectedEdgeAndCtrlZUndoesIt) {
  XServer x;
  if (x.display().empty()) GTEST_SKIP() << "no X server and no Xvfb";
  const fs::path dir = testing::scratch_dir();
  const fs::path file = dir / "cube.obj";
  save_mesh(file, make_cube());
  const HalfedgeMesh before = build_halfedge_mesh(make_cube());
  HalfedgeMesh flipped = before;
  ASSERT_TRUE(flip(flipped, EdgeId(7)).ok());

  std::ostringstream actions;
  actions << "frames 2\n"
          << "select e7\n"
          << "console tostring(selected) .. ' of ' .. mesh:num_faces()\n"
          << "expect-console e7 of 12\n"
          << "console mesh:flip(selected)\n"
          << "expect-console e7\n"
          << "expect-message console: mesh:flip(selected)\n"
          << expect_every_pointer(flipped) << "expect-valid\n"
          << "console nosuch()\n"
          << "expect-console console:1: attempt to call a nil value (global 'nosuch')\n"
          << "frames 2\n"
          << "screenshot " << (dir / "console.png").string() << "\n"
          << "frames 2\n"
          << "key ctrl+Z\n"
          << expect_every_pointer(before) << "quit\n";
  const WindowRun run = run_window(x.display(), file, actions.str(), dir);
  EXPECT_EQ(run.status, 0) << run.output;
  EXPECT_EQ(read_png(dir / "console.png").width, 1280);
}

}  // namespace
}  // namespace meshedit
