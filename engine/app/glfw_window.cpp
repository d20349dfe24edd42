// GLFW window + GL 3.3 core context (WebGL 2 in a page) + ImGui backends (see glfw_window.h).
#include "app/glfw_window.h"

// The GL header (render/gl_api.h) comes before every other GL header (GLFW's included).
#include "render/gl_api.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "app/window_host.h"
#include "ui/theme.h"

namespace meshedit {
namespace {

// A width and height from one of GLFW's size getters (the window's, in screen coordinates, or its framebuffer's).
std::pair<int, int> size_of(void (*get)(GLFWwindow*, int*, int*), GLFWwindow* window) {
  int w = 0, h = 0;
  get(window, &w, &h);
  return {w, h};
}

}  // namespace

GlfwWindow::GlfwWindow(const std::string& title, int width, int height, bool fit_to_screen) {
  if (!glfwInit()) throw std::runtime_error("cannot open a window (" + host_last_error() + ")" + host_no_window_hint());
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_SAMPLES, 4);
  host_window_size(width, height, fit_to_screen);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window_) {
    const std::string why = host_last_error();
    glfwTerminate();
    throw std::runtime_error("cannot create an OpenGL 3.3 core window: " + why);
  }
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(1);
  glfwSetWindowUserPointer(window_, this);
  glfwSetDropCallback(window_, [](GLFWwindow* w, int count, const char** paths) {
    auto* self = static_cast<GlfwWindow*>(glfwGetWindowUserPointer(w));
    try {
      for (int i = 0; i < count; ++i) self->dropped_.emplace_back(paths[i]);
    } catch (...) {  // nothing may unwind through GLFW's C code: the paths not queued are reported as lost
      self->drop_lost_ = true;
    }
    self->input_seen_ = true;
  });
  // Installed before ImGui's backend, which chains to them: they only note that input arrived.
  glfwSetCursorPosCallback(window_, [](GLFWwindow* w, double, double) { note_input(w); });
  glfwSetMouseButtonCallback(window_, [](GLFWwindow* w, int, int, int) { note_input(w); });
  glfwSetScrollCallback(window_, [](GLFWwindow* w, double, double) { note_input(w); });
  glfwSetKeyCallback(window_, [](GLFWwindow* w, int, int, int, int) { note_input(w); });
  glfwSetCharCallback(window_, [](GLFWwindow* w, unsigned int) { note_input(w); });
  glfwSetWindowFocusCallback(window_, [](GLFWwindow* w, int) { note_input(w); });
  glfwSetCursorEnterCallback(window_, [](GLFWwindow* w, int) { note_input(w); });
  glfwSetFramebufferSizeCallback(window_, [](GLFWwindow* w, int, int) { note_input(w); });
  glfwSetWindowRefreshCallback(window_, [](GLFWwindow* w) { note_input(w); });
  host_watch_content_scale(window_, [](GLFWwindow* w, float, float) {
    static_cast<GlfwWindow*>(glfwGetWindowUserPointer(w))->content_scale_changed_ = true;
    note_input(w);
  });

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // layout comes from code, not from a file beside the binary
  apply_theme(ImGui::GetStyle(), Theme::Dark);
  ImGui_ImplGlfw_InitForOpenGL(window_, true);
  ImGui_ImplOpenGL3_Init(gl::kGlslVersionLine);
}

GlfwWindow::~GlfwWindow() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window_);
  glfwTerminate();
}

void GlfwWindow::note_input(GLFWwindow* w) {
  static_cast<GlfwWindow*>(glfwGetWindowUserPointer(w))->input_seen_ = true;
}

bool GlfwWindow::should_close() const { return glfwWindowShouldClose(window_); }

void GlfwWindow::cancel_close() { glfwSetWindowShouldClose(window_, GLFW_FALSE); }

void GlfwWindow::begin_frame() {
  // ImGui needs a couple of frames after an input to settle hover states and animations. X delivers
  // events that are not input (ImGui's cursor updates cause some), so only the callbacks below count.
  constexpr int kSettleFrames = 3;
  constexpr double kIdleTimeoutSeconds = 5.0;  // a redraw now and then, even with no input
  last_wait_ms_ = 0.0f;
  host_follow_page(window_);
  if (lazy_ && host_may_wait_for_input() && quiet_frames_ >= kSettleFrames) {
    const double start = glfwGetTime();
    while (!input_seen_ && glfwGetTime() - start < kIdleTimeoutSeconds && !should_close()) {
      glfwWaitEventsTimeout(kIdleTimeoutSeconds - (glfwGetTime() - start));
    }
    last_wait_ms_ = float((glfwGetTime() - start) * 1000.0);
  } else {
    glfwPollEvents();
  }
  quiet_frames_ = input_seen_ ? 0 : quiet_frames_ + 1;
  input_seen_ = false;
  ImGui_ImplOpenGL3_NewFrame();
  frame_begun_ = true;
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
}

void GlfwWindow::end_frame(const std::function<void()>& before_swap) {
  ImGui::Render();
  glViewport(0, 0, framebuffer_width(), framebuffer_height());
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  if (before_swap) before_swap();
  glfwSwapBuffers(window_);
}

int GlfwWindow::framebuffer_width() const { return size_of(glfwGetFramebufferSize, window_).first; }
int GlfwWindow::framebuffer_height() const { return size_of(glfwGetFramebufferSize, window_).second; }

std::vector<std::string> GlfwWindow::take_dropped_files() {
  std::vector<std::string> files;
  files.swap(dropped_);
  return files;
}

bool GlfwWindow::take_drop_lost() { return std::exchange(drop_lost_, false); }

void GlfwWindow::set_title(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }

void GlfwWindow::set_size(int width, int height) { glfwSetWindowSize(window_, width, height); }

int GlfwWindow::width() const { return size_of(glfwGetWindowSize, window_).first; }
int GlfwWindow::height() const { return size_of(glfwGetWindowSize, window_).second; }

float GlfwWindow::pixels_per_coordinate() const {
  const int w = width();
  return w > 0 ? std::max(1.0f, float(framebuffer_width()) / float(w)) : 1.0f;
}

float GlfwWindow::ui_scale() const {
  const float scale = std::max(host_content_scale(window_), 0.5f) / pixels_per_coordinate();
  return std::isfinite(scale) ? std::clamp(scale, 0.5f, 4.0f) : 1.0f;
}

bool GlfwWindow::take_content_scale_changed() { return std::exchange(content_scale_changed_, false); }

FontsLoaded GlfwWindow::apply_look(float font_px, Theme theme) {  // NOLINT(readability-make-member-function-const)
  const float scale = ui_scale();
  const FontsLoaded fonts = load_fonts(font_px, scale, pixels_per_coordinate());
  ImGuiStyle style;
  apply_theme(style, theme);
  style.ScaleAllSizes(scale);
  ImGui::GetStyle() = style;
  if (frame_begun_) {  // before the first frame, the backend's first NewFrame uploads the atlas itself
    ImGui_ImplOpenGL3_DestroyFontsTexture();
    ImGui_ImplOpenGL3_CreateFontsTexture();
  }
  return fonts;
}

}  // namespace meshedit
