// The text of a C++ exception for a lesson's error (the runner's error(), a Lua error raised from a host call), made
// without failing in turn: out of memory must become an error that says so, not a second exception. And whether an
// exception is memory running out, told by its type, never by its text (a script may say "memory ran out" itself).
//
// Invariants: never throws. std::bad_alloc, and any exception whose message cannot be copied for lack of memory,
// give kScriptMemoryRanOut, which fits std::string's inline buffer and so allocates nothing.
#pragma once

#include <exception>
#include <new>
#include <string>

#include "script/lua_runtime.h"

namespace meshedit {

inline constexpr char kScriptMemoryRanOut[] = "memory ran out";  // as document/mesh_document.h's kMemoryRanOut
static_assert(sizeof(kScriptMemoryRanOut) <= 16, "held in std::string's inline buffer (15 characters)");

// Whether `error` is memory running out: a std::bad_alloc, or a ScriptError raised for one
// (ScriptError::out_of_memory).
inline bool is_out_of_memory(const std::exception& error) noexcept {
  if (dynamic_cast<const std::bad_alloc*>(&error)) return true;
  const auto* script_error = dynamic_cast<const ScriptError*>(&error);
  return script_error && script_error->out_of_memory();
}

// exception_text, also telling whether memory ran out: `error` is memory running out, or its message could not be
// copied for lack of it.
inline std::string exception_text(const std::exception& error, bool& out_of_memory) noexcept {
  out_of_memory = true;
  if (dynamic_cast<const std::bad_alloc*>(&error)) return kScriptMemoryRanOut;
  try {
    std::string text = error.what();
    out_of_memory = is_out_of_memory(error);
    return text;
  } catch (...) {
    return kScriptMemoryRanOut;
  }
}

inline std::string exception_text(const std::exception& error) noexcept {
  bool out_of_memory = false;
  return exception_text(error, out_of_memory);
}

// exception_text for the Lua error a C function running on `L` raises in the exception's place: memory running out
// is noted in the runtime that owns `L` (LuaRuntime::note_out_of_memory), so the error is known for what it is.
inline std::string lua_error_text(lua_State* L, const std::exception& error) noexcept {
  bool out_of_memory = false;
  std::string text = exception_text(error, out_of_memory);
  if (out_of_memory) LuaRuntime::note_out_of_memory(L);
  return text;
}

}  // namespace meshedit
