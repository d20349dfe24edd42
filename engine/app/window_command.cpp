// `meshedit [FILE] [--actions SCRIPT] [--size WxH] [--suite SUITE.lua] [--check]`: the window. Runs the frame loop,
// feeds dropped files to the app, and plays scripted actions (action_player.h) one per frame for GUI tests. --suite is
// the suite File > Check my work runs instead of the course's (check_room.h); --check starts Check my work as the
// window opens (a page's ?check).
//
// Settings (document/settings.h) are read at start and written when the window closes: the window opens at the size it
// had (never larger than the screen's work area), with the columns, text size and theme it had. --size opens it at
// that size exactly and is not remembered. A settings file that cannot be read or written is a warning on stderr.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <utility>

#include "app/action_player.h"
#include "app/cli_commands.h"
#include "app/editor_app.h"
#include "app/glfw_window.h"
#include "app/scripted_actions.h"
#include "app/window_host.h"
#include "document/exception_report.h"

namespace meshedit {

namespace {

// Writes what the window ends with: the app's settings (the size they were read with, when `remember_size` is off or
// the window is minimised), or a warning on stderr when the file cannot be written.
void save_settings(const std::filesystem::path& file, const EditorApp& app, const GlfwWindow& window,
                   bool remember_size) {
  if (file.empty()) return;
  Settings kept = app.settings();
  if (remember_size && window.width() > 0 && window.height() > 0) {
    kept.window_width = std::clamp(window.width(), Settings::kMinWindowWidth, Settings::kMaxWindowSide);
    kept.window_height = std::clamp(window.height(), Settings::kMinWindowHeight, Settings::kMaxWindowSide);
  }
  if (const std::string why = write_settings(file, kept); !why.empty()) {
    std::cerr << "meshedit: settings not saved: " << why << "\n";
  }
}

// The settings file's settings, each problem with it a warning on stderr.
Settings read_settings_warning(const std::filesystem::path& file) {
  std::vector<std::string> warnings;
  Settings settings = read_settings(file, warnings);
  for (const std::string& warning : warnings) std::cerr << "meshedit: settings: " << warning << "\n";
  return settings;
}

// --size WxH, or a UsageError.
void read_size(const std::string& size, int& width, int& height) {
  if (std::sscanf(size.c_str(), "%dx%d", &width, &height) != 2 || width < 200 || height < 150 || width > 16384 ||
      height > 16384) {
    throw UsageError("--size must look like 1280x800");
  }
}

}  // namespace

int run_window(const std::vector<std::string>& arguments, std::ostream& out) {
  std::vector<std::string> args = arguments;
  const auto script = take_option(args, "--actions");
  const auto size = take_option(args, "--size");
  const auto suite = take_option(args, "--suite");
  const bool check_at_start = take_flag(args, "--check");
  reject_unknown_options(args);
  if (suite && !std::filesystem::is_regular_file(*suite)) throw UsageError("--suite " + *suite + ": no such file");
  if (args.size() > 1) throw UsageError("the window opens at most one file");
  const std::filesystem::path settings_file = settings_path();
  const Settings settings = read_settings_warning(settings_file);
  int width = settings.window_width, height = settings.window_height;
  if (size) read_size(*size, width, height);
  // Everything the frames use lives on the heap: in a page the browser runs the frames after this call has returned
  // (window_host.h).
  struct WindowRun {
    WindowRun(std::vector<ScriptedAction> actions, const std::string& title, int w, int h, bool fit)
        : player(std::move(actions), std::cerr), window(title, w, h, fit) {}
    ActionPlayer player;
    GlfwWindow window;
    EditorApp app;
    std::chrono::steady_clock::time_point last = std::chrono::steady_clock::now();
    float frame_ms = 0.0f;
    int status = 0;
  };
  auto run = std::make_shared<WindowRun>(script ? read_actions(*script) : std::vector<ScriptedAction>{},
                                         DocumentRoom::kStartTitle, width, height, /*fit_to_screen=*/!size);
  run->window.set_lazy(!run->player.active());  // scripted runs step one action per frame
  run->app.panels().apply_settings(settings);
  if (suite) run->app.check_room().set_suite(std::filesystem::absolute(*suite));
  // Edits animate in a window a person uses, as the settings say; a scripted run only after `animate-edits on`.
  if (!run->player.active()) run->app.view().set_edit_animation_policy(EditAnimationPolicy::AsSettingSays);
  run->app.show_start_mesh();  // out of memory: an empty window that says so (editor_app.h)
  // On failure the cube (or the empty start) stays and the status line says why.
  if (!args.empty()) run->app.open(args[0]);
  if (check_at_start) run->app.run_command(CommandId::CheckMyWork);

  const auto frame = [run] {
    ActionPlayer& player = run->player;
    GlfwWindow& window = run->window;
    EditorApp& app = run->app;
    if (window.should_close() || app.quit_requested()) {
      if (app.may_close()) return false;
      window.cancel_close();  // the app asks about unsaved code first
    }
    window.set_lazy(!player.active() && !app.animating());
    if (const auto resize = app.take_window_size_request()) window.set_size(resize->first, resize->second);
    const bool look_changed = app.panels().take_look_change();  // both taken: each clears its flag
    const bool scale_changed = window.take_content_scale_changed();
    if (look_changed || scale_changed) {
      const FontsLoaded fonts = window.apply_look(app.settings().font_px, app.settings().theme);
      if (!fonts.warning.empty()) std::cerr << "meshedit: " << fonts.warning << "\n";
      app.panels().fonts_applied(fonts);
    }
    window.begin_frame();
    app.open_dropped(window.take_dropped_files());
    app.receive_files(host_take_received_files());  // a page's picked and dropped files (window_host.h)
    if (window.take_drop_lost()) set_memory_ran_out_message(app.document(), Severity::Error);
    app.frame(window.framebuffer_width(), window.framebuffer_height(), run->frame_ms);
    run_guarded(app.document(), [&] { window.set_title(app.title()); });  // outside the frame guard; allocates
    window.end_frame([&] { app.after_rendering(window.framebuffer_width(), window.framebuffer_height()); });
    const auto now = std::chrono::steady_clock::now();
    // The frame's own work: the time waiting for input is not the view's cost (the quality governor reads this).
    run->frame_ms =
        std::max(0.0f, std::chrono::duration<float, std::milli>(now - run->last).count() - window.last_wait_ms());
    run->last = now;
    return !(player.active() && !player.step(app));
  };
  const auto finish = [run, settings_file, remember_size = !size, &out] {
    save_settings(settings_file, run->app, run->window, remember_size);
    if (run->player.active()) {
      out << "actions: " << (run->player.failures() == 0 ? "all expectations held" : "some expectations failed")
          << "\n";
      run->status = run->player.failures() == 0 ? 0 : 3;
    }
  };
  run_frame_loop(frame, finish);
  return run->status;
}

}  // namespace meshedit
