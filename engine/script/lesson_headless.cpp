// run_lesson_headless (see lesson_headless.h): reads the answers file, then drives a LessonRunner on a
// HeadlessHost step by step, printing what each step says and how each wait was answered.
#include "script/lesson_headless.h"

#include <algorithm>
#include <cctype>
#include <deque>
#include <fstream>
#include <iterator>
#include <map>

#include <lua.hpp>

#include "core/loop_subdivision.h"
#include "core/mesh_ops.h"
#include "script/headless_host.h"
#include "script/lesson_text.h"

namespace meshedit {
namespace {

constexpr size_t kMaxRoundsPerStep = 100000;

struct Answer {
  enum class Kind { Key, Click, Selection, Button, Flip, Split, Collapse, Subdivide, LoopPhase };
  Kind kind = Kind::Key;
  std::string field;  // as written: "key", "click", ...
  std::string value;  // "F", "v3", "vertex", "Continue", "e7" ("" for subdivide)
};
using AnswerList = std::deque<Answer>;

struct Answers {
  std::map<lua_Integer, AnswerList> by_number;
  std::map<std::string, AnswerList> by_title;
};

const std::pair<const char*, Answer::Kind> kAnswerFields[] = {
    {"key", Answer::Kind::Key},   {"click", Answer::Kind::Click}, {"selection", Answer::Kind::Selection},
    {"button", Answer::Kind::Button}, {"flip", Answer::Kind::Flip},   {"split", Answer::Kind::Split},
    {"collapse", Answer::Kind::Collapse}, {"subdivide", Answer::Kind::Subdivide},
    {"loop_phase", Answer::Kind::LoopPhase}};

bool is_edit(Answer::Kind kind) {
  return kind == Answer::Kind::Flip || kind == Answer::Kind::Split || kind == Answer::Kind::Collapse ||
         kind == Answer::Kind::Subdivide || kind == Answer::Kind::LoopPhase;
}

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ScriptError("cannot open " + path.string());
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// One answer table {key = "F"} at the top of the stack (read raw: no script code runs while reading).
Answer read_answer(lua_State* L, const std::string& where) {
  if (!lua_istable(L, -1)) throw ScriptError(where + ": expected a table like {key = \"F\"}");
  Answer answer;
  int fields = 0;
  lua_pushnil(L);
  while (lua_next(L, -2) != 0) {
    const std::string key = lua_type(L, -2) == LUA_TSTRING ? lua_tostring(L, -2) : "";
    const auto* found = std::find_if(std::begin(kAnswerFields), std::end(kAnswerFields),
                                     [&](const auto& field) { return key == field.first; });
    if (found == std::end(kAnswerFields)) {
      throw ScriptError(where + ": unknown answer '" + key +
                        "' (use key, click, selection, button, flip, split, collapse, subdivide or loop_phase)");
    }
    answer.kind = found->second;
    answer.field = key;
    if (answer.kind == Answer::Kind::Subdivide || answer.kind == Answer::Kind::LoopPhase) {
      if (lua_type(L, -1) != LUA_TBOOLEAN || !lua_toboolean(L, -1)) {
        throw ScriptError(where + ": write " + key + " = true");
      }
    } else {
      if (lua_type(L, -1) != LUA_TSTRING) throw ScriptError(where + ": " + key + " must be a string");
      answer.value = lua_tostring(L, -1);
    }
    ++fields;
    lua_pop(L, 1);
  }
  if (fields != 1) throw ScriptError(where + ": give exactly one answer per table");
  return answer;
}

Answers read_answers(const std::filesystem::path& path, const LuaLimits& limits) {
  const std::string name = path.filename().string();
  LuaRuntime lua(limits);
  lua.load(read_text(path), name);
  lua.start_budget();
  lua.call(0, 1);
  lua_State* L = lua.state();
  if (!lua_istable(L, -1)) {
    throw ScriptError(name + ": must return a table of answers per step, like { [2] = { {key = \"F\"} } }");
  }
  Answers answers;
  lua_pushnil(L);
  while (lua_next(L, -2) != 0) {
    AnswerList* list = nullptr;
    std::string step;
    if (lua_isinteger(L, -2)) {
      step = "step " + std::to_string(lua_tointeger(L, -2));
      list = &answers.by_number[lua_tointeger(L, -2)];
    } else if (lua_type(L, -2) == LUA_TSTRING) {
      step = "step '" + std::string(lua_tostring(L, -2)) + "'";
      list = &answers.by_title[lua_tostring(L, -2)];
    } else {
      throw ScriptError(name + ": keys are step numbers or step titles, got a " + luaL_typename(L, -2));
    }
    if (!lua_istable(L, -1)) throw ScriptError(name + ": " + step + ": expected a list of answers");
    const lua_Integer n = static_cast<lua_Integer>(lua_rawlen(L, -1));
    for (lua_Integer i = 1; i <= n; ++i) {
      lua_rawgeti(L, -1, i);
      list->push_back(read_answer(L, name + ": " + step + ", answer " + std::to_string(i)));
      lua_pop(L, 1);
    }
    lua_pop(L, 1);
  }
  lua_settop(L, 0);
  return answers;
}

std::optional<ElementKind> kind_by_name(const std::string& name) {
  for (ElementKind kind : {ElementKind::Vertex, ElementKind::Halfedge, ElementKind::Edge, ElementKind::Face,
                           ElementKind::Boundary}) {
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
  HeadlessDriver(std::ostream& out, const LuaLimits& limits) : out_(out), runner_(host_, limits) {
    runner_.set_print([this](const std::string& line) { out_ << line << '\n'; });
  }

  HeadlessOutcome run(const std::filesystem::path& lesson, Answers answers) {
    HeadlessOutcome outcome;
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
    return outcome;
  }

 private:
  // Runs the current step to its end; "" or the failure line.
  std::string run_step(AnswerList& queue) {
    size_t printed = 0;
    for (size_t round = 0; round < kMaxRoundsPerStep; ++round) {
      const std::vector<std::string>& said = runner_.said();
      for (; printed < said.size(); ++printed) {
        if (printed > 0) out_ << '\n';
        print_block(out_, said[printed]);
      }
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
      if (wait.kind == LessonWait::Kind::Animation) {
        runner_.update(std::max(wait.seconds / 10.0, 1.0 / 60.0));
        continue;
      }
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

  // Gives one scripted answer; "" or the failure line.
  std::string give(const Answer& answer, const LessonWait& wait) {
    bool used = false;
    switch (answer.kind) {
      case Answer::Kind::Key:
        out_ << "  > key " << answer.value;
        used = runner_.deliver(LessonEvent::key(answer.value));
        break;
      case Answer::Kind::Button:
        out_ << "  > button " << answer.value;
        used = runner_.deliver(LessonEvent::button(answer.value));
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
      default: {
        std::string failure = edit(answer);
        if (!failure.empty()) return with_step(failure, step_name_);
        used = true;
        break;
      }
    }
    if (!used && !is_edit(answer.kind)) {
      out_ << " (not awaited: the step waits for " << wait.describe() << ")";
    }
    out_ << '\n';
    // A condition may have become true (a selection, an edit): look again.
    if (runner_.step_state() == LessonRunner::StepState::Waiting &&
        runner_.waiting_for().kind == LessonWait::Kind::Condition) {
      runner_.update(0.0);
    }
    return "";
  }

  // The edits the window's keys make, applied to the mesh on screen.
  std::string edit(const Answer& answer) {
    std::shared_ptr<HalfedgeMesh> mesh = host_.current_mesh();
    if (!mesh) return "answer " + answer.field + ": no mesh on screen";
    Check check;
    if (answer.kind == Answer::Kind::Subdivide) {
      out_ << "  > subdivide";
      check = loop_subdivide(*mesh);
    } else if (answer.kind == Answer::Kind::LoopPhase) {
      check = loop_phase(*mesh);
    } else {
      const std::optional<ElementRef> element = parse_element(answer.value);
      if (!element || element->kind != ElementKind::Edge) {
        return "answer " + answer.field + " = \"" + answer.value + "\": expected an edge id like e7";
      }
      const EdgeId e(element->index);
      out_ << "  > " << answer.field << " " << format_id(e);
      if (answer.kind == Answer::Kind::Flip) check = flip(*mesh, e).check;
      else if (answer.kind == Answer::Kind::Split) check = split(*mesh, e).check;
      else check = collapse(*mesh, e).check;
    }
    if (!check.ok) {
      out_ << '\n';
      return "answer " + answer.field + (answer.value.empty() ? "" : " " + answer.value) + " refused: " + check.reason;
    }
    host_.set_current_mesh(mesh);
    if (answer.kind == Answer::Kind::LoopPhase && loop_.next_phase > 1) loop_.left = std::move(mesh);
    return "";
  }

  // Shift+L: the next Loop phase on `mesh` (a copy of the screen mesh), as the window's loop_subdivide_step.
  Check loop_phase(HalfedgeMesh& mesh) {
    if (loop_.next_phase > 1 && (!loop_.left || host_.screen_mesh() != loop_.left.get())) {
      out_ << "  (the mesh changed after Loop phase " << loop_.next_phase - 1 << "; starting again)\n";
      loop_ = LoopPhases{};
    }
    const int phase = loop_.next_phase;
    static const char* const kPhaseNames[] = {"", "compute new positions", "split every original edge",
                                              "flip new edges joining an old and a new vertex",
                                              "move every vertex to its new position"};
    out_ << "  > loop phase " << phase << "/4: " << kPhaseNames[phase];
    if (phase == 1) {
      OpResult<LoopState> state = loop_compute_positions(mesh, LoopWeights::Course);
      if (!state.ok()) return state.check;
      loop_.state = std::move(state.value);
    } else if (phase == 2) {
      loop_split_edges(mesh, loop_.state);
    } else if (phase == 3) {
      loop_flip_edges(mesh, loop_.state);
    } else {
      loop_commit_positions(mesh, loop_.state);
    }
    loop_.next_phase = phase == 4 ? 1 : phase + 1;
    if (phase == 4) loop_.state = LoopState{};
    return Check::yes();
  }

  // Where Shift+L is in Loop subdivision: the next phase, what phase 1 computed, and the screen mesh the last
  // phase left (kept alive, so a new mesh at the same address cannot pass for it).
  struct LoopPhases {
    int next_phase = 1;
    LoopState state;
    std::shared_ptr<HalfedgeMesh> left;
  };

  std::ostream& out_;
  HeadlessHost host_;
  LessonRunner runner_;
  std::string step_name_;
  LoopPhases loop_;
};

}  // namespace

HeadlessOutcome run_lesson_headless(const std::filesystem::path& lesson,
                                    const std::optional<std::filesystem::path>& answers, std::ostream& out,
                                    const LuaLimits& limits) {
  Answers scripted = answers ? read_answers(*answers, limits) : Answers{};
  HeadlessDriver driver(out, limits);
  return driver.run(lesson, std::move(scripted));
}

}  // namespace meshedit
