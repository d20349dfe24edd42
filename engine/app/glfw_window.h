// GlfwWindow: one OS window with an OpenGL 3.3 core context and Dear ImGui set up on it (GLFW and
// OpenGL3 backends). RAII: the constructor creates everything or throws std::runtime_error with a
// message a user can act on ("no display: ..."); the destructor tears it all down in reverse order.
//
// Input is read through ImGui's io each frame (keys, mouse, wheel), so the app has one input path;
// files dropped on the window are queued and handed out by take_dropped_files().
#pragma once

#include <functional>
#include <string>
#include <vector>

struct GLFWwindow;

namespace meshedit {

class GlfwWindow {
 public:
  GlfwWindow(const std::string& title, int width, int height);
  ~GlfwWindow();
  GlfwWindow(const GlfwWindow&) = delete;
  GlfwWindow& operator=(const GlfwWindow&) = delete;

  bool should_close() const;
  void request_close();
  // Waits for input when the last frames were idle (see set_lazy), polls events, starts an ImGui frame.
  void begin_frame();
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

 private:
  static void note_input(GLFWwindow* window);

  GLFWwindow* window_ = nullptr;
  std::vector<std::string> dropped_;
  bool drop_lost_ = false;
  bool lazy_ = true;
  bool input_seen_ = true;  // set by the input callbacks, cleared each frame
  int quiet_frames_ = 0;    // frames since the last input
};

}  // namespace meshedit
