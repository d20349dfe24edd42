// The desktop host of the window (see window_host.h): GLFW's own loop, monitor work area, content scale and errors;
// the window reads and writes the disk itself, so files need no handing over.
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cstdlib>

#include "app/window_host.h"

namespace meshedit {

// By value, as the web host takes them to keep.
// NOLINTNEXTLINE(performance-unnecessary-value-param)
void run_frame_loop(std::function<bool()> frame, std::function<void()> finish) {
  while (frame()) {
  }
  finish();
}

bool host_may_wait_for_input() { return true; }

void host_window_size(int& width, int& height, bool fit_to_screen) {
  if (!fit_to_screen) return;
  if (GLFWmonitor* monitor = glfwGetPrimaryMonitor()) {
    int x = 0, y = 0, w = 0, h = 0;
    glfwGetMonitorWorkarea(monitor, &x, &y, &w, &h);
    if (w > 0 && h > 0) {
      width = std::min(width, w);
      height = std::min(height, h);
    }
  }
}

void host_follow_page(GLFWwindow*) {}

float host_content_scale(GLFWwindow* window) {
  float sx = 1.0f, sy = 1.0f;
  glfwGetWindowContentScale(window, &sx, &sy);
  return sx;
}

void host_watch_content_scale(GLFWwindow* window, void (*changed)(GLFWwindow*, float, float)) {
  glfwSetWindowContentScaleCallback(window, changed);
}

std::string host_last_error() {
  const char* description = nullptr;
  glfwGetError(&description);
  return description ? description : "unknown GLFW error";
}

std::string host_no_window_hint() {
  const char* display = std::getenv("DISPLAY");
  return std::string(display && *display ? "" : "; DISPLAY is not set") +
         ". Without a display, try `meshedit demo` or `meshedit render`";
}

bool host_files_on_users_disk() { return true; }

bool host_has_file_picker() { return false; }

void host_show_file_picker() {}

std::vector<std::string> host_take_received_files() { return {}; }

std::string host_hand_over(const std::filesystem::path&) { return ""; }

std::string host_keep_file(const std::filesystem::path&) { return ""; }

std::string host_keep_draft(const std::string&, const std::string&) { return ""; }

std::optional<std::string> host_kept_draft(const std::string&) { return std::nullopt; }

void host_drop_draft(const std::string&) {}

}  // namespace meshedit
