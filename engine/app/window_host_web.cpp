// The web page's host of the window (see window_host.h): the browser's animation-frame loop, and a canvas that fills
// the page's viewport at its device pixel ratio. Emscripten's GLFW makes the canvas the window: window and framebuffer
// sizes are both the canvas's size in device pixels, and mouse positions arrive in those pixels too.
#include <GLFW/glfw3.h>
#include <emscripten/emscripten.h>
#include <emscripten/html5.h>

#include <cmath>
#include <memory>
#include <utility>

#include "app/window_host.h"

namespace meshedit {
namespace {

struct FrameLoop {
  std::function<bool()> frame;
  std::function<void()> finish;
};

void one_frame(void* arg) {
  auto* loop = static_cast<FrameLoop*>(arg);
  if (loop->frame()) return;
  emscripten_cancel_main_loop();
  std::unique_ptr<FrameLoop> ended(loop);
  ended->finish();
}

// The page's viewport (the canvas's CSS box, which web/index.html makes the whole viewport) in device pixels.
std::pair<int, int> viewport_pixels() {
  double css_w = 0.0, css_h = 0.0;
  emscripten_get_element_css_size("#canvas", &css_w, &css_h);
  const double ratio = emscripten_get_device_pixel_ratio();
  return {std::max(1, int(std::lround(css_w * ratio))), std::max(1, int(std::lround(css_h * ratio)))};
}

}  // namespace

void run_frame_loop(std::function<bool()> frame, std::function<void()> finish) {
  auto* loop = new FrameLoop{std::move(frame), std::move(finish)};
  // fps 0: the browser's requestAnimationFrame paces the frames; simulate_infinite_loop: this call does not return.
  emscripten_set_main_loop_arg(one_frame, loop, 0, 1);
}

bool host_may_wait_for_input() { return false; }

void host_window_size(int& width, int& height, bool) { std::tie(width, height) = viewport_pixels(); }

void host_follow_page(GLFWwindow* window) {
  const auto [width, height] = viewport_pixels();
  int now_w = 0, now_h = 0;
  glfwGetWindowSize(window, &now_w, &now_h);
  if (width != now_w || height != now_h) glfwSetWindowSize(window, width, height);
}

float host_content_scale(GLFWwindow*) { return float(emscripten_get_device_pixel_ratio()); }

void host_watch_content_scale(GLFWwindow*, void (*)(GLFWwindow*, float, float)) {}

std::string host_last_error() { return "the browser gave no WebGL 2 context"; }

std::string host_no_window_hint() { return ". This page needs a browser with WebGL 2"; }

}  // namespace meshedit
