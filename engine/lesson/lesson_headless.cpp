// run_lesson_headless (see lesson_headless.h): reads the answers file, then drives a LessonRunner on a
// HeadlessHost step by step, printing what each step says and how each wait was answered. The edits the answers
// stand for run on a document of the screen mesh through document/mesh_edits.h, as the window's commands do.
#include "lesson/lesson_headless.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <fstream>
#include <iterator>
#include <map>

#include <glm/common.hpp>
#include <lua.hpp>

#include "core/mesh_build.h"
#include "core/mesh_repair.h"
#include "core/subdivision_phases.h"
#include "core/value_format.h"
#include "document/mesh_edits.h"
#include "io/mesh_file.h"
#include "lesson/headless_host.h"
#include "lesson/internal/lesson_answers.h"
#include "lesson/lesson_text.h"

namespace meshedit {
namespace {

constexpr size_t kMaxRoundsPerStep = 100000;

using Answer = ScriptedAnswer;
using AnswerList = ScriptedAnswerList;

std::optional<ElementKind> kind_by_name(const std::string& name) {
  for (ElementKind kind :
       {ElementKind::Vertex, ElementKind::Halfedge, ElementKind::Edge, ElementKind::Face, ElementKind::Boundary}) {
    if (name == kind_name(kind)) return kind;
  }
  return std::nullopt;
}

// "v3" as is; a kind name as the first live element of that kind on screen.
std::optional<ElementRef> resolve_element(const std::string& text, const HeadlessHost& host) {
  if (std::optional<ElementRef> element = parse_element(text)) return element;
  const std::optional<ElementKind> kind = kind_by_name(text);
  const HalfedgeMesh* mesh = host.screen_mesh();
  if (!kind || !mesh) return std::nullopt;
  for (uint32_t i = 0; i < mesh->capacity(*kind); ++i) {
    if (mesh->alive(ElementRef(*kind, i))) return ElementRef(*kind, i);
  }
  return std::nullopt;
}

// How far from the curve a headless curve_click still counts as on it: 2% of the larger side of the control points'
// bounding box (about the window's pick radius on a curve fitted to its view).
double headless_click_radius(const std::vector<glm::dvec2>& points) {
  glm::dvec2 low(0.0), high(0.0);
  for (size_t i = 0; i < points.size(); ++i) {
    low = i == 0 ? points[i] : glm::min(low, points[i]);
    high = i == 0 ? points[i] : glm::max(high, points[i]);
  }
  return 0.02 * std::max(high.x - low.x, high.y - low.y);
}

// "welcome.lua:7: message" -> "welcome.lua:7: step 3 'Title': message" (the step goes after the place).
std::string with_step(const std::string& message, const std::string& step) {
  const size_t colon = message.find(':');
  if (colon != std::string::npos) {
    size_t i = colon + 1;
    while (i < message.size() && std::isdigit(static_cast<unsigned char>(message[i]))) ++i;
    if (i > colon + 1 && message.compare(i, 2, ": ") == 0) {
      return message.substr(0, i + 2) + step + ": " + message.substr(i + 2);
    }
  }
  return step + ": " + message;
}

// A diagnosis of several lines as one ("a; b"), for a failure line.
std::string one_line(std::string text) {
  for (size_t at = text.find('\n'); at != std::string::npos; at = text.find('\n', at)) text.replace(at, 1, "; ");
  return text;
}

void print_block(std::ostream& out, const std::string& markdown) {
  const std::string plain = markdown_to_plain(markdown);
  size_t start = 0;
  while (start <= plain.size()) {
    size_t end = plain.find('\n', start);
    if (end == std::string::npos) end = plain.size();
    const std::string line = plain.substr(start, end - start);
    out << (line.empty() ? "" : "  ") << line << '\n';
    start = end + 1;
  }
}

class HeadlessDriver {
 public:
  HeadlessDriver(std::ostream& out, const LuaLimits& limits, const std::filesystem::path& student_folder)
      : out_(out), runner_(host_, limits) {
    runner_.set_print([this](const std::string& line) { out_ << line << '\n'; });
    runner_.set_student_folder(student_folder);
  }

