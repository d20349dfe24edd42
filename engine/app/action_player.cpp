// Playing scripted actions against the window (see action_player.h).
#include "app/action_player.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cctype>
#include <iterator>
#include <stdexcept>

#include "app/editor_app.h"
#include "app/layout_report.h"
#include "io/file_access.h"
#include "ui/document_actions.h"
#include "ui/exception_report.h"

namespace meshedit {
namespace {

std::string rest_of_line(const ScriptedAction& a) {
  std::string line;
  for (const auto& w : a.args) line += (line.empty() ? "" : " ") + w;
  return line;
}

// Keys named by a word or their character, besides the letters.
struct NamedKey {
  const char* name;
  int key;
};
constexpr NamedKey kNamedKeys[] = {
    {"space", GLFW_KEY_SPACE},  {"escape", GLFW_KEY_ESCAPE}, {"grave", GLFW_KEY_GRAVE_ACCENT},
    {"equal", GLFW_KEY_EQUAL},  {"=", GLFW_KEY_EQUAL},       {"minus", GLFW_KEY_MINUS},
    {"-", GLFW_KEY_MINUS},      {"0", GLFW_KEY_0},           {"[", GLFW_KEY_LEFT_BRACKET},
    {"]", GLFW_KEY_RIGHT_BRACKET},
};

KeyMods parse_key(std::string text, int& key) {
  KeyMods mods;
  for (;;) {
    if (text.rfind("ctrl+", 0) == 0) { mods.ctrl = true; text = text.substr(5); continue; }
    if (text.rfind("shift+", 0) == 0) { mods.shift = true; text = text.substr(6); continue; }
    break;
  }
  if (text.size() == 1 && std::isalpha(static_cast<unsigned char>(text[0]))) {
    key = GLFW_KEY_A + (std::toupper(static_cast<unsigned char>(text[0])) - 'A');
  } else if (const auto named = std::find_if(std::begin(kNamedKeys), std::end(kNamedKeys),
                                             [&](const NamedKey& k) { return text == k.name; });
             named != std::end(kNamedKeys)) {
    key = named->key;
  } else {
    throw std::runtime_error("unknown key '" + text + "'");
  }
  return mods;
}

// Checks of what a drawn frame computed (the mesh view's last geometry update, the curve view's "mine" line): they
// run in the step after the frame that follows the action before them, not in that action's step.
bool reads_a_drawn_frame(const ScriptedAction& a) { return a.verb == "expect-gpu-update" || a.verb == "expect-mine"; }

}  // namespace

bool ActionPlayer::step(EditorApp& app) {
  if (wait_frames_ > 0) {
    --wait_frames_;
    return true;
  }
  // Checks need no frame of their own: run them together with the action before the next one that does (but a check
  // of a drawn frame waits for one).
  while (next_ < actions_.size()) {
    const ScriptedAction& a = actions_[next_++];
    bool quit = false;
    // Between frames, outside the frame guard: the action's failure is counted, and whatever still escapes goes to
    // the status line instead of ending the window.
    run_guarded(app.document(), [&] {
      try {
        quit = !run(app, a);
      } catch (const std::exception& e) {
        fail(a, e.what());
      }
    });
    if (quit) return false;
    const bool checks_follow = next_ < actions_.size() && actions_[next_].verb.rfind("expect-", 0) == 0 &&
                               !reads_a_drawn_frame(actions_[next_]);
    if (!checks_follow) return true;
  }
  return false;
}

void ActionPlayer::fail(const ScriptedAction& a, std::string_view why) {
  ++failures_;  // first: a log that cannot be written (a stream out of memory goes bad) still fails the script
  log_ << a.source << ": " << a.verb << " failed: " << why << "\n";
}

bool ActionPlayer::run(EditorApp& app, const ScriptedAction& a) {
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
  } else if (a.verb == "click-on") {
    const auto element = parse_element(args[0]);
    if (!element) throw std::runtime_error("not an element id: '" + args[0] + "'");
    const std::optional<ScreenPoint> at = app.element_pixel(*element);
    if (!at) throw std::runtime_error(args[0] + " is not on screen");
    app.click(int(at->pixel.x), int(at->pixel.y));
  } else if (a.verb == "window-size") {
    const int width = std::stoi(args[0]), height = std::stoi(args[1]);
    if (width < 1 || height < 1 || width > 16384 || height > 16384) throw std::runtime_error("no window of that size");
    app.request_window_size(width, height);
  } else if (a.verb == "layout-json") {
    write_file(args[0], layout_json(app));
  } else if (a.verb == "open") {
    if (!app.open(args[0])) throw std::runtime_error(app.document().message.text);
  } else if (a.verb == "open-repaired") {
    if (!app.open_repaired()) throw std::runtime_error(app.document().message.text);
  } else if (a.verb == "repair-row") {
    const int row = std::stoi(args[0]);
    if (row < 1) throw std::runtime_error("repair-row counts from 1");
    if (!app.click_repair_row(size_t(row - 1))) throw std::runtime_error(app.document().message.text);
  } else if (a.verb == "triangulate") {
    if (!triangulate_all(app.document(), app.selection()).ok) throw std::runtime_error(app.document().message.text);
  } else if (a.verb == "save") {
    if (!app.save(args[0])) throw std::runtime_error(app.document().message.text);
  } else if (a.verb == "orbit") {
    app.camera().orbit(std::stod(args[0]), std::stod(args[1]));
  } else if (a.verb == "up-axis") {
    if (args[0] == "from-file") app.choose_up_axis(UpAxisChoice::FromFile);
    else if (args[0] == "y") app.choose_up_axis(UpAxisChoice::Y);
    else if (args[0] == "z") app.choose_up_axis(UpAxisChoice::Z);
    else throw std::runtime_error("up-axis takes from-file, y or z");
  } else if (a.verb == "animate-edits") {
    if (args[0] != "on" && args[0] != "off") throw std::runtime_error("animate-edits takes on or off");
    app.set_edit_animation_policy(args[0] == "on" ? EditorApp::EditAnimationPolicy::Always
                                                  : EditorApp::EditAnimationPolicy::Never);
  } else if (a.verb == "expect-up-axis") {
    expect_up_axis(app, a);
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
  } else if (a.verb == "lesson-choose" || a.verb == "lesson-answer") {
    const std::string text = rest_of_line(a);
    const LessonEvent event = a.verb == "lesson-choose" ? LessonEvent::choice(text) : LessonEvent::value(text);
    if (!app.lesson().deliver(event)) {
      fail(a, "the lesson is not asking for it (it waits for " + app.lesson().waiting_for().describe() + ")");
    }
  } else if (a.verb == "expect-lesson-feedback" || a.verb == "expect-lesson-hint") {
    const LessonWait& wait = app.lesson().waiting_for();
    const bool hint = a.verb == "expect-lesson-hint";
    const std::string got = hint ? (wait.hint_shown() ? wait.hint : std::string()) : wait.feedback;
    if (!wait.is_question() && wait.kind != LessonWait::Kind::YourTurn) {
      fail(a, "the lesson asks no question (it waits for " + wait.describe() + ")");
    }
    else if (got.empty() || got.find(rest_of_line(a)) == std::string::npos) {
      fail(a, std::string(hint ? "the hint shown is '" : "the feedback is '") + got + "'");
    }
  } else if (a.verb == "lesson-show-mine") {
    if (const Check check = app.show_your_turn_mine(); !check) fail(a, check.reason);
  } else if (a.verb == "expect-exercise-run") {
    const std::optional<ExerciseRun>& run = app.exercises().last_run();
    const std::string got = run ? run->label + " (" + run->input.describe(run->exercise) + "): " +
                                      (run->mine ? run->report.summary() : "the reference alone")
                                : std::string("none");
    if (got.find(rest_of_line(a)) == std::string::npos) fail(a, "the Exercises tab's last run is '" + got + "'");
  } else if (a.verb == "expect-lesson-live") {
    std::string texts;
    bool found = false;
    for (const LessonLive& live : app.lesson().lives()) {
      const std::string& shown = live.error.empty() ? live.text : live.error;
      found = found || shown.find(rest_of_line(a)) != std::string::npos;
      texts += (texts.empty() ? "'" : ", '") + shown + "'";
    }
    if (!found) fail(a, "the live texts are " + (texts.empty() ? std::string("none") : texts));
  } else if (a.verb == "curve-t") {
    if (app.mode() != ViewMode::Curve) throw std::runtime_error("the curve view is not on screen");
    set_t(app.curve_editor(), std::stod(args[0]));
  } else if (a.verb == "expect-lesson-step") {
    const LessonRunner& lesson = app.lesson();
    static const char* const states[] = {"empty", "waiting", "finished", "failed"};
    const std::string got = std::to_string(lesson.current_step() + 1) + " " +
                            states[int(lesson.step_state())];
    if (got != args[0] + " " + args[1]) fail(a, "lesson is at step " + got + " (" + lesson.error() + ")");
  } else if (a.verb == "expect-lesson-said") {
    bool found = false;
    for (const std::string& block : app.lesson().said()) {
      found = found || block.find(rest_of_line(a)) != std::string::npos;
    }
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

void ActionPlayer::expect_up_axis(EditorApp& app, const ScriptedAction& a) {
  const std::string& wanted = a.args[0];
  if (wanted != "X" && wanted != "Y" && wanted != "Z") throw std::runtime_error("expect-up-axis takes X, Y or Z first");
  const std::string got(up_axis_name(app.camera().up_axis()));
  const std::string status(app.status_up_axis());
  if (got != wanted + " up") fail(a, "the camera is " + got + " (status bar: '" + status + "')");
  std::string text;
  for (size_t i = 1; i < a.args.size(); ++i) text += (text.empty() ? "" : " ") + a.args[i];
  if (status.find(text) == std::string::npos) fail(a, "the status bar says '" + status + "'");
}

void ActionPlayer::expect_field(EditorApp& app, const ScriptedAction& a) {
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

}  // namespace meshedit
