// `meshedit [FILE] [--actions SCRIPT] [--size WxH]`: the window. Runs the frame loop, feeds dropped files
// to the app, and plays scripted actions (scripted_actions.h) one per frame for GUI tests.
#include <GLFW/glfw3.h>

#include <chrono>
#include <iostream>

#include "app/cli_commands.h"
#include "app/editor_app.h"
#include "app/glfw_window.h"
#include "app/scripted_actions.h"
#include "core/mesh_build.h"
#include "core/primitives.h"
#include "ui/document_actions.h"

namespace meshedit {
namespace {

// Plays scripted actions against the app; counts failed expectations.
class ActionPlayer {
 public:
  ActionPlayer(std::vector<ScriptedAction> actions, std::ostream& log) : actions_(std::move(actions)), log_(log) {}

  bool active() const { return !actions_.empty(); }
  bool finished() const { return next_ >= actions_.size() && wait_frames_ == 0; }
  int failures() const { return failures_; }

  // Runs the next action unless a `frames N` wait is in progress. Returns false once the script asks to quit.
  bool step(EditorApp& app) {
    if (wait_frames_ > 0) {
      --wait_frames_;
      return true;
    }
    // Checks need no frame of their own: run them together with the action before the next one that does.
    while (next_ < actions_.size()) {
      const ScriptedAction& a = actions_[next_++];
      try {
        if (!run(app, a)) return false;
      } catch (const std::exception& e) {
        fail(a, e.what());
      }
      const bool checks_follow = next_ < actions_.size() && actions_[next_].verb.rfind("expect-", 0) == 0;
      if (!checks_follow) return true;
    }
    return false;
  }

 private:
  void fail(const ScriptedAction& a, const std::string& why) {
    ++failures_;
    log_ << a.source << ": " << a.verb << " failed: " << why << "\n";
  }

  static std::string rest_of_line(const ScriptedAction& a) {
    std::string line;
    for (const auto& w : a.args) line += (line.empty() ? "" : " ") + w;
    return line;
  }

  static KeyMods parse_key(std::string text, int& key) {
    KeyMods mods;
    for (;;) {
      if (text.rfind("ctrl+", 0) == 0) { mods.ctrl = true; text = text.substr(5); continue; }
      if (text.rfind("shift+", 0) == 0) { mods.shift = true; text = text.substr(6); continue; }
      break;
    }
    if (text.size() == 1 && std::isalpha(static_cast<unsigned char>(text[0]))) {
      key = GLFW_KEY_A + (std::toupper(static_cast<unsigned char>(text[0])) - 'A');
    } else if (text == "space") {
      key = GLFW_KEY_SPACE;
    } else if (text == "escape") {
      key = GLFW_KEY_ESCAPE;
    } else if (text == "grave") {
      key = GLFW_KEY_GRAVE_ACCENT;
    } else {
      throw std::runtime_error("unknown key '" + text + "'");
    }
    return mods;
  }

