// EditRecorder: registration with the Lua state's BindingState (see edit_recorder.h for the contract).
#include "script/edit_recorder.h"

#include <algorithm>

#include "script/internal/binding_state.h"
#include "script/lua_runtime.h"

namespace meshedit {

EditRecorder::EditRecorder(lua_State* L, std::shared_ptr<HalfedgeMesh> mesh, Options options)
    : mesh_(std::move(mesh)), max_edits_(options.max_edits) {
  BindingState* state = find_binding_state(L);
  if (!state) throw ScriptError("cannot record: the meshedit module is not open in this Lua state");
  if (!mesh_) throw ScriptError("cannot record: no mesh");
  if (options.keep_before) before_ = std::make_shared<const HalfedgeMesh>(*mesh_);
  state->recorders.push_back(this);
  state_ = state;
}

EditRecorder::~EditRecorder() { stop(); }

void EditRecorder::stop() {
  if (!state_) return;
  auto& list = state_->recorders;
  list.erase(std::remove(list.begin(), list.end(), this), list.end());
  state_ = nullptr;
}

}  // namespace meshedit
