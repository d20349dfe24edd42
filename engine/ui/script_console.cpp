// The Lua console: see script_console.h for the contract.
#include "ui/script_console.h"

#include <algorithm>
#include <new>
#include <optional>
#include <utility>

#include <imgui.h>
#include <lua.hpp>

#include "core/change_journal.h"
#include "core/mesh_patch.h"
#include "script/mesh_bindings.h"
#include "ui/theme.h"

namespace meshedit {
namespace {

LuaLimits console_limits() {
  LuaLimits limits;
  limits.instructions = 200'000'000;
  limits.memory_bytes = size_t(256) << 20;
  limits.wall_seconds = 5.0;
  return limits;
}

bool is_blank(const std::string& text) {
  return std::all_of(text.begin(), text.end(), [](unsigned char c) { return c == ' ' || c == '\t' || c == '\n'; });
}

std::string join(const std::vector<std::string>& values) {
  std::string line;
  for (size_t i = 0; i < values.size(); ++i) line += (i ? "\t" : "") + values[i];
  return line;
}

// The first line of `code`, shortened, for undo labels ("console: m:flip(m:edge(3))").
std::string label_of(const std::string& code) {
  std::string first = code.substr(0, code.find('\n'));
  if (first.size() > 60) first = first.substr(0, 57) + "...";
  return first;
}

}  // namespace

ScriptConsole::ScriptConsole() : lua_(console_limits()), mesh_(std::make_shared<HalfedgeMesh>()) {
  lua_.set_print([this](const std::string& line) { add(ConsoleEntryKind::Output, line); });
  push_mesh(lua_.state(), mesh_);
  lua_setglobal(lua_.state(), "mesh");
}

void ScriptConsole::add(ConsoleEntryKind kind, std::string text) {
  if (text.size() > kMaxEntryBytes) {
    const size_t dropped = text.size() - kMaxEntryBytes;
    text.resize(kMaxEntryBytes);
    text += "... (" + std::to_string(dropped) + " more bytes)";
  }
  entries_.push_back({kind, std::move(text)});
  while (entries_.size() > kMaxEntries) entries_.pop_front();
}

void ScriptConsole::sync_from(const MeshDocument& doc) {
  // A console mesh changed since it was synced (a line that threw past submit's bookkeeping) is copied afresh.
  const bool untouched = mesh_->version() == mesh_version_when_synced_;
  if (untouched && doc.generation == synced_generation_ && doc.mesh.version() == synced_version_) return;
  const bool one_local_change_behind =
      untouched && doc.generation == synced_generation_ && synced_version_ != UINT64_MAX && doc.last.patch &&
      doc.last.version_before == synced_version_ && doc.last.version_after == doc.mesh.version();
  if (one_local_change_behind) {
    doc.last.patch->apply(*mesh_, true);
    mesh_->bump_version_above(mesh_->version());  // apply() keeps the version: the script's undo must see a change
  } else {
    *mesh_ = doc.mesh;  // in place: handles in globals keep pointing at the console's mesh
  }
  synced_generation_ = doc.generation;
  synced_version_ = doc.mesh.version();
  mesh_version_when_synced_ = mesh_->version();
}

void ScriptConsole::bind_selection(const Selection& selection) {
  lua_State* L = lua_.state();
  const ElementRef ref = selection.selected;
  if (!ref.valid()) {
    lua_pushnil(L);
  } else {
    // mesh:vertex(i) / :halfedge(i) / :edge(i) / :face(i) / :boundary(i) make the handle: the bindings are the
    // one place that knows how handles are built.
    lua_getglobal(L, "mesh");
    lua_getfield(L, -1, kind_name(ref.kind));
    lua_insert(L, -2);
    lua_pushinteger(L, ref.index);
    if (lua_pcall(L, 2, 1, 0) != LUA_OK) {
      lua_pop(L, 1);
      lua_pushnil(L);
    }
  }
  lua_setglobal(L, "selected");
}

std::vector<std::string> ScriptConsole::run(const std::string& code) {
  // lua.c's rule: an expression is printed; anything else runs as a statement.
  const std::string as_expression = "return " + code;
  lua_State* L = lua_.state();
  const bool expression = luaL_loadbufferx(L, as_expression.data(), as_expression.size(), "=console", "t") == LUA_OK;
  lua_pop(L, 1);  // the compiled chunk or the syntax error message
  return lua_.run_string(expression ? as_expression : code, "console");
}

void ScriptConsole::submit(MeshDocument& doc, const Selection& selection, const std::string& code) {
  if (is_blank(code)) return;
  add(ConsoleEntryKind::Input, code);
  history_.erase(std::remove(history_.begin(), history_.end(), code), history_.end());
  history_.push_back(code);
  if (history_.size() > kMaxHistory) history_.erase(history_.begin());
  history_cursor_ = history_.size();

  sync_from(doc);
  bind_selection(selection);
  const uint64_t version_before = mesh_->version();
  bool failed = false;
  std::optional<MeshPatch> patch;
  {
    ChangeJournal journal(*mesh_);  // what the line writes, slot by slot, unless it rewrites the mesh wholesale
    try {
      const std::vector<std::string> results = run(code);
      if (!results.empty()) add(ConsoleEntryKind::Output, join(results));
    } catch (const ScriptError& e) {
      add(ConsoleEntryKind::Error, e.what());
      failed = true;
    }
    if (mesh_->version() == version_before) return;
    if (!journal.has_snapshot() && !journal.state_before_lost()) {
      try {
        patch = make_patch(journal, *mesh_);
      } catch (const std::bad_alloc&) {
        // The document gets the whole mesh instead.
      }
    }
  }
  const std::string label = std::string(failed ? "console (error): " : "console: ") + label_of(code);
  // A local change reaches the document as the same writes (its journal keeps a patch: no copy of the mesh, the diff
  // and the validation from the patch); anything else as an assignment of the console's mesh.
  const Check done = apply_operation(doc, label, [&](HalfedgeMesh& mesh) {
    if (!patch || !patch->apply_as_edit(mesh)) mesh = *mesh_;
    return Check::yes();
  });
  // Kept, the document's mesh now holds what the console's does (its version may differ): no copy next line.
  synced_generation_ = doc.generation;
  synced_version_ = done.ok ? doc.mesh.version() : UINT64_MAX;
  mesh_version_when_synced_ = mesh_->version();
}

std::string ScriptConsole::history_up() {
  if (history_.empty()) return {};
  if (history_cursor_ > 0) --history_cursor_;
  return history_[history_cursor_];
}

std::string ScriptConsole::history_down() {
  if (history_cursor_ < history_.size()) ++history_cursor_;
  return history_cursor_ < history_.size() ? history_[history_cursor_] : std::string();
}

namespace {

// ImGui's input callback: Up/Down browse the history.
int input_callback(ImGuiInputTextCallbackData* data) {
  if (data->EventFlag == ImGuiInputTextFlags_CallbackHistory) {
    auto* console = static_cast<ScriptConsole*>(data->UserData);
    const std::string line = data->EventKey == ImGuiKey_UpArrow ? console->history_up() : console->history_down();
    data->DeleteChars(0, data->BufTextLen);
    data->InsertChars(0, line.c_str(), line.c_str() + std::min(line.size(), size_t(data->BufSize - 1)));
  }
  return 0;
}

ImVec4 colour_of(ConsoleEntryKind kind) {
  switch (kind) {
    case ConsoleEntryKind::Input: return im_colour(ui_palette().console_input);
    case ConsoleEntryKind::Error: return im_colour(ui_palette().error);
    case ConsoleEntryKind::Output: break;
  }
  return ImGui::GetStyleColorVec4(ImGuiCol_Text);
}

}  // namespace

void draw_console_panel_contents(ScriptConsole& console, ConsolePanelState& state, MeshDocument& doc,
                                 const Selection& selection) {
  const float input_height = ImGui::GetFrameHeightWithSpacing();
  ImGui::BeginChild("transcript", ImVec2(0, -input_height), false, ImGuiWindowFlags_HorizontalScrollbar);
  for (const ConsoleEntry& entry : console.entries()) {
    ImGui::PushStyleColor(ImGuiCol_Text, colour_of(entry.kind));
    if (entry.kind == ConsoleEntryKind::Input) {
      ImGui::TextUnformatted("> ");
      ImGui::SameLine(0, 0);
    }
    ImGui::TextUnformatted(entry.text.c_str(), entry.text.c_str() + entry.text.size());
    ImGui::PopStyleColor();
  }
  if (state.scroll_to_bottom) ImGui::SetScrollHereY(1.0f);
  state.scroll_to_bottom = false;
  ImGui::EndChild();

  if (state.focus_input) ImGui::SetKeyboardFocusHere();
  state.focus_input = false;
  ImGui::SetNextItemWidth(-1);
  const ImGuiInputTextFlags flags = ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_CallbackHistory;
  if (ImGui::InputText("##lua", state.input.data(), state.input.size(), flags, input_callback, &console)) {
    const std::string code = state.input.data();
    state.input[0] = '\0';
    console.submit(doc, selection, code);
    state.focus_input = true;  // Enter keeps the keyboard in the console
    state.scroll_to_bottom = true;
  }
}

}  // namespace meshedit