  HeadlessOutcome run(const std::filesystem::path& lesson, ScriptedAnswers answers) {
    HeadlessOutcome outcome;
    lesson_folder_ = lesson.parent_path();
    if (!runner_.load(lesson)) {
      outcome.failure = runner_.error();
      return outcome;
    }
    outcome.steps = runner_.step_count();
    out_ << runner_.title() << " (" << lesson.filename().string() << ", " << outcome.steps
         << (outcome.steps == 1 ? " step)\n" : " steps)\n");
    if (!runner_.summary().empty()) print_block(out_, runner_.summary());
    const std::vector<std::string> titles = runner_.step_titles();
    for (size_t i = 0; i < outcome.steps; ++i) {
      if (i > 0) runner_.next();
      step_name_ = "step " + std::to_string(i + 1) + " '" + titles[i] + "'";
      out_ << "\nstep " << i + 1 << "/" << outcome.steps << ": " << titles[i] << '\n';
      AnswerList queue;
      if (auto it = answers.by_number.find(static_cast<lua_Integer>(i + 1)); it != answers.by_number.end()) {
        queue = it->second;
      } else if (auto named = answers.by_title.find(titles[i]); named != answers.by_title.end()) {
        queue = named->second;
      }
      outcome.failure = run_step(queue);
      if (!outcome.failure.empty()) break;
      ++outcome.passed;
    }
    out_ << '\n';
    if (outcome.failure.empty()) out_ << outcome.passed << (outcome.passed == 1 ? " step passed\n" : " steps passed\n");
    else out_ << outcome.passed << " of " << outcome.steps << " steps passed\n";
    outcome.text_problems = runner_.texts().problems();
    outcome.untranslated = runner_.texts().untranslated();
    return outcome;
  }

 private:
  // Runs the current step to its end; "" or the failure line.
  std::string run_step(AnswerList& queue) {
    shown_ = StepShown{};
    for (size_t round = 0; round < kMaxRoundsPerStep; ++round) {
      if (std::string failure = print_new_blocks(queue); !failure.empty()) return failure;
      switch (runner_.step_state()) {
        case LessonRunner::StepState::Finished:
          if (!queue.empty()) out_ << "  (" << queue.size() << " scripted answer(s) not used)\n";
          out_ << "  done\n";
          return "";
        case LessonRunner::StepState::Failed: return with_step(runner_.error(), step_name_);
        case LessonRunner::StepState::Empty: return "no lesson loaded";
        case LessonRunner::StepState::Waiting: break;
      }
      const LessonWait wait = runner_.waiting_for();
      if (wait.kind == LessonWait::Kind::YourTurn && shown_.wrong_expected) {
        if (!queue.empty()) out_ << "  (" << queue.size() << " scripted answer(s) not used)\n";
        out_ << "  (wrong, as the answers expect: going on)\n";
        return "";
      }
      if (wait.kind == LessonWait::Kind::Animation) {
        runner_.update(std::max(wait.seconds / 10.0, 1.0 / 60.0));
        continue;
      }
      print_question(wait);
      if (!queue.empty()) {
        const Answer answer = queue.front();
        queue.pop_front();
        if (std::string failure = give(answer, wait); !failure.empty()) return failure;
        continue;
      }
      if (wait.kind == LessonWait::Kind::Button) {
        out_ << "  > button " << wait.name << " (pressed)\n";
        runner_.deliver(LessonEvent::button(wait.name));
        continue;
      }
      if (wait.kind == LessonWait::Kind::Selection && wait.selection_matches(host_.current_selection())) {
        runner_.update(0.0);
        continue;
      }
      const std::string where = wait.where.empty() ? "" : wait.where + ": ";
      return where + step_name_ + ": waiting for " + wait.describe() + " (no scripted answer)";
    }
    return with_step("did not finish after " + std::to_string(kMaxRoundsPerStep) + " frames and answers", step_name_);
  }

