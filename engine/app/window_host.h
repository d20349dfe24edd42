// What the window's host does differently on a desktop and in a web page, behind one set of functions (the one seam
// between GlfwWindow and run_window and the platform): window_host_native.cpp (GLFW on X11/Wayland) or
// window_host_web.cpp (emscripten's GLFW on the page's canvas); engine/app/CMakeLists.txt picks one.
//
// Invariants: the rest of the app never asks which host it runs on. On the desktop run_frame_loop returns after the
// last frame; in a page the browser owns the loop (one call of `frame` per animation frame), run_frame_loop returns
// to nobody, and everything the frames use must outlive the call (heap-held, captured by the callbacks). A page's
// window is its canvas: the browser's viewport at the device pixel ratio (sharp on HiDPI), followed on every frame.
#pragma once

#include <functional>
#include <string>

struct GLFWwindow;

namespace meshedit {

// Calls frame() once per displayed frame until it returns false, then finish() once.
void run_frame_loop(std::function<bool()> frame, std::function<void()> finish);

// Whether begin_frame may block waiting for input (a desktop window that is idle); a page must never block.
bool host_may_wait_for_input();

// The size to create the window at: the asked size, fitted to the screen's work area when `fit_to_screen` (desktop);
// the page's viewport in device pixels (web, which ignores the asked size).
void host_window_size(int& width, int& height, bool fit_to_screen);

// Per frame, before polling input: a page's canvas takes the viewport's size again after the browser window changed.
void host_follow_page(GLFWwindow* window);

// The monitor's content scale (1 on an ordinary screen, 2 on a HiDPI one): GLFW's on a desktop, the device pixel ratio
// in a page.
float host_content_scale(GLFWwindow* window);

// Installs `changed` to run when the window moves to a monitor of another content scale (desktop only: a page keeps
// its device pixel ratio until reloaded).
void host_watch_content_scale(GLFWwindow* window, void (*changed)(GLFWwindow*, float, float));

// What went wrong in GLFW's last call, for error messages.
std::string host_last_error();

// The words a user needs when no window can be opened.
std::string host_no_window_hint();

}  // namespace meshedit
