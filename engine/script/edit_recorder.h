// EditRecorder: records every change Lua code makes to one mesh while the host runs it, each with the script
// line that made it, so the app can replay a student's operation write by write:
//
//   EditRecorder recorder(lua.state(), mesh);       // recording starts; before() is a copy of the mesh now
//   ... call the student's flip_edge through the runtime ...
//   recorder.stop();
//   HalfedgeMesh step_k = replay(*recorder.before(), recorder.edits(), k);   // edit_log.h
//
// What is recorded: field writes (h.next = x, v.position = p, ...), each field of h:set_neighbors(...) as its
// own edit, mesh:new_*(), mesh:delete(x), and the operations flip/split/collapse/loop_subdivide/restore/undo/
// redo run through the mesh API (operations refused by the core change nothing and are not recorded). Changes
// the host makes in C++ are not recorded. `where` is "file.lua:LINE" of the innermost Lua line (the file's
// name without its folders), found when the change is made.
//
// Invariants:
// - Only changes to the given mesh object are recorded (a student's scratch copy is not), from any coroutine
//   of the state, for as long as the recorder is recording; recorders nest (each one sees every change).
// - replay(*before(), edits(), edits().size()) is same_as the mesh when recording stopped, provided nothing but
//   the Lua API changed the mesh meanwhile.
// - At most max_edits are kept: the change after that raises a Lua error in the script ("more than N changes
//   recorded ...") and is not made, so a runaway loop cannot exhaust memory through the log.
// - Safe to outlive the Lua state: when the state closes the recorder just stops.
#pragma once

#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include "core/edit_log.h"
#include "core/halfedge_mesh.h"

struct lua_State;

namespace meshedit {

struct BindingState;

class EditRecorder {
 public:
  static constexpr size_t kDefaultMaxEdits = size_t(1) << 20;

  struct Options {
    bool keep_before = true;  // copy the mesh when recording starts (before())
    size_t max_edits = kDefaultMaxEdits;
  };

  // Starts recording. open_mesh_bindings must have run on L (LuaRuntime does it); throws ScriptError otherwise.
  EditRecorder(lua_State* L, std::shared_ptr<HalfedgeMesh> mesh, Options options);
  EditRecorder(lua_State* L, std::shared_ptr<HalfedgeMesh> mesh) : EditRecorder(L, std::move(mesh), Options{}) {}
  ~EditRecorder();
  EditRecorder(const EditRecorder&) = delete;
  EditRecorder& operator=(const EditRecorder&) = delete;

  // Stops recording (idempotent); the edits stay.
  void stop();
  bool recording() const { return state_ != nullptr; }

  // The mesh as it was when recording started (null when Options::keep_before is false).
  const std::shared_ptr<const HalfedgeMesh>& before() const { return before_; }
  const std::vector<RecordedEdit>& edits() const { return edits_; }
  std::vector<RecordedEdit> take_edits() { return std::move(edits_); }

  // ---- for the bindings ---------------------------------------------------------------------------------
  bool watches(const HalfedgeMesh* mesh) const { return mesh == mesh_.get(); }
  bool full() const { return edits_.size() >= max_edits_; }
  size_t max_edits() const { return max_edits_; }
  void append(RecordedEdit edit) { edits_.push_back(std::move(edit)); }
  // The Lua state is closing: stop without touching it.
  void detach() { state_ = nullptr; }

 private:
  BindingState* state_ = nullptr;
  std::shared_ptr<HalfedgeMesh> mesh_;
  std::shared_ptr<const HalfedgeMesh> before_;
  std::vector<RecordedEdit> edits_;
  size_t max_edits_;
};

// Pushes the list mesh:record returns: one table per edit, {what="set"|"new"|"delete"|"operation",
// element="h3", field="next", before="h4", after="h7", where="flip.lua:12"} (texts from edit_log.h's
// format_edit_before/after; a new vertex also has position = vec3).
void push_edit_log(lua_State* L, std::span<const RecordedEdit> edits);

}  // namespace meshedit
