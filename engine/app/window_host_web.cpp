// The web page's host of the window (see window_host.h): the browser's animation-frame loop, and a canvas that fills
// the page's viewport at its device pixel ratio. Emscripten's GLFW makes the canvas the window: window and framebuffer
// sizes are both the canvas's size in device pixels, and mouse positions arrive in those pixels too.
// Files: web/index.html owns the page's file picker (<input id="open-file">) and the drop on the page; it writes each
// file the user hands over into /uploads and calls meshedit_receive_file. Downloads are made here from the file's
// bytes in the in-memory file system. The student's saved files are copied into the browser's storage (IndexedDB,
// mounted by web/index.html at /kept), which the page puts back over the packaged scripts/student at its next start;
// drafts (the editor's unsaved text) are kept in /kept/drafts, which only the editor reads.
#include <GLFW/glfw3.h>
#include <emscripten/emscripten.h>
#include <emscripten/html5.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <new>
#include <stdexcept>
#include <utility>
#include <vector>

#include "app/window_host.h"
#include "core/file_bytes.h"
#include "core/translation.h"

// The page's JavaScript (clang-format would space its operators as C++).
// clang-format off
// Clicks the page's hidden file input; 0 when the page has none (a host page other than web/index.html).
EM_JS(int, page_show_file_picker, (), {
  const input = document.getElementById("open-file");
  if (!input) return 0;
  input.click();
  return 1;
});

// Has the browser download the file at `path` as `name`; "" when it started, else what went wrong.
EM_JS(char*, page_download, (const char* path, const char* name, const char* type), {
  try {
    const blob = new Blob([FS.readFile(UTF8ToString(path))], {type: UTF8ToString(type)});
    const link = document.createElement("a");
    link.href = URL.createObjectURL(blob);
    link.download = UTF8ToString(name);
    document.body.appendChild(link);
    link.click();
    link.remove();
    setTimeout(() => URL.revokeObjectURL(link.href), 60000);
    return allocateUTF8("");
  } catch (e) {
    return allocateUTF8(String(e && e.message ? e.message : e));
  }
});
// Copies the file at `path` into the browser's storage (web/index.html mounts IndexedDB at /kept and puts its
// student/ files back over the packaged ones before the program starts) and starts the write; "" when it started.
EM_JS(char*, page_keep_file, (const char* path), {
  try {
    const from = UTF8ToString(path);
    FS.mkdirTree('/kept/student');
    FS.writeFile('/kept/student/' + from.split('/').pop(), FS.readFile(from));
    FS.syncfs(false, (error) => {
      if (error) err('meshedit: the browser did not keep ' + from + ': ' + error);
    });
    return allocateUTF8("");
  } catch (e) {
    return allocateUTF8(String(e && e.message ? e.message : e));
  }
});
// Writes /kept (the browser's storage) back to IndexedDB; the write finishes a moment later.
EM_JS(void, page_sync_kept, (), {
  FS.syncfs(false, (error) => {
    if (error) err('meshedit: the browser did not keep the files of /kept: ' + error);
  });
});
// clang-format on

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

// Where the page keeps drafts: a folder of the browser's storage that web/index.html mounts (not put back over the
// packaged files: a draft is unsaved text, taken back by the editor only).
const std::filesystem::path kDraftFolder = "/kept/drafts";

std::vector<std::string>& received_files() {
  static std::vector<std::string> files;
  return files;
}

}  // namespace

// Called by the page (web/index.html) for each file the user picked or dropped, once its bytes are at `path`.
extern "C" EMSCRIPTEN_KEEPALIVE void meshedit_receive_file(const char* path) {
  try {
    received_files().emplace_back(path);
  } catch (const std::bad_alloc&) {
    std::fputs("meshedit: out of memory: a file handed to the page was not opened\n", stderr);
  }
}

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

bool host_files_on_users_disk() { return false; }

bool host_has_file_picker() { return true; }

void host_show_file_picker() {
  if (!page_show_file_picker()) std::fputs("meshedit: this page has no file picker (#open-file)\n", stderr);
}

std::vector<std::string> host_take_received_files() { return std::exchange(received_files(), {}); }

std::string host_hand_over(const std::filesystem::path& written) {
  const std::string name = written.filename().string();
  const char* type = written.extension() == ".png" ? "image/png" : "application/octet-stream";
  std::unique_ptr<char, void (*)(void*)> failure(page_download(written.c_str(), name.c_str(), type), std::free);
  if (failure && *failure) {
    throw std::runtime_error(
        tr_format("the browser could not download {file}: {why}", {{"file", name}, {"why", failure.get()}}));
  }
  return tr_format("downloaded as {file}", {{"file", name}});
}

std::string host_keep_file(const std::filesystem::path& written) {
  std::unique_ptr<char, void (*)(void*)> failure(page_keep_file(written.c_str()), std::free);
  if (failure && *failure) return tr_format("not kept in this browser: {why}", {{"why", failure.get()}});
  return tr("kept in this browser");
}

std::string host_keep_draft(const std::string& name, const std::string& text) {
  std::error_code error;
  std::filesystem::create_directories(kDraftFolder, error);
  if (error) return tr_format("this browser keeps no drafts: {why}", {{"why", error.message()}});
  if (std::string failure = write_file_bytes(kDraftFolder / name, text); !failure.empty()) return failure;
  page_sync_kept();
  return "";
}

std::optional<std::string> host_kept_draft(const std::string& name) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(kDraftFolder / name, error)) return std::nullopt;
  FileBytes draft = read_file_bytes(kDraftFolder / name, kMaxStudentFileBytes);
  if (!draft.ok()) return std::nullopt;
  return std::move(draft.bytes);
}

void host_drop_draft(const std::string& name) {
  std::error_code error;
  if (std::filesystem::remove(kDraftFolder / name, error)) page_sync_kept();
}

}  // namespace meshedit
