// The frame guard's recovery (see frame_guard.h).
#include "ui/frame_guard.h"

#include <imgui.h>
#include <imgui_internal.h>

namespace meshedit {

void recover_from_escaped_exception(MeshDocument& doc, const std::exception& error) noexcept {
  // Ends every window, table, tree, ID and style push the frame left open (ImGui's own recovery, ImGui >= 1.80).
  ImGui::ErrorCheckEndFrameRecover(nullptr);
  report_escaped_exception(doc, error);
}

}  // namespace meshedit
