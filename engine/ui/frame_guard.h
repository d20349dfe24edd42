// The window's last line of defence: runs one frame's input handling and panels, and when an exception still escapes
// them (memory running out in code that does not handle it, a bug), shows it as an Error in the status line instead
// of letting it end the program.
//
// Invariants: only std::exception and what derives from it (std::bad_alloc included) is caught; what the frame did
// before the throw stays (the document's own entry points keep it consistent: mesh_document.h); ImGui's Begin/End,
// Push/Pop, table and tree stacks are closed, so the frame can still be rendered and the next one starts clean; the
// message is report_escaped_exception's (document/exception_report.h, which guards what runs outside a frame). Not the
// protection against running out of memory, only what stops the app from terminating when something was missed.
#pragma once

#include <exception>

#include "document/exception_report.h"
#include "document/mesh_document.h"

namespace meshedit {

// What run_guarded_frame does with an exception that escaped the frame: closes ImGui's open windows and stacks and
// sets an Error message. Call between ImGui::NewFrame() and ImGui::Render(). Never throws.
void recover_from_escaped_exception(MeshDocument& doc, const std::exception& error) noexcept;

// Runs `frame()`; an exception that escapes it goes to recover_from_escaped_exception.
template <class Frame>
void run_guarded_frame(MeshDocument& doc, Frame&& frame) {
  try {
    frame();
  } catch (const std::exception& error) {
    recover_from_escaped_exception(doc, error);
  }
}

}  // namespace meshedit
