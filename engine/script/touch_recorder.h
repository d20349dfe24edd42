// TouchRecorder: counts which elements of one mesh Lua code touched while the host ran it, so a check can tell a
// local operation (a flip reaches the two triangles at its edge) from one that walks the whole mesh:
//
//   TouchRecorder touches(lua.state(), mesh);    // counting starts
//   ... call the student's flip_edge through the runtime ...
//   const TouchCount count = touches.count();   // {elements = 21, written = 10, whole_mesh_call = ""}
//
// What counts as touching an element: the script got a handle to it (an iterator's step, a field read such as
// h.next, m:element("h3"), a new_* call: every handle the script holds was made so), or changed it (a field write,
// new_*, delete, an operation's edge). A call that reads every element in C++ (mesh:copy, :snapshot, :validate,
// :tables, :diff, and the whole-mesh operations restore, undo, redo and the subdivisions) touches the whole mesh.
// Walks in C++ that stay at one element's neighbours (v:degree(), h:prev()) count only the handles they return.
//
// Invariants:
// - Each element is counted once, however often it is touched: elements is the number of distinct (kind, id)
//   pairs, written those of them that were changed; written <= elements.
// - Only the given mesh object is watched (a scratch copy the script makes is not), from any coroutine of the
//   state, for as long as the recorder counts; recorders nest (each sees every touch).
// - Memory is one flag per id of the watched mesh: never more than the mesh itself holds.
// - Safe to outlive the Lua state: when the state closes the recorder just stops (its count stays).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/edit_log.h"
#include "core/halfedge_mesh.h"

struct lua_State;

namespace meshedit {

struct BindingState;

// What one run touched of one mesh.
struct TouchCount {
  size_t elements = 0;          // distinct elements touched; every live element when whole_mesh_call is set
  size_t written = 0;           // of those, the ones changed (written, created, deleted, an operation's edge)
  std::string whole_mesh_call;  // the first call that read every element ("mesh:copy()"), empty when none
};

class TouchRecorder {
 public:
  // Starts counting. open_mesh_bindings must have run on L (LuaRuntime does it); throws ScriptError otherwise.
  TouchRecorder(lua_State* L, std::shared_ptr<const HalfedgeMesh> mesh);
  ~TouchRecorder();
  TouchRecorder(const TouchRecorder&) = delete;
  TouchRecorder& operator=(const TouchRecorder&) = delete;

  // Stops counting (idempotent); the count stays.
  void stop();
  // The count so far; a whole-mesh read counts the mesh's live elements as they are now.
  TouchCount count() const;
  const std::shared_ptr<const HalfedgeMesh>& mesh() const { return mesh_; }

  // ---- for the bindings ---------------------------------------------------------------------------------
  bool watches(const HalfedgeMesh* mesh) const { return mesh == mesh_.get(); }
  void touch(ElementRef element);
  void write(ElementRef element);
  void touch_whole_mesh(const char* call);
  // The Lua state is closing: stop without touching it.
  void detach() { state_ = nullptr; }

 private:
  // Marks the element in `seen` (one flag per id); true when it was not marked yet.
  static bool mark(std::array<std::vector<bool>, kElementKindCount>& seen, ElementRef element);

  BindingState* state_ = nullptr;
  std::shared_ptr<const HalfedgeMesh> mesh_;
  std::array<std::vector<bool>, kElementKindCount> touched_{};
  std::array<std::vector<bool>, kElementKindCount> written_{};
  size_t touched_count_ = 0;
  size_t written_count_ = 0;
  std::string whole_mesh_call_;
};

// The hooks the bindings call (cheap when nothing counts: one test of an empty list).
// A handle for `element` of `mesh` was made.
void note_touch(BindingState& state, const HalfedgeMesh* mesh, ElementRef element);
// `edit` changed `mesh`: its element (a Set, Create or Delete; a flip's, split's or collapse's edge), or the whole
// mesh for an operation on all of it (restore, undo, redo, a subdivision).
void note_change(BindingState& state, const HalfedgeMesh* mesh, const RecordedEdit& edit);
// `call` ("mesh:copy()") read every element of `mesh`.
void note_whole_mesh_read(lua_State* L, const HalfedgeMesh* mesh, const char* call);

}  // namespace meshedit