  // What the step shows that was not printed yet: say() text as plain text (a blank line between blocks), live text
  // ("  [live] t = 0.50"), plots ("  [plot Bernstein weights: B0, B1 for x from 0 to 1, marker at 0.5]"). Answered
  // questions were printed with their answer.
  // your_turn runs are printed in their place among the blocks (check_your_turns); "" or the failure line.
  std::string print_new_blocks(AnswerList& queue) {
    const std::vector<LessonBlock>& blocks = runner_.blocks();
    for (; shown_.blocks < blocks.size(); ++shown_.blocks) {
      if (std::string failure = check_your_turns(queue, shown_.blocks); !failure.empty()) return failure;
      const LessonBlock& block = blocks[shown_.blocks];
      if (block.kind == LessonBlock::Kind::Text) {
        if (shown_.texts++ > 0) out_ << '\n';
        print_block(out_, runner_.said()[block.index]);
      } else if (block.kind == LessonBlock::Kind::Live) {
        print_live(block.index);
      } else if (block.kind == LessonBlock::Kind::Plot) {
        print_plot(runner_.plots()[block.index]);
      }
    }
    return check_your_turns(queue, blocks.size());
  }

  void print_live(size_t index) {
    const LessonLive& live = runner_.lives()[index];
    const std::string line = live.error.empty() ? "  [live] " + markdown_to_plain(live.text) : "  [live] " + live.error;
    if (shown_.lives.size() <= index) shown_.lives.resize(index + 1);
    if (shown_.lives[index] == line) return;
    shown_.lives[index] = line;
    out_ << line << '\n';
  }

  // The live text that changed since it was printed (after an answer moved the view).
  void print_changed_lives() {
    runner_.refresh_live();
    for (size_t i = 0; i < shown_.lives.size() && i < runner_.lives().size(); ++i) print_live(i);
  }

  void print_plot(const LessonPlot& plot) {
    std::string labels;
    for (const LessonPlotCurve& curve : plot.curves) labels += (labels.empty() ? "" : ", ") + curve.label;
    out_ << "  [plot " << (plot.title.empty() ? "" : plot.title + ": ") << labels << " for x from "
         << format_rounded(plot.x_range[0]) << " to " << format_rounded(plot.x_range[1]);
    if (plot.marker) out_ << ", marker at " << *plot.marker;
    if (!plot.error.empty()) out_ << "; marker stopped: " << plot.error;
    out_ << "]\n";
  }

  // A question the step asks, once: "  ? Which halfedge...? (h1 | h2 | h4)".
  void print_question(const LessonWait& wait) {
    if (!wait.is_question() || shown_.asked) return;
    shown_.asked = true;
    out_ << "  ? " << wait.question;
    std::string options;
    for (const std::string& option : wait.options) options += (options.empty() ? "" : " | ") + option;
    if (!options.empty()) out_ << " (" << options << ")";
    out_ << '\n';
  }

  // The your_turn runs not printed yet that came before block `before`, each printed ("  > your turn flip.lua: wrong:
  // DIAGNOSIS") and checked against the next answer when that is a your_turn expectation; "" or the failure line.
  std::string check_your_turns(AnswerList& queue, size_t before) {
    const std::vector<YourTurnVerdict>& turns = runner_.your_turns();
    for (; shown_.your_turns < turns.size() && turns[shown_.your_turns].block <= before; ++shown_.your_turns) {
      const YourTurnVerdict& verdict = turns[shown_.your_turns];
      out_ << "  > your turn " << verdict.file << ": " << (verdict.right ? "right" : "wrong");
      std::string feedback = verdict.feedback;
      for (size_t at = feedback.find('\n'); at != std::string::npos; at = feedback.find('\n', at + 5)) {
        feedback.replace(at, 1, "\n    ");
      }
      if (!feedback.empty()) out_ << ": " << feedback;
      out_ << '\n';
      shown_.wrong_expected = false;
      if (queue.empty() || queue.front().kind != Answer::Kind::YourTurn) continue;
      const Answer expected = queue.front();
      queue.pop_front();
      std::string got;
      if (verdict.right && expected.value == "wrong") got = "it was judged right";
      else if (!verdict.right && expected.value == "right") got = "it was judged wrong: " + one_line(verdict.feedback);
      else if (!verdict.right && expected.feedback && verdict.feedback.find(*expected.feedback) == std::string::npos)
        got = "its feedback was '" + one_line(verdict.feedback) + "'";
      if (!got.empty()) {
        const std::string words = expected.feedback ? " with feedback containing '" + *expected.feedback + "'" : "";
        const std::string where = verdict.where.empty() ? "" : verdict.where + ": ";
        return where + step_name_ + ": your_turn should be judged " + expected.value + words + ", but " + got;
      }
      shown_.wrong_expected = !verdict.right;
    }
    return "";
  }

