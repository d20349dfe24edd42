// StudentState: the sandboxed Lua state student code runs in during one test, and calls into it from the
// suite's state.
//
// Invariants:
// - One fresh state per test (a new LuaRuntime): nothing a student's code does to its globals, the RNG or
//   metatables outlives the test. Suite code never runs in this state and nothing of the suite's state is
//   reachable from it: values cross by copy (value_bridge.h); meshes are shared C++ objects.
// - The student API is exercise/student_api.h's, the window's own: no file access, and the operations that are
//   exercises (mesh:flip, :split, :collapse, :loop_subdivide, meshedit.curve, meshedit.patch) hidden unless the
//   test allows them by name ("mesh:flip"); a hidden one raises the same words as in the window.
// - Student files all run in the state's one global environment, in the order given, so split.lua may call
//   a helper flip.lua defines (as in a real program). A function is found as a global first, then in the
//   tables the files returned, in load order. Lookups are raw: no student __index runs to find it.
// - The whole test shares one budget window (LuaRuntime::start_budget): loading and every call.
// - Reference functions (reference_functions.h) are set before the files load and again after, so a
//   student's own definition of the same name does not replace them.
// - What the student prints is kept (capped) for the test's output; nothing reaches stdout.
// - A call of a function held to a locality bound (flip_edge, split_edge: exercise/exercise_locality.h) counts what it
//   touched of every mesh it was given (an argument that is a mesh or an element of one; script/touch_recorder.h),
//   so expect.exercise holds it to the window's bound; other calls count nothing.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "grade/submission.h"
#include "script/lua_runtime.h"
#include "script/script_runtime.h"
#include "script/touch_recorder.h"

struct lua_State;

namespace meshedit {

struct StudentOptions {
  LuaLimits limits;
  size_t output_bytes = size_t(64) << 10;
  std::vector<std::string> reference;  // reference functions to install (names checked by the suite loader)
  std::vector<std::string>
      allow_api;  // "mesh:flip", "meshedit.curve", ... (hideable_api_names, exercise/student_api.h)
};

// A student file failed to load (compile or run its top level).
class LoadFailure : public ScriptError {
 public:
  LoadFailure(const std::string& message, Limit limit) : ScriptError(message, limit) {}
};

// What one call touched of one mesh it was given.
struct MeshTouches {
  std::shared_ptr<const HalfedgeMesh> mesh;
  TouchCount count;
};

class StudentState {
 public:
  explicit StudentState(const StudentOptions& options);
  StudentState(const StudentState&) = delete;
  StudentState& operator=(const StudentState&) = delete;

  LuaRuntime& runtime() { return runtime_; }
  // Loads the named files of the submission in order. Throws LoadFailure naming the file: "the submission
  // has no flip.lua", "flip.lua:3: unexpected symbol near '='", "flip.lua:9: time limit exceeded (2 s)".
  void load(const Submission& submission, const std::vector<std::string>& files);
  // Whether the student defines a function `name`.
  bool has(const std::string& name);
  // Calls the student's function `name` with copies of suite[first .. first + nargs - 1]; pushes copies of the
  // results on `suite` and returns their number. Throws ScriptError (the student's error, or a limit) and
  // BridgeError (an argument or result that cannot cross). `suite` must be in protected mode.
  int call(const std::string& name, lua_State* suite, int first, int nargs);

  // What the last call touched of each mesh it was given, in argument order (empty for a call not counted, and after
  // a call that raised).
  const std::vector<MeshTouches>& last_call_touches() const { return last_call_touches_; }

  const std::string& output() const { return output_; }
  bool output_truncated() const { return runtime_.print_truncated(); }

 private:
  void install_references();
  // Pushes the student's function `name` on the student's stack, or nil.
  void push_function(const std::string& name);
  static int call_trampoline(lua_State* L);

  ScriptRuntime runtime_;
  StudentOptions options_;
  std::string output_;
  std::vector<MeshTouches> last_call_touches_;
  int returned_tables_ref_ = -2;  // registry ref of the list of tables the files returned (LUA_NOREF = -2)
};

}  // namespace meshedit
