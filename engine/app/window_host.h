// What the window's host does differently on a desktop and in a web page, behind one set of functions (the one seam
// between GlfwWindow and run_window and the platform): window_host_native.cpp (GLFW on X11/Wayland) or
// window_host_web.cpp (emscripten's GLFW on the page's canvas); engine/app/CMakeLists.txt picks one.
//
// Invariants: the rest of the app never asks which host it runs on. On the desktop run_frame_loop returns after the
// last frame; in a page the browser owns the loop (one call of `frame` per animation frame), run_frame_loop returns
// to nobody, and everything the frames use must outlive the call (heap-held, captured by the callbacks). A page's
// window is its canvas: the browser's viewport at the device pixel ratio (sharp on HiDPI), followed on every frame.
// A page reaches the user's disk only through the browser: a file the user picks or drops on the page is written
// whole into the program's in-memory file system and handed over here, and a file the program writes for the user
// (a screenshot, a saved mesh) is downloaded by the browser.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

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

// Whether the program's files (lessons, exercises) are files on the user's disk, which the user can edit in an editor
// of their own and the program reloads. A page's files are packaged into its in-memory file system instead.
bool host_files_on_users_disk();

// Whether the host has a file picker of its own for the user's disk (a page: the browser's). The desktop has none:
// the window's Open panel reads the disk itself.
bool host_has_file_picker();

// Shows the host's file picker (nothing without one). The file the user picks arrives later through
// host_take_received_files. A browser shows it only shortly after a click or a key press on the page.
void host_show_file_picker();

// The files the user handed the page since the last call (picked, or dropped anywhere on the page), in the order
// they arrived, each a path in the program's file system (/uploads/NAME) to open as a dropped file is opened. Always
// empty on the desktop, whose drops arrive through GLFW (GlfwWindow::take_dropped_files).
std::vector<std::string> host_take_received_files();

// Gives the user a file the program has just written at `written`. On the desktop it stays where it is and this
// returns "". In a page the browser downloads its bytes under its file name; this returns the words for the status
// line ("downloaded as NAME"), and throws std::runtime_error when the browser could not start the download.
std::string host_hand_over(const std::filesystem::path& written);

// Keeps a file the user changed in the program (the student's code, saved in the window's editor) where it outlives
// the program. On the desktop it is on the user's disk already: returns "". In a page the browser's storage
// (IndexedDB) keeps the page's student folder, and web/index.html puts it back before the program starts; this
// returns the words for the status line ("kept in this browser") and starts the write, which finishes a moment later.
std::string host_keep_file(const std::filesystem::path& written);

// Drafts: the student's unsaved text of a student file (`name`: flip.lua), kept where a page reloaded or closed by
// mistake finds it again. In a page the browser's storage keeps them beside the saved files (written a moment after
// the call); the desktop keeps none (its student files are on the user's disk, and its window closes on purpose).
// host_keep_draft returns "" when kept (or not kept by design), else what went wrong; host_kept_draft gives the
// draft kept for `name`, or nullopt; host_drop_draft forgets it (the file was saved or replaced).
std::string host_keep_draft(const std::string& name, const std::string& text);
std::optional<std::string> host_kept_draft(const std::string& name);
void host_drop_draft(const std::string& name);

}  // namespace meshedit