  // Hands one answer to the runner (or makes its edit): "" or the failure line; `used` says whether the step took it.
  std::string deliver(const Answer& answer, bool& used) {
    switch (answer.kind) {
      case Answer::Kind::Key:
        out_ << "  > key " << answer.value;
        used = runner_.deliver(LessonEvent::key(answer.value));
        break;
      case Answer::Kind::Button:
        out_ << "  > button " << answer.value;
        used = runner_.deliver(LessonEvent::button(answer.value));
        break;
      case Answer::Kind::Choose:
        out_ << "  > choose " << answer.value;
        used = runner_.deliver(LessonEvent::choice(answer.value));
        break;
      case Answer::Kind::Value:
        out_ << "  > answer " << answer.value;
        used = runner_.deliver(LessonEvent::value(answer.value));
        break;
      case Answer::Kind::Click:
      case Answer::Kind::Selection: {
        const std::optional<ElementRef> element = resolve_element(answer.value, host_);
        if (!element) {
          return with_step("answer " + answer.field + " = \"" + answer.value + "\": no such element", step_name_);
        }
        out_ << "  > " << answer.field << " " << format_id(*element);
        host_.set_selection(*element);  // a click selects, as in the window
        if (answer.kind == Answer::Kind::Click) used = runner_.deliver(LessonEvent::click(*element));
        if (runner_.step_state() == LessonRunner::StepState::Waiting) {
          used = runner_.deliver(LessonEvent::selection(*element)) || used;
        }
        break;
      }
      case Answer::Kind::PatchUv: {
        if (!host_.patch_reading()) return with_step("answer patch_uv: no patches on screen", step_name_);
        char* rest = nullptr;
        const double u = std::strtod(answer.value.c_str(), &rest);
        host_.set_patch_uv(u, std::strtod(rest, nullptr));
        out_ << "  > patch u, v = " << host_.patch_reading()->u << ", " << host_.patch_reading()->v;
        used = true;
        break;
      }
      case Answer::Kind::CurveClick: {
        const std::optional<CurveReading> curve = host_.curve_reading();
        if (!curve) return with_step("answer curve_click: no curve on screen", step_name_);
        char* rest = nullptr;
        const double x = std::strtod(answer.value.c_str(), &rest);
        const glm::dvec2 point(x, std::strtod(rest, nullptr));
        out_ << "  > curve click " << point.x << ", " << point.y;
        used = runner_.deliver(LessonEvent::curve_click(point, headless_click_radius(curve->control_points)));
        break;
      }
      case Answer::Kind::CurveT: {
        if (!host_.curve_reading()) return with_step("answer curve_t: no curve on screen", step_name_);
        host_.set_curve_t(std::strtod(answer.value.c_str(), nullptr));
        out_ << "  > curve t = " << host_.curve_reading()->t;
        used = true;
        break;
      }
      default: {
        std::string failure = edit(answer);
        if (!failure.empty()) return with_step(failure, step_name_);
        used = true;
        break;
      }
    }
    return "";
  }

  // Gives one scripted answer; "" or the failure line.
  std::string give(const Answer& answer, const LessonWait& wait) {
    if (answer.kind == Answer::Kind::YourTurn) {
      const std::string where = wait.where.empty() ? "" : wait.where + ": ";
      return where + step_name_ + ": answer your_turn = \"" + answer.value +
             "\" expects a your_turn run, but the step waits for " + wait.describe();
    }
    bool used = false;
    const size_t judged_before = runner_.judgements();
    if (std::string failure = deliver(answer, used); !failure.empty()) return failure;
    if (!used && !answer.is_edit()) {
      out_ << " (not awaited: the step waits for " << wait.describe() << ")";
    }
    const bool judged = runner_.judgements() > judged_before;
    if (judged) print_judgement();
    out_ << '\n';
    if (judged && !runner_.last_judgement().right) {
      const LessonWait& now = runner_.waiting_for();
      if (now.is_question() && now.hint_shown() && !shown_.hint) {
        shown_.hint = true;
        out_ << "  hint: " << now.hint << '\n';
      }
    }
    if (judged && runner_.last_judgement().right) shown_.asked = shown_.hint = false;  // the next question is new
    if (answer.feedback) {
      if (std::string failure = check_feedback(answer, wait, judged); !failure.empty()) return failure;
    }
    // A condition may have become true (a selection, an edit): look again.
    if (runner_.step_state() == LessonRunner::StepState::Waiting &&
        runner_.waiting_for().kind == LessonWait::Kind::Condition) {
      runner_.update(0.0);
    }
    print_changed_lives();
    return "";
  }

