// Exceptions as the status line's Error, reported without failing in turn: what the window does with an exception an
// action reports itself (a file that would not open or save) and with one that escaped an action altogether (a key,
// a dropped file, a scripted action, a whole frame: run_guarded), instead of letting it end the program.
//
// Invariants: the reports never throw. They change doc.message only, so whatever the action did before the throw
// stays as the document's entry points left it (mesh_document.h). When memory has run out (std::bad_alloc, or no
// memory left to copy the exception's message) the text is kMemoryRanOut's or falls back to it, which allocates
// nothing. Only std::exception and what derives from it is caught.
#pragma once

#include <exception>

#include "document/mesh_document.h"

namespace meshedit {

// An Error with `error`'s own message ("cow.obj: cannot open the file"); kMemoryRanOut for std::bad_alloc.
void report_exception(MeshDocument& doc, const std::exception& error) noexcept;

// An Error for an exception that escaped an action: "the last action failed: WHAT", or for std::bad_alloc "memory
// ran out; the last action did not finish".
void report_escaped_exception(MeshDocument& doc, const std::exception& error) noexcept;

// Runs `action()`; a std::exception that escapes it goes to report_escaped_exception instead of further up.
template <class Action>
void run_guarded(MeshDocument& doc, Action&& action) {
  try {
    action();
  } catch (const std::exception& error) {
    report_escaped_exception(doc, error);
  }
}

}  // namespace meshedit
