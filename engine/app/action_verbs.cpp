// The scripted actions' verbs and their handlers (see action_verbs.h).
//
// Sections: keys | the verbs' handlers (view, files and edits; lessons; exercises; checks) | the table
#include "app/action_verbs.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iterator>
#include <optional>
#include <stdexcept>

#include "app/editor_app.h"
#include "app/layout_report.h"
#include "app/window_host.h"
#include "core/translation.h"
#include "document/document_actions.h"
#include "document/mesh_edits.h"
#include "exercise/exercise_registry.h"
#include "io/file_access.h"

namespace meshedit {
namespace {

using Action = ScriptedAction;

// "" when `got` contains `wanted`, else `what` followed by the text found.
std::string expect_contains(const std::string& wanted, const std::string& got, const std::string& what) {
  return got.find(wanted) == std::string::npos ? what + " '" + got + "'" : "";
}

ElementRef element_argument(const std::string& text) {
  const auto element = parse_element(text);
  if (!element) throw std::runtime_error("not an element id: '" + text + "'");
  return *element;
}

// ---- keys ----------------------------------------------------------------------------------------------------

// Keys named by a word or their character, besides the letters.
struct NamedKey {
  const char* name;
  int key;
};
constexpr NamedKey kNamedKeys[] = {
    {"space", GLFW_KEY_SPACE},     {"escape", GLFW_KEY_ESCAPE}, {"grave", GLFW_KEY_GRAVE_ACCENT},
    {"equal", GLFW_KEY_EQUAL},     {"=", GLFW_KEY_EQUAL},       {"minus", GLFW_KEY_MINUS},
    {"-", GLFW_KEY_MINUS},         {"0", GLFW_KEY_0},           {"[", GLFW_KEY_LEFT_BRACKET},
    {"]", GLFW_KEY_RIGHT_BRACKET}, {"f1", GLFW_KEY_F1},
};

KeyMods parse_key(std::string text, int& key) {
  KeyMods mods;
  for (;;) {
    if (text.rfind("ctrl+", 0) == 0) {
      mods.ctrl = true;
      text = text.substr(5);
      continue;
    }
    if (text.rfind("shift+", 0) == 0) {
      mods.shift = true;
      text = text.substr(6);
      continue;
    }
    break;
  }
  if (text.size() == 1 && std::isalpha(static_cast<unsigned char>(text[0]))) {
    key = GLFW_KEY_A + (std::toupper(static_cast<unsigned char>(text[0])) - 'A');
  } else if (const auto* const named = std::find_if(std::begin(kNamedKeys), std::end(kNamedKeys),
                                                    [&](const NamedKey& k) { return text == k.name; });
             named != std::end(kNamedKeys)) {
    key = named->key;
  } else {
    throw std::runtime_error("unknown key '" + text + "'");
  }
  return mods;
}

// ---- view, files and edits -------------------------------------------------------------------------------------

std::string press_key(EditorApp& app, const Action& a) {
  int key = 0;
  const KeyMods mods = parse_key(a.args[0], key);
  app.handle_key(key, mods);
  return "";
}

std::string select(EditorApp& app, const Action& a) {
  if (!select_element(app.document(), app.selection(), element_argument(a.args[0]))) {
    throw std::runtime_error(a.args[0] + " is not live");
  }
  return "";
}

std::string click(EditorApp& app, const Action& a) {
  app.click(std::stoi(a.args[0]), std::stoi(a.args[1]));
  return "";
}

std::string hover(EditorApp& app, const Action& a) {
  app.input().hover(std::stoi(a.args[0]), std::stoi(a.args[1]));
  return "";
}

std::string click_on(EditorApp& app, const Action& a) {
  const std::optional<ScreenPoint> at = app.view().element_pixel(element_argument(a.args[0]));
  if (!at) throw std::runtime_error(a.args[0] + " is not on screen");
  app.click(int(at->pixel.x), int(at->pixel.y));
  return "";
}

std::string window_size(EditorApp& app, const Action& a) {
  const int width = std::stoi(a.args[0]), height = std::stoi(a.args[1]);
  if (width < 1 || height < 1 || width > 16384 || height > 16384) throw std::runtime_error("no window of that size");
  app.request_window_size(width, height);
  return "";
}

std::string write_layout(EditorApp& app, const Action& a) {
  write_file(a.args[0], layout_json(app));
  return "";
}

// What the status line says about an action that did not happen, thrown.
void throw_message(EditorApp& app) { throw std::runtime_error(app.document().message.text); }

std::string open(EditorApp& app, const Action& a) {
  if (!app.open(a.args[0])) throw_message(app);
  return "";
}

std::string open_picker(EditorApp&, const Action&) {
  if (!host_has_file_picker()) throw std::runtime_error("this window has no file picker of its own (use open PATH)");
  host_show_file_picker();
  return "";
}

// A command of the table run as its menu item runs it; throws why it was not done.
void run(EditorApp& app, CommandId id) {
  if (const Check done = app.run_command(id); !done) throw std::runtime_error(done.reason);
}

std::string open_repaired(EditorApp& app, const Action&) {
  run(app, CommandId::OpenRepaired);
  return "";
}

std::string save(EditorApp& app, const Action& a) {
  if (!app.document_room().save(a.args[0])) throw_message(app);
  return "";
}

std::string bug_report(EditorApp& app, const Action& a) { return app.bug_report_room().save(a.args[0]).reason; }

std::string bug_report_send(EditorApp& app, const Action& a) {
  if (a.args[1] != "yes" && a.args[1] != "no") throw std::runtime_error("bug-report-send takes FILE yes|no");
  app.bug_report_room().choose_file(a.args[0], a.args[1] == "yes");
  return "";
}

std::string repair_row(EditorApp& app, const Action& a) {
  const int row = std::stoi(a.args[0]);
  if (row < 1) throw std::runtime_error("repair-row counts from 1");
  if (!app.click_repair_row(size_t(row - 1))) throw_message(app);
  return "";
}

std::string triangulate(EditorApp& app, const Action&) {
  run(app, CommandId::Triangulate);
  return "";
}

template <bool OnePhase>
std::string subdivide(EditorApp& app, const Action& a) {
  const std::optional<SubdivisionScheme> scheme = scheme_named(a.args[0]);
  if (!scheme) throw std::runtime_error(a.verb + " takes " + scheme_names());
  run(app, subdivide_command(*scheme, OnePhase));
  return "";
}

std::string run_named_command(EditorApp& app, const Action& a) {
  const Command* named = find_command(a.args[0]);
  if (!named) throw std::runtime_error("no command '" + a.args[0] + "' (the names are document/command_table.h's)");
  run(app, named->id);
  return "";
}

std::string orbit(EditorApp& app, const Action& a) {
  app.view().camera().orbit(std::stod(a.args[0]), std::stod(a.args[1]));
  return "";
}

std::string up_axis(EditorApp& app, const Action& a) {
  const std::string& which = a.args[0];
  if (which == "from-file") app.view().choose_up_axis(UpAxisChoice::FromFile);
  else if (which == "y") app.view().choose_up_axis(UpAxisChoice::Y);
  else if (which == "z") app.view().choose_up_axis(UpAxisChoice::Z);
  else throw std::runtime_error("up-axis takes from-file, y or z");
  return "";
}

std::string language(EditorApp& app, const Action& a) {
  const std::optional<Language> chosen = language_by_code(a.args[0]);
  if (!chosen || a.args[0] != language_code(*chosen)) throw std::runtime_error("language takes en or zh");
  app.panels().set_language(*chosen);
  return "";
}

std::string animate_edits(EditorApp& app, const Action& a) {
  if (a.args[0] != "on" && a.args[0] != "off") throw std::runtime_error("animate-edits takes on or off");
  app.view().set_edit_animation_policy(a.args[0] == "on" ? EditAnimationPolicy::Always : EditAnimationPolicy::Never);
  return "";
}

std::string quality(EditorApp& app, const Action& a) {
  if (a.args[0] != "full" && a.args[0] != "auto") throw std::runtime_error("quality takes full or auto");
  app.view().hold_full_quality(a.args[0] == "full");
  return "";
}

std::string screenshot(EditorApp& app, const Action& a) {
  app.request_screenshot(a.args[0]);
  return "";
}

std::string console(EditorApp& app, const Action& a) {
  app.run_console(a.words());
  return "";
}

std::string curve_t(EditorApp& app, const Action& a) {
  if (app.mode() != ViewMode::Curve) throw std::runtime_error("the curve view is not on screen");
  set_t(app.view().curve(), std::stod(a.args[0]));
  return "";
}

std::string patch_uv(EditorApp& app, const Action& a) {
  if (app.mode() != ViewMode::Patches) throw std::runtime_error("the patch view is not on screen");
  set_probe(app.view().patches(), std::stod(a.args[0]), std::stod(a.args[1]));
  return "";
}

// A click on the canvas away from the control points, taken in the next frame as the mouse's would be.
std::string curve_click(EditorApp& app, const Action& a) {
  if (app.mode() != ViewMode::Curve) throw std::runtime_error("the curve view is not on screen");
  app.view().curve().clicked = glm::dvec2(std::stod(a.args[0]), std::stod(a.args[1]));
  return "";
}

// ---- lessons ---------------------------------------------------------------------------------------------------

std::string lesson_next(EditorApp& app, const Action&) {
  app.lesson().next();
  return "";
}

std::string lesson_back(EditorApp& app, const Action&) {
  app.lesson().back();
  return "";
}

std::string lesson_button(EditorApp& app, const Action& a) {
  return app.lesson().deliver(LessonEvent::button(a.words())) ? "" : "the lesson is not waiting for it";
}

template <bool Choose>
std::string lesson_reply(EditorApp& app, const Action& a) {
  const std::string text = a.words();
  if (app.lesson().deliver(Choose ? LessonEvent::choice(text) : LessonEvent::value(text))) return "";
  return "the lesson is not asking for it (it waits for " + app.lesson().waiting_for().describe() + ")";
}

std::string lesson_show_mine(EditorApp& app, const Action&) { return app.show_your_turn_mine().reason; }

template <bool Hint>
std::string expect_lesson_feedback(EditorApp& app, const Action& a) {
  const LessonWait& wait = app.lesson().waiting_for();
  const std::string got = Hint ? (wait.hint_shown() ? wait.hint : std::string()) : wait.feedback;
  if (!wait.is_question() && wait.kind != LessonWait::Kind::YourTurn) {
    return "the lesson asks no question (it waits for " + wait.describe() + ")";
  }
  if (got.empty() || got.find(a.words()) == std::string::npos) {
    return std::string(Hint ? "the hint shown is '" : "the feedback is '") + got + "'";
  }
  return "";
}

std::string expect_lesson_step(EditorApp& app, const Action& a) {
  const LessonRunner& lesson = app.lesson();
  static const char* const kStates[] = {"empty", "waiting", "finished", "failed"};
  const std::string got = std::to_string(lesson.current_step() + 1) + " " + kStates[int(lesson.step_state())];
  return got == a.args[0] + " " + a.args[1] ? "" : "lesson is at step " + got + " (" + lesson.error() + ")";
}

std::string expect_lesson_said(EditorApp& app, const Action& a) {
  for (const std::string& block : app.lesson().said()) {
    if (block.find(a.words()) != std::string::npos) return "";
  }
  return "the current step did not say it";
}

std::string expect_lesson_shown(EditorApp& app, const Action& a) {
  const LessonRunner& lesson = app.lesson();
  std::string shown;
  for (const std::string& block : lesson.said()) {
    const std::string& text = lesson.texts().in(block, text_language());
    if (text.find(a.words()) != std::string::npos) return "";
    shown += (shown.empty() ? "" : " / ") + text.substr(0, 60);
  }
  return "the panel does not show it: " + shown;
}

std::string expect_lesson_error(EditorApp& app, const Action& a) {
  const std::string& error = app.lesson().error();
  if (error.empty()) return "the lesson has no error";
  return expect_contains(a.words(), error, "the lesson's error is");
}

std::string expect_lesson_live(EditorApp& app, const Action& a) {
  std::string texts;
  for (const LessonLive& live : app.lesson().lives()) {
    const std::string& shown = live.error.empty() ? live.text : live.error;
    if (shown.find(a.words()) != std::string::npos) return "";
    texts += (texts.empty() ? "'" : ", '") + shown + "'";
  }
  return "the live texts are " + (texts.empty() ? std::string("none") : texts);
}

// ---- exercises -------------------------------------------------------------------------------------------------

std::string exercise(EditorApp& app, const Action& a) {
  const auto which = find_exercise(a.args[0]);
  if (which == Exercise::CurveStep || which == Exercise::PatchEvaluate) {
    app.view().bezier_mine().set_folder(a.args[1]);
  } else if (!which) {
    throw std::runtime_error(exercise_registry().unknown_name_error(a.args[0]));
  } else if (!app.exercises().set_exercise(*which)) {
    throw std::runtime_error("no exercise " + a.args[0]);
  } else {
    app.exercises().set_folder(a.args[1]);
  }
  return "";
}

template <bool Mine>
std::string run_exercise(EditorApp& app, const Action&) {
  ExerciseSession& session = app.exercises();
  return (Mine ? session.start_mine(app.document(), app.selection())
               : session.run_reference(app.document(), app.selection()))
      .reason;
}

std::string stop_mine(EditorApp& app, const Action&) {
  if (!app.exercises().running()) return "no code of yours is running";
  app.exercises().stop_running();
  return "";
}

std::string run_mine_fails(EditorApp& app, const Action& a) {
  const Check run = app.exercises().run_mine(app.document(), app.selection());
  if (run) return "Run mine ran";
  return expect_contains(a.words(), run.reason, "Run mine was refused with");
}

std::string replay_start(EditorApp& app, const Action&) { return app.exercises().start_replay(app.document()).reason; }

std::string replay_step(EditorApp& app, const Action& a) {
  return app.exercises().replay_step(app.document(), std::stoul(a.args[0])).reason;
}

std::string replay_finish(EditorApp& app, const Action&) {
  app.exercises().finish_replay(app.document());
  return "";
}

std::string expect_exercise_run(EditorApp& app, const Action& a) {
  const std::optional<ExerciseRun>& run = app.exercises().last_run();
  const std::string got = run ? run->label + " (" + run->input.describe(run->exercise) +
                                    "): " + (run->mine ? run->report.summary() : "the reference alone")
                              : std::string("none");
  return expect_contains(a.words(), got, "the Exercises tab's last run is");
}

std::string editor_open(EditorApp& app, const Action&) {
  app.show_student_code();
  return "";
}

std::string editor_set_line(EditorApp& app, const Action& a) {
  const size_t line = std::stoul(a.args.at(0));
  if (!app.exercise_room().student_edit().set_line(line, a.words(1))) {
    return "the editor's file has no line " + a.args[0];
  }
  return "";
}

std::string editor_save(EditorApp& app, const Action&) { return app.exercise_room().save_student_code().reason; }

std::string editor_download(EditorApp& app, const Action&) {
  app.exercise_room().download_student_code();
  return "";
}

std::string unsaved_code(EditorApp& app, const Action& a) {
  using Answer = EditorApp::UnsavedCodeAnswer;
  static const std::pair<const char*, Answer> kAnswers[] = {
      {"save", Answer::SaveAndQuit}, {"discard", Answer::QuitWithoutSaving}, {"keep", Answer::KeepEditing}};
  for (const auto& [word, answer] : kAnswers) {
    if (a.args[0] != word) continue;
    if (!app.asking_about_unsaved_code()) return "the Unsaved code dialog is not open";
    app.answer_unsaved_code(answer);
    return "";
  }
  throw std::runtime_error("unsaved-code takes save, discard or keep");
}

std::string expect_unsaved_code(EditorApp& app, const Action& a) {
  if (!app.asking_about_unsaved_code()) return "the Unsaved code dialog is not open";
  return expect_contains(a.words(), app.exercise_room().unsaved_student_files(), "the dialog names");
}

std::string expect_editor_line(EditorApp& app, const Action& a) {
  const std::optional<std::string_view> line = app.exercise_room().student_edit().line(std::stoul(a.args.at(0)));
  if (!line) return "the editor's file has no line " + a.args[0];
  return expect_contains(a.words(1), std::string(*line), "line " + a.args[0] + " is");
}

std::string expect_editor_error(EditorApp& app, const Action& a) {
  const std::optional<size_t> line = app.exercise_room().student_code_error_line();
  const std::string got = line ? std::to_string(*line) : "none";
  if (got != a.args.at(0))
    return "the editor marks line " + got + " (" + app.exercise_room().student_code_error() + ")";
  return expect_contains(a.words(1), app.exercise_room().student_code_error(), "the editor's error is");
}

std::string expect_mine(EditorApp& app, const Action& a) {
  const BezierMine& mine = app.view().bezier_mine();
  const bool curve = app.mode() == ViewMode::Curve;
  if (!(curve ? mine.curve_on() : app.mode() == ViewMode::Patches && mine.patch_on())) {
    return "no \"mine\" switch is on in the view on screen";
  }
  return expect_contains(a.words(), curve ? mine.curve().message : mine.patch().message, "the mine line is");
}

// ---- checks ----------------------------------------------------------------------------------------------------

std::string expect_selected(EditorApp& app, const Action& a) {
  const std::string got = format_id(app.selection().selected);
  return got == a.args[0] ? "" : "selected " + got + ", expected " + a.args[0];
}

std::string expect_field(EditorApp& app, const Action& a) {
  const HalfedgeMesh& m = app.document().mesh;
  const ElementRef element = element_argument(a.args[0]);
  if (!m.alive(element)) throw std::runtime_error(a.args[0] + " is not a live element");
  const std::string& field = a.args[1];
  std::string got = "?";
  if (element.kind == ElementKind::Halfedge) {
    const HalfedgeId h(element.index);
    if (field == "next") got = format_id(m.next(h));
    if (field == "twin") got = format_id(m.twin(h));
    if (field == "vertex") got = format_id(m.vertex(h));
    if (field == "edge") got = format_id(m.edge(h));
    if (field == "face") got = format_id(m.face(h));
  } else if (field == "halfedge") {
    switch (element.kind) {
      case ElementKind::Vertex: got = format_id(m.halfedge(VertexId(element.index))); break;
      case ElementKind::Edge: got = format_id(m.halfedge(EdgeId(element.index))); break;
      default: got = format_id(m.halfedge(element.face_id())); break;
    }
  }
  return got == a.args[2] ? "" : a.args[0] + "." + field + " is " + got + ", expected " + a.args[2];
}

std::string expect_changed(EditorApp& app, const Action& a) {
  const auto element = parse_element(a.args[0]);
  const auto field = parse_field(a.args[1]);
  if (!element || !field) throw std::runtime_error("expect-changed takes an element and a field name");
  if (app.document().last.index.contains(*element, *field)) return "";
  return a.args[0] + "." + a.args[1] + " is not among the cells the last operation changed";
}

std::string expect_message(EditorApp& app, const Action& a) {
  return expect_contains(a.words(), app.document().message.text, "status line is");
}

std::string expect_valid(EditorApp& app, const Action&) {
  const ValidationReport& report = cached_validation(app.document());
  return report.ok() ? "" : report.summary();
}

std::string expect_console(EditorApp& app, const Action& a) {
  const auto& entries = app.panels().console().entries();
  return expect_contains(a.words(), entries.empty() ? "" : entries.back().text, "the console's last line is");
}

std::string expect_up_axis(EditorApp& app, const Action& a) {
  const std::string& wanted = a.args[0];
  if (wanted != "X" && wanted != "Y" && wanted != "Z") throw std::runtime_error("expect-up-axis takes X, Y or Z first");
  const std::string got(up_axis_name(app.view().camera().up_axis()));
  const std::string status(app.view().status_bar().up_axis);
  if (got != wanted + " up") return "the camera is " + got + " (status bar: '" + status + "')";
  return status.find(a.words(1)) == std::string::npos ? "the status bar says '" + status + "'" : "";
}

std::string expect_gpu_update(EditorApp& app, const Action& a) {
  if (a.args[0] != "patch" && a.args[0] != "rebuild") {
    throw std::runtime_error("expect-gpu-update takes patch or rebuild");
  }
  const RenderStats& stats = app.view().mesh_render_stats();
  const std::string got = stats.last_update_patch ? "patch" : "rebuild";
  const std::string why = stats.last_update_patch ? "" : " (" + stats.last_rebuild_reason + ")";
  return got == a.args[0] ? "" : "the last update was a " + got + why;
}

// ---- Check my work ----------------------------------------------------------------------------------------------

std::string check_suite(EditorApp& app, const Action& a) {
  app.check_room().set_suite(std::filesystem::absolute(a.args[0]));
  return "";
}

std::string expect_check(EditorApp& app, const Action& a) {
  return expect_contains(a.words(), app.check_room().text(), "the Check tab says");
}

std::string check_open(EditorApp& app, const Action& a) {
  const std::optional<size_t> row = app.check_room().row_of(a.args[0]);
  if (!row) throw std::runtime_error("the Check tab has no test " + a.args[0]);
  return app.open_failing_case(*row).reason;
}

std::string check_stop(EditorApp& app, const Action&) {
  if (!app.check_room().running()) return "no check is running";
  app.check_room().stop();
  return "";
}

// ---- the table -------------------------------------------------------------------------------------------------

// Every verb, its words after it, what it does, and its handler; the usage texts are the verbs' documentation.
const ActionVerb kVerbs[] = {
    {"frames", 1, "frames N   the next N frames pass with no action", nullptr},
    {"wait-message", -1,
     "wait-message N TEXT...   waits, a frame at a time, until the status line contains TEXT (what arrives from "
     "outside the script, such as a file the page receives); fails after N frames without it",
     nullptr},
    {"wait-check", -1,
     "wait-check N TEXT...   waits, a frame at a time, until the Check tab's words contain TEXT (a check's progress: "
     "the test running now); fails after N frames without them",
     nullptr},
    {"quit", 0, "quit   closes the window (the script's end does too)", nullptr},
    {"key", 1,
     "key F | key ctrl+Z | key shift+L   a key press (a letter, space, escape, grave, equal (=), minus (-), "
     "0, [, ] or f1, with ctrl+ and shift+)",
     press_key},
    {"select", 1, "select h12   selects the element, as a click on it does", select},
    {"click", 2,
     "click X Y   a click at view pixels (framebuffer pixels from the view's top-left corner, as picking "
     "counts them)",
     click},
    {"hover", 2, "hover X Y   the mouse rests at view pixels", hover},
    {"click-on", 1,
     "click-on h12   a click where the element's label anchor is on screen (a vertex's position, an edge's midpoint, "
     "a face's centre, a halfedge's arrow); fails when it is not in the view",
     click_on},
    {"window-size", 2, "window-size W H   asks the window system to resize the window before the next frame",
     window_size},
    {"layout-json", 1, "layout-json PATH   writes the window's layout as JSON (app/layout_report.h)", write_layout},
    {"open", 1, "open PATH   File > Open", open},
    {"open-picker", 0,
     "open-picker   File > Open mesh from this computer: the page's file picker, whose file opens when the browser "
     "hands it over (wait-message); fails where the window has no picker of its own (the desktop)",
     open_picker},
    {"open-repaired", 0, "open-repaired   File > Open a repaired copy of the mesh file `open` last refused",
     open_repaired},
    {"save", 1, "save PATH   File > Save as", save},
    {"screenshot", 1, "screenshot PATH   a PNG of the next frame", screenshot},
    {"bug-report", 1, "bug-report PATH   Help > Save a bug report's Save, to PATH, with the files ticked", bug_report},
    {"bug-report-send", 2, "bug-report-send flip.lua yes|no   ticks or unticks a code file in Save a bug report",
     bug_report_send},
    {"repair-row", 1,
     "repair-row K   clicks the Repairs tab's K-th change (1 the first): selects its first spot; fails when there is "
     "no such row, it has no spot, or the spots are stale",
     repair_row},
    {"command", 1,
     "command NAME   runs the command of that name (document/command_table.h: loop-phase, wireframe, inspector...) as "
     "its menu item does; fails when it was not done, with the status line's reason",
     run_named_command},
    {"triangulate", 0, "triangulate   Edit > Triangulate", triangulate},
    {"subdivide", 1, "subdivide loop|catmull-clark|linear   the Subdivide menu's item for the scheme",
     subdivide<false>},
    {"subdivide-phase", 1, "subdivide-phase loop|catmull-clark|linear   the Subdivide menu's \"next phase\" item",
     subdivide<true>},
    {"orbit", 2, "orbit DX DY   the camera turns as a drag of DX, DY pixels would turn it", orbit},
    {"up-axis", 1, "up-axis from-file|y|z   View > Up axis: the file's, or Y or Z up; refits the view", up_axis},
    {"language", 1, "language en|zh   View > Language", language},
    {"animate-edits", 1,
     "animate-edits on|off   flip, split, collapse and their undo and redo play for a quarter "
     "second, whatever the settings say; a scripted run starts with them off",
     animate_edits},
    {"quality", 1,
     "quality full|auto   the mesh view draws with multisampling, wireframe and back sides whatever its frames cost "
     "(full: for pictures compared across machines), or as the quality governor chooses (auto, the start)",
     quality},
    {"console", -1, "console LUA CODE...   runs the code in the Lua console", console},
    {"curve-t", 1, "curve-t T   the curve view's t, as its slider sets it", curve_t},
    {"patch-uv", 2, "patch-uv U V   the patch view's probe, as the Patches panel's u and v sliders set it", patch_uv},
    {"curve-click", 2, "curve-click X Y   a click in the curve view at that point of the curve's plane", curve_click},
    {"lesson-next", 0, "lesson-next   the lesson's Next", lesson_next},
    {"lesson-back", 0, "lesson-back   the lesson's Back", lesson_back},
    {"lesson-button", -1, "lesson-button LABEL...   presses a button the step shows", lesson_button},
    {"lesson-choose", -1, "lesson-choose OPTION...   presses that option of the choose{} the step asks",
     lesson_reply<true>},
    {"lesson-answer", -1,
     "lesson-answer TEXT...   types TEXT into the answer{} box and presses Check (a pick{} is "
     "answered by click-on)",
     lesson_reply<false>},
    {"lesson-show-mine", 0,
     "lesson-show-mine   presses the your_turn's \"Show mine vs reference\"; fails when the "
     "step waits on no wrong your_turn",
     lesson_show_mine},
    {"exercise", 2,
     "exercise flip|split|...|curve|patch FOLDER   the exercise and the folder its student files are "
     "read from (curve and patch: where the views' \"mine\", key M, reads them)",
     exercise},
    {"run-mine", 0, "run-mine   the Exercises tab's Run mine; what follows waits for its end", run_exercise<true>},
    {"start-mine", 0, "start-mine   the Exercises tab's Run mine; what follows runs while the code does",
     run_exercise<true>},
    {"stop-mine", 0, "stop-mine   the Exercises tab's Stop, while the code of a Run mine runs", stop_mine},
    {"run-mine-fails", -1,
     "run-mine-fails TEXT...   the Exercises tab's Run mine, run to its end at once, refused or failed with a reason "
     "containing TEXT",
     run_mine_fails},
    {"run-reference", 0, "run-reference   the Exercises tab's Run the reference", run_exercise<false>},
    {"replay-start", 0, "replay-start   starts the replay of the last run's writes", replay_start},
    {"replay-step", 1, "replay-step K   the replay at write K", replay_step},
    {"replay-finish", 0, "replay-finish   ends the replay", replay_finish},
    {"check-suite", 1, "check-suite FILE   the suite Check my work runs, as the window's --suite gives it",
     check_suite},
    {"expect-check", -1,
     "expect-check TEXT...   the Check tab (File > Check my work) shows TEXT: its total, a test's row or the "
     "grader's words for it",
     expect_check},
    {"check-open", 1, "check-open 4.1   the Check tab's \"Open in Exercises\" of test 4.1", check_open},
    {"check-stop", 0, "check-stop   the Check tab's Stop; fails when no check runs", check_stop},
    {"editor-open", 0, "editor-open   View > Your code: the active exercise's student file in the editor tab",
     editor_open},
    {"editor-set-line", -1,
     "editor-set-line N TEXT...   line N of the editor's text becomes TEXT (one past the last adds a line), unsaved",
     editor_set_line},
    {"editor-save", 0, "editor-save   the editor's Save (Ctrl+S): writes the student file, which the exercise loads",
     editor_save},
    {"editor-download", 0,
     "editor-download   File > Download your FILE.lua: saves the editor's text if it changed, then hands the student "
     "file over (a page's browser downloads it; the desktop's status line names where it is)",
     editor_download},
    {"unsaved-code", 1,
     "unsaved-code save|discard|keep   answers the Unsaved code dialog (a close with unsaved text in Your code): Save "
     "and quit, Quit without saving, Keep editing",
     unsaved_code},
    {"expect-unsaved-code", -1,
     "expect-unsaved-code TEXT...   the Unsaved code dialog is open, and the files it names contain TEXT",
     expect_unsaved_code},
    {"expect-editor-line", -1, "expect-editor-line N TEXT...   line N of the editor's text contains TEXT",
     expect_editor_line},
    {"expect-editor-error", -1,
     "expect-editor-error N|none [TEXT...]   the editor marks line N as the line of its file's error (none: no "
     "line), and the error contains TEXT",
     expect_editor_error},
    {"expect-selected", 1, "expect-selected h12   the selection is that element", expect_selected},
    {"expect-field", 3, "expect-field h0 next h3   the field of a live element holds that value", expect_field},
    {"expect-changed", 2, "expect-changed h0 next   the last operation changed that cell", expect_changed},
    {"expect-message", -1, "expect-message TEXT...   the status line contains TEXT", expect_message},
    {"expect-valid", 0, "expect-valid   the mesh passes validate()", expect_valid},
    {"expect-console", -1, "expect-console TEXT...   the console's last line contains TEXT", expect_console},
    {"expect-up-axis", -1,
     "expect-up-axis X|Y|Z [TEXT...]   the camera's up axis, and the status bar's up-axis words "
     "contain TEXT",
     expect_up_axis},
    {"expect-gpu-update", 1,
     "expect-gpu-update patch|rebuild   how the mesh view's last geometry update went (the "
     "slots an edit touched rewritten in place, or everything rebuilt); made by the next "
     "frame, which the check waits for",
     expect_gpu_update},
    {"expect-lesson-step", 2, "expect-lesson-step 3 waiting|finished|failed   the lesson's step and its state",
     expect_lesson_step},
    {"expect-lesson-said", -1, "expect-lesson-said TEXT...   the current step said TEXT", expect_lesson_said},
    {"expect-lesson-shown", -1, "expect-lesson-shown TEXT...   the panel shows TEXT in the window's language",
     expect_lesson_shown},
    {"expect-lesson-feedback", -1,
     "expect-lesson-feedback TEXT...   the feedback on the last wrong answer to the "
     "question asked, or the diagnosis of the your_turn waited on, contains TEXT",
     expect_lesson_feedback<false>},
    {"expect-lesson-hint", -1, "expect-lesson-hint TEXT...   the question's hint is shown, and contains TEXT",
     expect_lesson_feedback<true>},
    {"expect-lesson-error", -1,
     "expect-lesson-error TEXT...   the lesson's error (a file that does not load, a step that failed or was "
     "stopped), as its panel shows it, contains TEXT",
     expect_lesson_error},
    {"expect-lesson-live", -1,
     "expect-lesson-live TEXT...   a live() text of the step contains TEXT, as the last "
     "frame evaluated it",
     expect_lesson_live},
    {"expect-exercise-run", -1,
     "expect-exercise-run TEXT...   the Exercises tab's last run, as \"LABEL (INPUT): "
     "SUMMARY\", contains TEXT",
     expect_exercise_run},
    {"expect-mine", -1,
     "expect-mine TEXT...   the \"mine\" line of the curve or patch view on screen contains TEXT; "
     "computed when a frame draws the view, so the check waits for the frame after the action "
     "before it",
     expect_mine},
};

}  // namespace

std::span<const ActionVerb> action_verbs() { return kVerbs; }

const ActionVerb* find_action_verb(const std::string& name) {
  const auto* found =
      std::find_if(std::begin(kVerbs), std::end(kVerbs), [&](const ActionVerb& v) { return name == v.name; });
  return found == std::end(kVerbs) ? nullptr : found;
}

}  // namespace meshedit
