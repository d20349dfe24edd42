// EditorApp: opening files, whole or nothing, across the rooms (see editor_app.h). The document room reads and builds
// everything a file needs (DocumentRoom::prepare_file, which throws with nothing changed) while the window still shows
// what it showed; a running exercise replay is finished first; then take_file switches the view (and the document)
// and the title, the recent list and the message with steps that cannot fail. A mesh file the builder refuses as not
// a manifold is remembered, and File > Open a repaired copy opens it repaired in the same way, the Repairs tab in
// front.
#include <new>

#include "app/editor_app.h"
#include "core/mesh_build.h"
#include "core/mesh_error.h"
#include "core/primitives.h"
#include "core/translation.h"
#include "document/bug_report.h"
#include "document/exception_report.h"
#include "ui/frame_guard.h"

namespace meshedit {

void EditorApp::take_file(PreparedFile& file) noexcept {
  if (file.mesh || file.patches) view_.set_file_up_axis(file.up_axis);  // a curve is drawn in its plane
  if (file.mesh) view_.take_mesh(std::move(*file.mesh), std::move(file.name));
  if (file.curve) view_.take_curve(std::move(*file.curve));
  if (file.patches) view_.take_patches(std::move(*file.patches));
  const bool repaired = file.repairs.has_value();
  document_.take_opened(file);
  if (repaired) panels_.bring_forward(RightTab::Repairs);
}

bool EditorApp::open(const std::filesystem::path& path) {
  if (path.extension() == ".lua") return lessons_.open(path);
  if (path.extension() == kBugReportExtension) return open_bug_report(path);
  bool not_a_manifold = false;
  try {
    exercises_.session().finish_replay(document_.doc());
    PreparedFile file = document_.prepare_file(path, not_a_manifold);
    take_file(file);
    return true;
  } catch (const std::exception& e) {
    // Nothing was switched yet: the window shows what it showed.
    document_.refuse(path, e, not_a_manifold && dynamic_cast<const MeshError*>(&e) != nullptr);
    return false;
  }
}

bool EditorApp::open_repaired() {
  try {
    exercises_.session().finish_replay(document_.doc());
    PreparedFile file = document_.prepare_repaired();
    take_file(file);
    return true;
  } catch (const std::exception& e) {
    report_exception(document_.doc(), e);
    return false;
  }
}

void EditorApp::open_dropped(const std::vector<std::string>& paths) {
  // Called between frames, outside the frame guard: each file under its own guard, so what escapes opening one (a
  // path that cannot be made for lack of memory) is an Error in the status line and the next file still opens.
  for (const std::string& path : paths) run_guarded(document_.doc(), [&] { open(path); });
}

void EditorApp::receive_files(const std::vector<std::string>& paths) {
  std::vector<std::string> others;
  for (const std::string& path : paths) {
    switch (exercises_.take_received_file(path)) {
      case ExerciseRoom::Received::NotStudentFile: others.push_back(path); break;
      case ExerciseRoom::Received::Refused: break;
      case ExerciseRoom::Received::Taken: show_student_code(); break;
    }
  }
  if (!others.empty()) open_dropped(others);
}

void EditorApp::show_mesh(HalfedgeMesh mesh, const std::string& name) {
  std::string title = DocumentRoom::window_title(name.empty() ? std::string(tr("untitled")) : name);
  std::string path = name;
  view_.take_made_mesh(std::move(mesh), std::move(path));
  document_.take_title(title, false);
}

void EditorApp::show_start_mesh() {
  try {
    show_mesh(build_halfedge_mesh(make_cube()), "");
  } catch (const std::bad_alloc&) {
    // show_mesh is whole or nothing: the document is as it was (as the window starts, the empty one).
    set_message_noexcept(document_.doc(), Severity::Error, [] {
      return std::string(tr("memory ran out making the start-up cube; open a file to start"));
    });
  } catch (const std::exception& e) {
    report_exception(document_.doc(), e);  // never expected: the cube is a valid mesh
  }
}

}  // namespace meshedit
