// GlfwWindow: one OS window with an OpenGL 3.3 core context and Dear ImGui set up on it (GLFW and
// OpenGL3 backends); in the web build, the page's canvas with a WebGL 2 context (what differs: window_host.h).
// RAII: the constructor creates everything or throws std::runtime_error with a message a user can act on ("no
// display: ..."); the destructor tears it all down in reverse order.
//
// Input is read through ImGui's io each frame (keys, mouse, wheel), so the app has one input path;
// files dropped on the window are queued and handed out by take_dropped_files().
//
// Size: asked for a size with fit_to_screen, the window opens no larger than the primary monitor's work area (a
// 1280x800 window on a 1024x640 screen opens at the screen's size). Look: apply_look sets the fonts (ui/fonts.h) at
// the text size times the monitor's content scale, the theme's colours and the style's sizes at that scale, and
// uploads the font atlas again; call it outside a frame (before begin_frame), again when content_scale_changed().
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "document/settings.h"
#include "ui/fonts.h"

struct GLFWwindow;

namespace meshedit {

class GlfwWindow {
 public:
  GlfwWindow(const std::string& title, int width, int height, bool fit_to_screen = false);
  ~GlfwWindow();
  GlfwWindow(const GlfwWindow&) = delete;
  GlfwWindow& operator=(const GlfwWindow&) = delete;

  bool should_close() const;
  // Takes back a close the user asked for (the window's close button), so the next frames run (the app asks first).
  void cancel_close();
  // Waits for input when the last frames were idle (see set_lazy), polls events, starts an ImGui frame.
  void begin_frame();
  // How long the last begin_frame() waited for input, in milliseconds (0 when it only polled).
  float last_wait_ms() const { return last_wait_ms_; }
  // Lazy mode: after a few frames with no input, sleep until the next event (or a second passes) instead of
  // redrawing at the display's rate: an idle window costs nothing, even with a million triangles. Off for
  // scripted runs, which need every frame.
  void set_lazy(bool lazy) { lazy_ = lazy; }
  // Renders ImGui's draw data over whatever was drawn, calls `before_swap` (screenshots read the finished
  // frame there), then swaps buffers.
  void end_frame(const std::function<void()>& before_swap = {});

  // Framebuffer size in pixels (what glViewport and glReadPixels use).
  int framebuffer_width() const;
  int framebuffer_height() const;
  std::vector<std::string> take_dropped_files();
  // True once after a drop whose paths could not all be queued (memory ran out in GLFW's callback).
  bool take_drop_lost();
  void set_title(const std::string& title);
  // The window's size in screen coordinates (what the settings remember); set_size asks the window system for one.
  void set_size(int width, int height);
  int width() const;
  int height() const;
  // The monitor's content scale (1 on an ordinary screen, 2 on a HiDPI one) divided by how many framebuffer pixels
  // a window coordinate holds (2 on macOS's Retina screens, where ImGui's coordinates are points).
  float ui_scale() const;
  // Framebuffer pixels per window coordinate, at least 1 (2 on a Retina screen, 1 elsewhere).
  float pixels_per_coordinate() const;
  // True once after the window moved to a monitor of another content scale.
  bool take_content_scale_changed();
  // Applies the text size (pixels at content scale 1) and the theme; returns what the fonts became.
  // Not const: it changes the window's fonts and style (ImGui's state), though no field of this object.
  FontsLoaded apply_look(float font_px, Theme theme);

 private:
  static void note_input(GLFWwindow* window);

  GLFWwindow* window_ = nullptr;
  std::vector<std::string> dropped_;
  bool drop_lost_ = false;
  bool content_scale_changed_ = false;
  bool frame_begun_ = false;  // the backend made its GL objects (the first begin_frame)
  bool lazy_ = true;
  bool input_seen_ = true;  // set by the input callbacks, cleared each frame
  int quiet_frames_ = 0;    // frames since the last input
  float last_wait_ms_ = 0.0f;
};

}  // namespace meshedit