  // ": right", ": right: <feedback>", ": wrong: <feedback>" after the answer's line.
  void print_judgement() {
    const LessonJudgement& judgement = runner_.last_judgement();
    out_ << (judgement.right ? ": right" : ": wrong");
    if (!judgement.feedback.empty()) out_ << ": " << judgement.feedback;
  }

  // An answer that carries `feedback`: it must have been judged wrong with feedback containing those words.
  std::string check_feedback(const Answer& answer, const LessonWait& wait, bool judged) {
    const std::string expected = "answer " + answer.field + " = \"" + answer.value +
                                 "\" should be judged wrong with feedback containing '" + *answer.feedback + "'";
    const LessonJudgement& judgement = runner_.last_judgement();
    const bool named = judgement.feedback.find(*answer.feedback) != std::string::npos;
    std::string got;
    if (!judged) got = "no question judged it";
    else if (judgement.right) got = "it was judged right";
    else if (!named) got = "its feedback was '" + judgement.feedback + "'";
    else return "";
    const std::string where = wait.where.empty() ? "" : wait.where + ": ";
    return where + step_name_ + ": " + expected + ", but " + got;
  }

  // File > Open a repaired copy: the file (a path from the lesson's folder) read, repaired and shown.
  std::string open_repaired(const Answer& answer) {
    const std::filesystem::path path = lesson_folder_ / answer.value;
    out_ << "  > open a repaired copy of " << answer.value;
    try {
      const RepairResult repaired = repair_polygons(load_mesh(path));
      host_.set_current_mesh(std::make_shared<HalfedgeMesh>(build_halfedge_mesh(repaired.polygons)));
    } catch (const std::exception& e) {
      return "answer open_repaired = \"" + answer.value + "\": " + e.what();
    }
    return "";
  }

  // The edits the window's keys and menu commands make, applied to the mesh on screen by the function the window
  // runs them with (document/mesh_edits.h); a command a lesson can wait for then tells the lesson its name, as the
  // window does.
  std::string edit(const Answer& answer) {
    const std::optional<CommandId> id = command_of(answer);
    if (!id) return edit_edge(answer);  // flip, split, collapse name their edge
    std::string failure = *id == CommandId::OpenRepaired ? open_repaired(answer) : edit_mesh(answer, *id);
    if (failure.empty() && command(*id).lesson_can_wait) runner_.deliver(LessonEvent::command(command(*id).name));
    return failure;
  }

  // The command a whole-mesh edit answer stands for; nullopt for flip, split and collapse.
  static std::optional<CommandId> command_of(const Answer& answer) {
    switch (answer.kind) {
      case Answer::Kind::Subdivide:
      case Answer::Kind::SubdividePhase:
        return subdivide_command(scheme_named(answer.value).value_or(SubdivisionScheme::Loop),
                                 answer.kind == Answer::Kind::SubdividePhase);
      case Answer::Kind::Triangulate: return CommandId::Triangulate;
      case Answer::Kind::OpenRepaired: return CommandId::OpenRepaired;
      default: return std::nullopt;
    }
  }

  // The document the edits run on: the mesh on screen, taken again when the screen shows another mesh than the last
  // edit left (the lesson showed another), which starts a one-phase subdivision again at phase 1 as in the window.
  bool take_screen_mesh() {
    const HalfedgeMesh* screen = host_.screen_mesh();
    if (!screen) return false;
    if (screen != left_.get()) {
      replace_mesh(doc_, *screen, std::string());
      selection_ = Selection{};
    }
    return true;
  }

