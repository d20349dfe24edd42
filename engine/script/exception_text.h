// The text of a C++ exception for a lesson's error (the runner's error(), a Lua error raised from a host call), made
// without failing in turn: out of memory must become an error that says so, not a second exception.
//
// Invariants: never throws. std::bad_alloc, and any exception whose message cannot be copied for lack of memory,
// give kScriptMemoryRanOut, which fits std::string's inline buffer and so allocates nothing.
#pragma once

#include <exception>
#include <new>
#include <string>

namespace meshedit {

inline constexpr char kScriptMemoryRanOut[] = "memory ran out";  // as ui/mesh_document.h's kMemoryRanOut
static_assert(sizeof(kScriptMemoryRanOut) <= 16, "held in std::string's inline buffer (15 characters)");

inline std::string exception_text(const std::exception& error) noexcept {
  if (dynamic_cast<const std::bad_alloc*>(&error)) return kScriptMemoryRanOut;
  try {
    return error.what();
  } catch (...) {
    return kScriptMemoryRanOut;
  }
}

// Whether a lesson's error is memory running out: exception_text's, or a Lua error made of it ("hot.lua:2: memory ran
// out"). A retry can make it go away, unlike the file's own errors.
inline bool ran_out_of_memory(const std::string& error) noexcept { return error.ends_with(kScriptMemoryRanOut); }

}  // namespace meshedit
