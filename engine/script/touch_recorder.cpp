// TouchRecorder: registration with the Lua state's BindingState and the hooks the bindings call (see
// touch_recorder.h for what counts as a touch).
#include "script/touch_recorder.h"

#include <algorithm>

#include "script/internal/binding_state.h"
#include "script/lua_runtime.h"

namespace meshedit {
namespace {

// "mesh:restore()" for an operation's field "restore"; a field of several words ("subdivision phase") as it is.
std::string operation_call(const std::string& field) {
  if (field.find(' ') != std::string::npos) return field;
  return "mesh:" + field + "()";
}

size_t live_elements(const HalfedgeMesh& mesh) {
  return mesh.num_vertices() + mesh.num_halfedges() + mesh.num_edges() + mesh.num_faces() + mesh.num_boundaries();
}

}  // namespace

TouchRecorder::TouchRecorder(lua_State* L, std::shared_ptr<const HalfedgeMesh> mesh) : mesh_(std::move(mesh)) {
  BindingState* state = find_binding_state(L);
  if (!state) throw ScriptError("cannot count touches: the meshedit module is not open in this Lua state");
  if (!mesh_) throw ScriptError("cannot count touches: no mesh");
  state->touch_recorders.push_back(this);
  state_ = state;
}

TouchRecorder::~TouchRecorder() { stop(); }

void TouchRecorder::stop() {
  if (!state_) return;
  auto& list = state_->touch_recorders;
  list.erase(std::remove(list.begin(), list.end(), this), list.end());
  state_ = nullptr;
}

TouchCount TouchRecorder::count() const {
  TouchCount out;
  out.elements = whole_mesh_call_.empty() ? touched_count_ : live_elements(*mesh_);
  out.written = written_count_;
  out.whole_mesh_call = whole_mesh_call_;
  return out;
}

bool TouchRecorder::mark(std::array<std::vector<bool>, kElementKindCount>& seen, ElementRef element) {
  std::vector<bool>& flags = seen[static_cast<size_t>(element.kind)];
  if (element.index >= flags.size()) flags.resize(size_t(element.index) + 1, false);
  if (flags[element.index]) return false;
  flags[element.index] = true;
  return true;
}

void TouchRecorder::touch(ElementRef element) {
  if (element.valid() && mark(touched_, element)) ++touched_count_;
}

void TouchRecorder::write(ElementRef element) {
  if (!element.valid()) return;
  touch(element);
  if (mark(written_, element)) ++written_count_;
}

void TouchRecorder::touch_whole_mesh(const char* call) {
  if (whole_mesh_call_.empty()) whole_mesh_call_ = call;
}

void note_touch(BindingState& state, const HalfedgeMesh* mesh, ElementRef element) {
  for (TouchRecorder* recorder : state.touch_recorders) {
    if (recorder->watches(mesh)) recorder->touch(element);
  }
}

void note_change(BindingState& state, const HalfedgeMesh* mesh, const RecordedEdit& edit) {
  const bool whole_mesh = edit.what == EditKind::Operation && (!edit.element.valid() || edit.state);
  for (TouchRecorder* recorder : state.touch_recorders) {
    if (!recorder->watches(mesh)) continue;
    if (whole_mesh) recorder->touch_whole_mesh(operation_call(edit.field).c_str());
    else recorder->write(edit.element);
  }
}

void note_whole_mesh_read(lua_State* L, const HalfedgeMesh* mesh, const char* call) {
  BindingState* state = find_binding_state(L);
  if (!state) return;
  for (TouchRecorder* recorder : state->touch_recorders) {
    if (recorder->watches(mesh)) recorder->touch_whole_mesh(call);
  }
}

}  // namespace meshedit
