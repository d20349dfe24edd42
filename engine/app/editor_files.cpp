// EditorApp: opening and saving files, showing a mesh as a new document, and the recent-files list (see
// editor_app.h).
#include "app/editor_app.h"

#include "app/mesh_loading.h"
#include "core/mesh_build.h"
#include "io/mesh_file.h"
#include "ui/exception_report.h"

namespace meshedit {

namespace {
constexpr size_t kRecentFiles = 8;
}  // namespace

void EditorApp::remember_recent(const std::filesystem::path& path) {
  const std::string text = path.string();
  std::erase(recent_, text);
  recent_.push_front(text);
  if (recent_.size() > kRecentFiles) recent_.pop_back();
}

void EditorApp::show_mesh(HalfedgeMesh mesh, const std::string& name) {
  replace_mesh(doc_, std::move(mesh), name);
  selection_ = {};
  mode_ = ViewMode::Mesh;
  title_ = "MeshEdit - " + (name.empty() ? std::string("untitled") : name);
  mesh_renderer_->update(doc_.mesh);
  fit_camera();
}

bool EditorApp::open(const std::filesystem::path& path) {
  try {
    if (path.extension() == ".lua") return open_lesson(path);
    exercises_.finish_replay(doc_);
    const LoadedFile file = load_file(path);
    switch (file.kind) {
      case FileKind::Curve:
        show_curve(file.curve);
        break;
      case FileKind::Patches:
        show_patches(file.patches);
        break;
      case FileKind::Mesh:
        show_mesh(build_from_file(file.mesh, path).mesh, path.string());
    }
    title_ = "MeshEdit - " + path.filename().string();
    remember_recent(path);
    message(Severity::Info, "opened " + path.string());
    return true;
  } catch (const std::exception& e) {
    // The current document stays (out of memory part-way: the old one or the new one, whole); the report needs no
    // memory, so nothing escapes from here.
    report_exception(doc_, e);
    return false;
  }
}

void EditorApp::open_dropped(const std::vector<std::string>& paths) {
  // Called between frames, outside the frame guard: each file under its own guard, so what escapes opening one (a
  // path that cannot be made for lack of memory) is an Error in the status line and the next file still opens.
  for (const std::string& path : paths) run_guarded(doc_, [&] { open(path); });
}

bool EditorApp::save(const std::filesystem::path& path) {
  try {
    save_mesh(path, to_polygon_mesh(doc_.mesh));
    remember_recent(path);
    message(Severity::Info, "saved " + path.string());
    return true;
  } catch (const std::exception& e) {
    report_exception(doc_, e);
    return false;
  }
}

}  // namespace meshedit
