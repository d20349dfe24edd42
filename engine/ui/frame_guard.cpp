// The frame guard's recovery (see frame_guard.h).
#include "ui/frame_guard.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <new>
#include <string>

namespace meshedit {

void recover_from_escaped_exception(MeshDocument& doc, const std::exception& error) noexcept {
  // Ends every window, table, tree, ID and style push the frame left open (ImGui's own recovery, ImGui >= 1.80).
  ImGui::ErrorCheckEndFrameRecover(nullptr);
  const bool out_of_memory = dynamic_cast<const std::bad_alloc*>(&error) != nullptr;
  set_message_noexcept(doc, Severity::Error, [&] {
    return out_of_memory ? std::string("memory ran out; the last action did not finish")
                         : std::string("the last action failed: ") + error.what();
  });
}

}  // namespace meshedit