  bool run(EditorApp& app, const ScriptedAction& a) {
    const auto& args = a.args;
    if (a.verb == "quit") return false;
    if (a.verb == "frames") {
      wait_frames_ = std::stoi(args[0]);
    } else if (a.verb == "key") {
      int key = 0;
      const KeyMods mods = parse_key(args[0], key);
      app.handle_key(key, mods);
    } else if (a.verb == "select") {
      const auto element = parse_element(args[0]);
      if (!element) throw std::runtime_error("not an element id: '" + args[0] + "'");
      if (!select_element(app.document(), app.selection(), *element)) throw std::runtime_error(args[0] + " is not live");
    } else if (a.verb == "click" || a.verb == "hover") {
      const int x = std::stoi(args[0]), y = std::stoi(args[1]);
      a.verb == "click" ? app.click(x, y) : app.hover(x, y);
    } else if (a.verb == "open") {
      if (!app.open(args[0])) throw std::runtime_error(app.document().message.text);
    } else if (a.verb == "save") {
      if (!app.save(args[0])) throw std::runtime_error(app.document().message.text);
    } else if (a.verb == "orbit") {
      app.camera().orbit(std::stod(args[0]), std::stod(args[1]));
    } else if (a.verb == "expect-gpu-update") {
      const RenderStats& stats = app.mesh_render_stats();
      const std::string got = stats.last_update_patch ? "patch" : "rebuild";
      if (args[0] != "patch" && args[0] != "rebuild") {
        throw std::runtime_error("expect-gpu-update takes patch or rebuild");
      }
      const std::string why = stats.last_update_patch ? "" : " (" + stats.last_rebuild_reason + ")";
      if (got != args[0]) fail(a, "the last update was a " + got + why);
    } else if (a.verb == "screenshot") {
      app.request_screenshot(args[0]);
    } else if (a.verb == "expect-selected") {
      const std::string got = format_id(app.selection().selected);
      if (got != args[0]) fail(a, "selected " + got + ", expected " + args[0]);
    } else if (a.verb == "expect-field") {
      expect_field(app, a);
    } else if (a.verb == "expect-changed") {
      const auto element = parse_element(args[0]);
      const auto field = parse_field(args[1]);
      if (!element || !field) throw std::runtime_error("expect-changed takes an element and a field name");
      if (!app.document().last.index.contains(*element, *field)) {
        fail(a, args[0] + "." + args[1] + " is not among the cells the last operation changed");
      }
    } else if (a.verb == "expect-message") {
      const std::string& got = app.document().message.text;
      if (got.find(rest_of_line(a)) == std::string::npos) fail(a, "status line is '" + got + "'");
    } else if (a.verb == "lesson-next") {
      app.lesson().next();
    } else if (a.verb == "lesson-back") {
      app.lesson().back();
    } else if (a.verb == "lesson-button") {
      if (!app.lesson().deliver(LessonEvent::button(rest_of_line(a)))) fail(a, "the lesson is not waiting for it");
    } else if (a.verb == "expect-lesson-step") {
      const LessonRunner& lesson = app.lesson();
      static const char* const states[] = {"empty", "waiting", "finished", "failed"};
      const std::string got = std::to_string(lesson.current_step() + 1) + " " +
                              states[int(lesson.step_state())];
      if (got != args[0] + " " + args[1]) fail(a, "lesson is at step " + got + " (" + lesson.error() + ")");
    } else if (a.verb == "expect-lesson-said") {
      bool found = false;
      for (const std::string& block : app.lesson().said()) found = found || block.find(rest_of_line(a)) != std::string::npos;
      if (!found) fail(a, "the current step did not say it");
    } else if (a.verb == "exercise") {
      const auto exercise = find_exercise(args[0]);
      if (exercise == Exercise::CurveStep || exercise == Exercise::PatchEvaluate) {
        app.bezier_mine().set_folder(args[1]);
      } else if (!exercise || !app.exercises().set_exercise(*exercise)) {
        throw std::runtime_error("no exercise " + args[0]);
      } else {
        app.exercises().set_folder(args[1]);
      }
    } else if (a.verb == "expect-mine") {
      const BezierMine& mine = app.bezier_mine();
      const bool curve = app.mode() == ViewMode::Curve;
      if (!(curve ? mine.curve_on() : app.mode() == ViewMode::Patches && mine.patch_on())) {
        fail(a, "no \"mine\" switch is on in the view on screen");
      } else if (const std::string& got = curve ? mine.curve().message : mine.patch().message;
                 got.find(rest_of_line(a)) == std::string::npos) {
        fail(a, "the mine line is '" + got + "'");
      }
    } else if (a.verb == "run-mine" || a.verb == "run-reference") {
      ExerciseSession& session = app.exercises();
      const Check check = a.verb == "run-mine" ? session.run_mine(app.document(), app.selection())
                                               : session.run_reference(app.document(), app.selection());
      if (!check) fail(a, check.reason);
    } else if (a.verb == "replay-start") {
      if (const Check check = app.exercises().start_replay(app.document()); !check) fail(a, check.reason);
    } else if (a.verb == "replay-step") {
      const Check check = app.exercises().replay_step(app.document(), std::stoul(args[0]));
      if (!check) fail(a, check.reason);
    } else if (a.verb == "replay-finish") {
      app.exercises().finish_replay(app.document());
    } else if (a.verb == "console") {
      app.run_console(rest_of_line(a));
    } else if (a.verb == "expect-console") {
      const auto& entries = app.console().entries();
      const std::string got = entries.empty() ? "" : entries.back().text;
      if (got.find(rest_of_line(a)) == std::string::npos) fail(a, "the console's last line is '" + got + "'");
    } else if (a.verb == "expect-valid") {
      const ValidationReport& report = cached_validation(app.document());
      if (!report.ok()) fail(a, report.summary());
    }
    return true;
  }

  void expect_field(EditorApp& app, const ScriptedAction& a) {
    const HalfedgeMesh& m = app.document().mesh;
    const auto element = parse_element(a.args[0]);
    if (!element || !m.alive(*element)) throw std::runtime_error(a.args[0] + " is not a live element");
    const std::string& field = a.args[1];
    std::string got = "?";
    if (element->kind == ElementKind::Halfedge) {
      const HalfedgeId h(element->index);
      if (field == "next") got = format_id(m.next(h));
      if (field == "twin") got = format_id(m.twin(h));
      if (field == "vertex") got = format_id(m.vertex(h));
      if (field == "edge") got = format_id(m.edge(h));
      if (field == "face") got = format_id(m.face(h));
    } else if (field == "halfedge") {
      switch (element->kind) {
        case ElementKind::Vertex: got = format_id(m.halfedge(VertexId(element->index))); break;
        case ElementKind::Edge: got = format_id(m.halfedge(EdgeId(element->index))); break;
        default: got = format_id(m.halfedge(element->face_id())); break;
      }
    }
    if (got != a.args[2]) fail(a, a.args[0] + "." + field + " is " + got + ", expected " + a.args[2]);
  }

  std::vector<ScriptedAction> actions_;
  std::ostream& log_;
  size_t next_ = 0;
  int wait_frames_ = 0;
  int failures_ = 0;
};

}  // namespace

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

  GlfwWindow window("MeshEdit", width, height);
  window.set_lazy(!player.active());  // scripted runs step one action per frame
  EditorApp app;
  app.show_mesh(build_halfedge_mesh(make_cube()), "");
  if (!args.empty()) app.open(args[0]);  // on failure the cube stays and the status line says why

  auto last = std::chrono::steady_clock::now();
  float frame_ms = 0.0f;
  while (!window.should_close() && !app.quit_requested()) {
    window.set_lazy(!player.active() && !app.animating());
    window.begin_frame();
    for (const std::string& dropped : window.take_dropped_files()) app.open(dropped);
    app.frame(window.framebuffer_width(), window.framebuffer_height(), frame_ms);
    window.set_title(app.title());
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
