// Shared by the window tests: an X server (the existing DISPLAY or an Xvfb started for the test), running
// the real binary with a scripted-actions file, and `expect-field` lines for every pointer of a mesh.
#pragma once

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/halfedge_mesh.h"

namespace meshedit::testing {

namespace fs = std::filesystem;

// An X server for the test: the existing DISPLAY, or an Xvfb started here and stopped at the end. Given a screen
// size ("1024x640"), always an Xvfb of its own with a screen of that size.
class XServer {
 public:
  explicit XServer(const std::string& screen = "") {
    if (const char* display = std::getenv("DISPLAY"); screen.empty() && display && *display) {
      display_ = display;
      return;
    }
    const std::string screen_depth = (screen.empty() ? std::string("1280x800") : screen) + "x24";
    if (std::system("command -v Xvfb >/dev/null 2>&1") != 0) return;
    // Two tests started together may pick the same number: the Xvfb that loses the lock exits, and its test tries
    // the next number instead of borrowing the winner's server (which goes away when the winner's test ends).
    for (int number = 90 + int(::getpid() % 50); number < 200; ++number) {
      const std::string socket = "/tmp/.X11-unix/X" + std::to_string(number);
      if (fs::exists(socket) || fs::exists("/tmp/.X" + std::to_string(number) + "-lock")) continue;
      pid_ = ::fork();
      if (pid_ == 0) {
        const std::string name = ":" + std::to_string(number);
        // -noreset: the root window's properties (a test's Xft.dpi) outlive the client that set them.
        ::execlp("Xvfb", "Xvfb", name.c_str(), "-screen", "0", screen_depth.c_str(), "-nolisten", "tcp", "-noreset",
                 (char*)nullptr);
        ::_exit(127);
      }
      bool exited = false;
      for (int tries = 0; tries < 100 && !fs::exists(socket); ++tries) {
        if (::waitpid(pid_, nullptr, WNOHANG) == pid_) {
          exited = true;
          break;
        }
        ::usleep(50000);
      }
      if (!exited && ::waitpid(pid_, nullptr, WNOHANG) == pid_) exited = true;
      if (exited) {
        pid_ = -1;
        continue;
      }
      if (fs::exists(socket)) display_ = ":" + std::to_string(number);
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

// Runs the window on `mesh` with the actions. `size` is the --size option ("" for none: the window opens at the size
// its settings remember, within the screen); `environment` goes before the command ("NAME=value ...").
inline WindowRun run_window(const std::string& display, const fs::path& mesh, const std::string& actions,
                            const fs::path& dir, const std::string& size = "1280x800",
                            const std::string& environment = "") {
  const fs::path script = dir / "actions.txt";
  std::ofstream(script) << actions;
  const fs::path log = dir / "log.txt";
  // Settings live in the test's folder: no test reads or changes another's (or the user's) settings. The locale is
  // English unless `environment` names another (a window with no language chosen follows it).
  const std::string command = "XDG_CONFIG_HOME='" + dir.string() + "' LC_ALL= LC_MESSAGES= LANG=C.UTF-8 " +
                              environment + " DISPLAY=" + display + " timeout 120 '" + std::string(MESHEDIT_BINARY) +
                              "' '" + mesh.string() + "'" + (size.empty() ? std::string() : " --size " + size) +
                              " --actions '" + script.string() + "' >'" + log.string() + "' 2>&1";
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
inline std::string expect_every_pointer(const HalfedgeMesh& mesh) {
  std::ostringstream out;
  for (HalfedgeId h : mesh.halfedges()) {
    out << "expect-field " << format_id(h) << " next " << format_id(mesh.next(h)) << "\n"
        << "expect-field " << format_id(h) << " twin " << format_id(mesh.twin(h)) << "\n"
        << "expect-field " << format_id(h) << " vertex " << format_id(mesh.vertex(h)) << "\n"
        << "expect-field " << format_id(h) << " edge " << format_id(mesh.edge(h)) << "\n"
        << "expect-field " << format_id(h) << " face " << format_id(mesh.face(h)) << "\n";
  }
  for (VertexId v : mesh.vertices())
    out << "expect-field " << format_id(v) << " halfedge " << format_id(mesh.halfedge(v)) << "\n";
  for (FaceId f : mesh.faces())
    out << "expect-field " << format_id(f) << " halfedge " << format_id(mesh.halfedge(f)) << "\n";
  return out.str();
}

}  // namespace meshedit::testing
