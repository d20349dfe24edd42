// `meshedit [FILE] [--actions SCRIPT] [--size WxH]`: the window. Runs the frame loop, feeds dropped files
// to the app, and plays scripted actions (action_player.h) one per frame for GUI tests.
#include <chrono>
#include <cstdio>
#include <iostream>

#include "app/action_player.h"
#include "app/cli_commands.h"
#include "app/editor_app.h"
#include "app/glfw_window.h"
#include "app/scripted_actions.h"
#include "ui/exception_report.h"

namespace meshedit {

int run_window(const std::vector<std::string>& arguments, std::ostream& out) {
  std::vector<std::string> args = arguments;
  const auto script = take_option(args, "--actions");
  const std::string size = take_option(args, "--size").value_or("1280x800");
  reject_unknown_options(args);
  if (args.size() > 1) throw UsageError("the window opens at most one file");
  int width = 1280, height = 800;
  if (std::sscanf(size.c_str(), "%dx%d", &width, &height) != 2 || width < 200 || height < 150 || width > 16384 ||
      height > 16384) {
    throw UsageError("--size must look like 1280x800");
  }
  ActionPlayer player(script ? read_actions(*script) : std::vector<ScriptedAction>{}, std::cerr);

  GlfwWindow window(EditorApp::kStartTitle, width, height);
  window.set_lazy(!player.active());  // scripted runs step one action per frame
  EditorApp app;
  app.show_start_mesh();  // out of memory: an empty window that says so (editor_app.h)
  if (!args.empty()) app.open(args[0]);  // on failure the cube (or the empty start) stays and the status line says why

  auto last = std::chrono::steady_clock::now();
  float frame_ms = 0.0f;
  while (!window.should_close() && !app.quit_requested()) {
    window.set_lazy(!player.active() && !app.animating());
    window.begin_frame();
    app.open_dropped(window.take_dropped_files());
    if (window.take_drop_lost()) set_memory_ran_out_message(app.document(), Severity::Error);
    app.frame(window.framebuffer_width(), window.framebuffer_height(), frame_ms);
    run_guarded(app.document(), [&] { window.set_title(app.title()); });  // outside the frame guard; allocates
    window.end_frame([&] { app.write_pending_screenshot(window.framebuffer_width(), window.framebuffer_height()); });
    const auto now = std::chrono::steady_clock::now();
    frame_ms = std::chrono::duration<float, std::milli>(now - last).count();
    last = now;
    if (player.active() && !player.step(app)) break;
  }
  if (player.active()) {
    out << "actions: " << (player.failures() == 0 ? "all expectations held" : "some expectations failed") << "\n";
    return player.failures() == 0 ? 0 : 3;
  }
  return 0;
}

}  // namespace meshedit