  // The edit ran on doc_: the screen shows its mesh.
  void show_edited() {
    left_ = std::make_shared<HalfedgeMesh>(doc_.mesh);
    host_.set_current_mesh(left_);
  }

  // Flip, split or collapse of the edge the answer names: the edge selected, then the command run, as a click on the
  // edge and its key do in the window.
  std::string edit_edge(const Answer& answer) {
    if (!take_screen_mesh()) return "answer " + answer.field + ": no mesh on screen";
    const std::optional<ElementRef> element = parse_element(answer.value);
    if (!element || element->kind != ElementKind::Edge) {
      return "answer " + answer.field + " = \"" + answer.value + "\": expected an edge id like e7";
    }
    out_ << "  > " << answer.field << " " << format_id(*element);
    const CommandId id = answer.kind == Answer::Kind::Flip    ? CommandId::Flip
                         : answer.kind == Answer::Kind::Split ? CommandId::Split
                                                              : CommandId::Collapse;
    selection_.selected = *element;
    if (const Check check = run_mesh_edit(id, doc_, selection_, edits_); !check) return refused(answer, check);
    show_edited();
    return "";
  }

  // Triangulate, or a subdivision whole or its next phase (Shift+L, the Subdivide menu's items).
  std::string edit_mesh(const Answer& answer, CommandId id) {
    if (!take_screen_mesh()) return "answer " + answer.field + ": no mesh on screen";
    if (answer.kind == Answer::Kind::Subdivide) {
      out_ << "  > subdivide" << (answer.value == "loop" ? "" : " " + answer.value);
    } else if (answer.kind == Answer::Kind::Triangulate) {
      out_ << "  > triangulate";
    } else {  // one phase: say which, and that the phases start again when the mesh changed since the last one
      const SubdivisionScheme scheme = *scheme_named(answer.value);
      if (const std::optional<int> stale = stale_phase(scheme, doc_, edits_)) {
        out_ << "  (the mesh changed after " << scheme_title(scheme) << " phase " << *stale << "; starting again)\n";
      }
      const std::string& label = next_phase_label(scheme, doc_, edits_);
      out_ << "  > " << scheme_name(scheme) << " phase" << label.substr(std::strlen(scheme_title(scheme)));
    }
    if (const Check check = run_mesh_edit(id, doc_, selection_, edits_); !check) return refused(answer, check);
    show_edited();
    return "";
  }

  std::string refused(const Answer& answer, const Check& check) {
    out_ << '\n';
    return "answer " + answer.field + (answer.value.empty() ? "" : " " + answer.value) + " refused: " + check.reason;
  }

  // What was printed of the current step.
  struct StepShown {
    size_t blocks = 0;               // runner_.blocks() printed
    size_t texts = 0;                // say() blocks printed (a blank line goes between them)
    std::vector<std::string> lives;  // each live block's line as last printed
    bool asked = false;              // the question waited on was printed
    bool hint = false;               // its hint was printed
    size_t your_turns = 0;           // runner_.your_turns() printed
    bool wrong_expected = false;     // the last your_turn was wrong, as the answers expected: the step may go on
  };

  std::ostream& out_;
  HeadlessHost host_;
  LessonRunner runner_;
  std::string step_name_;
  // The edits' document, selection and steppers, as the window keeps them, and the screen mesh the last edit left
  // (kept alive, so a new mesh at the same address cannot pass for it).
  MeshDocument doc_ = make_document(HalfedgeMesh());
  Selection selection_;
  MeshEditState edits_;
  std::shared_ptr<HalfedgeMesh> left_;
  std::filesystem::path lesson_folder_;  // where open_repaired's paths start
  StepShown shown_;
};

}  // namespace

HeadlessOutcome run_lesson_headless(const std::filesystem::path& lesson,
                                    const std::optional<std::filesystem::path>& answers, std::ostream& out,
                                    const LuaLimits& limits, const std::filesystem::path& student_folder) {
  ScriptedAnswers scripted = answers ? read_scripted_answers(*answers, limits) : ScriptedAnswers{};
  HeadlessDriver driver(out, limits, student_folder);
  return driver.run(lesson, std::move(scripted));
}

}  // namespace meshedit
