// EditorApp: opening and saving files, showing a mesh, a curve or patches as what the window edits, and the
// recent-files list (see editor_app.h).
//
// Whole or nothing: everything that can fail (reading the file, building the mesh, tessellating patches, the window
// title, the new recent list, the message) is made first, while the window still shows what it showed; then the take_*
// steps switch to it with steps that cannot fail (replace_mesh moves the mesh in, its own message falling back to
// kMemoryRanOut; the strings and lists are swapped or moved in; the camera takes the file's up axis, View > Up axis's
// choice going back to "From the file", and is fitted to bounds read from the mesh). The
// renderer comes last: it is a view that every frame updates from the document, so when it cannot take the new mesh at
// once (memory ran out, a mesh too large to draw) it drops what it showed and the next frame tries again, under the
// frame guard, which reports what stops it.
// A mesh file the builder refuses as not a manifold is remembered, and File > Open a repaired copy opens it repaired
// (core/mesh_repair.h), whole or nothing in the same way, listing the changes in the Repairs tab.
// Saving makes the new recent list and the message before it writes the file, and only swaps them in after.
#include <deque>
#include <new>
#include <optional>
#include <stdexcept>
#include <type_traits>

#include "app/editor_app.h"
#include "app/mesh_loading.h"
#include "app/window_host.h"
#include "core/mesh_build.h"
#include "core/mesh_error.h"
#include "core/mesh_repair.h"
#include "core/primitives.h"
#include "document/exception_report.h"
#include "io/mesh_file.h"
#include "render/mesh_geometry.h"

namespace meshedit {

namespace {

constexpr size_t kRecentFiles = 8;

// Moved in whole, without allocating (take_curve, take_patches).
static_assert(std::is_nothrow_move_assignable_v<CurveEditorState>);
static_assert(std::is_nothrow_move_assignable_v<PatchViewState>);

// `recent` with `path` first (moved up when it is there already), at most kRecentFiles long. A new list, so the one
// in use stays as it was when memory runs out making it.
std::deque<std::string> with_recent(const std::deque<std::string>& recent, std::string path) {
  std::deque<std::string> list;
  list.push_back(std::move(path));
  for (const std::string& old : recent) {
    if (list.size() == kRecentFiles) break;
    if (old != list.front()) list.push_back(old);
  }
  return list;
}

// `patches` in a patch view, tessellated: ready to be moved in.
PatchViewState tessellated_view(const std::vector<BezierPatch>& patches) {
  PatchViewState view = make_patch_view(patches);
  update_tessellation(view);
  return view;
}

// Has `renderer` show `mesh` now, so that a pick before the next frame draws finds the new mesh. When it cannot, it
// shows nothing (and picks nothing) until the next frame's update, which tries again under the frame guard.
void refresh_view(MeshRenderer& renderer, const HalfedgeMesh& mesh) noexcept {
  try {
    renderer.update(mesh);
  } catch (const std::exception&) {
    renderer.invalidate();
  }
}

}  // namespace

std::string EditorApp::window_title(const std::string& name) { return std::string(kStartTitle) + " - " + name; }

void EditorApp::fit_camera(const BoundingBox& bounds) { camera_.fit(bounds); }

void EditorApp::take_mesh(HalfedgeMesh&& mesh, std::string&& path, bool fit) {
  const BoundingBox bounds = mesh_bounds(mesh);  // what the renderer's bounds will be, read before the move
  replace_mesh(doc_, std::move(mesh), std::move(path));
  selection_ = {};
  mode_ = ViewMode::Mesh;
  if (apply_up_axis()) fit = true;  // a view turned to a new up axis is fitted again
  if (fit) fit_camera(bounds);
  refresh_view(*mesh_renderer_, doc_.mesh);
}

void EditorApp::take_curve(CurveEditorState&& curve) {
  curve_ = std::move(curve);
  mode_ = ViewMode::Curve;
}

void EditorApp::take_patches(PatchViewState&& patches) {
  patches_ = std::move(patches);
  mode_ = ViewMode::Patches;
  apply_up_axis();
  if (!patches_.tessellation.mesh) return;
  fit_camera(mesh_bounds(*patches_.tessellation.mesh));
  refresh_view(*patch_renderer_, *patches_.tessellation.mesh);
}

void EditorApp::show_mesh(HalfedgeMesh mesh, const std::string& name) {
  std::string title = window_title(name.empty() ? std::string("untitled") : name);
  std::string path = name;
  file_up_axis_.reset();
  take_mesh(std::move(mesh), std::move(path));
  title_.swap(title);
  title_names_lesson_ = false;
}

void EditorApp::show_start_mesh() {
  try {
    show_mesh(build_halfedge_mesh(make_cube()), "");
  } catch (const std::bad_alloc&) {
    // show_mesh is whole or nothing: the document is as it was (as the window starts, the empty one).
    set_message_noexcept(doc_, Severity::Error,
                         [] { return std::string("memory ran out making the start-up cube; open a file to start"); });
  } catch (const std::exception& e) {
    report_exception(doc_, e);  // never expected: the cube is a valid mesh
  }
}

void EditorApp::show_curve(const BezierCurve& curve) { take_curve(make_curve_editor(curve)); }

void EditorApp::show_patches(const std::vector<BezierPatch>& patches) {
  PatchViewState view = tessellated_view(patches);
  file_up_axis_.reset();
  take_patches(std::move(view));
}

bool EditorApp::open(const std::filesystem::path& path) {
  bool not_a_manifold = false;
  try {
    if (path.extension() == ".lua") return open_lesson(path);
    exercises_.finish_replay(doc_);
    LoadedFile file = load_file(path);
    std::optional<HalfedgeMesh> mesh;
    std::optional<CurveEditorState> curve;
    std::optional<PatchViewState> patches;
    switch (file.kind) {
      case FileKind::Curve: curve = make_curve_editor(std::move(file.curve)); break;
      case FileKind::Patches: patches = tessellated_view(file.patches); break;
      case FileKind::Mesh:
        not_a_manifold = true;
        mesh = build_from_file(file.mesh, path).mesh;
        not_a_manifold = false;
    }
    std::string title = window_title(path.filename().string());
    std::string name = path.string();
    std::deque<std::string> recent = with_recent(recent_, path.string());
    std::string text = "opened " + path.string();
    if (file.joined_vertices > 0) {
      text += " (" + std::to_string(file.joined_vertices) +
              " vertices the file repeats at one position, for its "
              "normals or texture coordinates, joined)";
    }
    // Nothing from here on can fail: the window switches to the file whole.
    if (file.kind != FileKind::Curve) {  // a curve is drawn in its plane: the mesh view keeps its axis
      file_up_axis_ = file.up_axis;
      up_axis_choice_ = UpAxisChoice::FromFile;
    }
    if (mesh) take_mesh(std::move(*mesh), std::move(name));
    if (curve) take_curve(std::move(*curve));
    if (patches) take_patches(std::move(*patches));
    title_.swap(title);
    title_names_lesson_ = false;
    recent_.swap(recent);
    repairable_path_.clear();
    repairs_ = RepairMarks();  // the Repairs tab belongs to the repaired copy this file replaces
    set_message(doc_, Severity::Info, std::move(text));
    return true;
  } catch (const std::exception& e) {
    // Nothing was switched yet: the window shows what it showed. The report needs no memory, so nothing escapes.
    report_exception(doc_, e);
    offer_repair(path, not_a_manifold && dynamic_cast<const MeshError*>(&e) != nullptr);
    return false;
  }
}

void EditorApp::offer_repair(const std::filesystem::path& path, bool repairable) noexcept {
  try {
    repairable_path_ = repairable ? path.string() : std::string();
    if (repairable) doc_.message.text += " (File > Open a repaired copy)";
  } catch (const std::bad_alloc&) {
    repairable_path_.clear();  // the refusal's message stays as report_exception left it
  }
}

bool EditorApp::open_repaired() {
  try {
    if (repairable_path_.empty()) throw std::runtime_error("no file to repair: open one that is not a manifold first");
    const std::filesystem::path path = repairable_path_;
    exercises_.finish_replay(doc_);
    LoadedFile file = load_file(path);
    if (file.kind != FileKind::Mesh) throw std::runtime_error(path.string() + " is not a mesh file");
    const RepairResult repaired = repair_polygons(file.mesh);
    HalfedgeMesh mesh = build_from_file(repaired.polygons, path).mesh;
    RepairMarks marks = marks_of_repair(repaired.report);
    std::string title = window_title(path.filename().string() + " (repaired)");
    std::string name = path.string() + " (repaired)";
    std::string text = "opened a repaired copy of " + path.string() + ": " + repaired.report.summary() +
                       " (the Repairs tab lists each change; click one to select it)";
    // Nothing from here on can fail.
    file_up_axis_ = file.up_axis;
    up_axis_choice_ = UpAxisChoice::FromFile;
    take_mesh(std::move(mesh), std::move(name));
    title_.swap(title);
    title_names_lesson_ = false;
    marks.generation = doc_.generation;
    marks.version = doc_.mesh.version();
    repairs_ = std::move(marks);
    repairs_tab_open_ = true;
    repair_row_clicked_ = SIZE_MAX;
    select_tab_ = RightTab::Repairs;
    settings_.layout.right_open = true;
    repairable_path_.clear();
    set_message(doc_, Severity::Info, std::move(text));
  } catch (const std::exception& e) {
    report_exception(doc_, e);
    return false;
  }
  return true;
}

void EditorApp::open_dropped(const std::vector<std::string>& paths) {
  // Called between frames, outside the frame guard: each file under its own guard, so what escapes opening one (a
  // path that cannot be made for lack of memory) is an Error in the status line and the next file still opens.
  for (const std::string& path : paths) run_guarded(doc_, [&] { open(path); });
}

bool EditorApp::save(const std::filesystem::path& path) {
  try {
    std::deque<std::string> recent = with_recent(recent_, path.string());
    std::string text = "saved " + path.string();
    save_mesh(path, to_polygon_mesh(doc_.mesh));
    if (const std::string handed = host_hand_over(path); !handed.empty()) text = "saved and " + handed;
    // Nothing from here on can fail: a file written is a file reported saved.
    recent_.swap(recent);
    set_message(doc_, Severity::Info, std::move(text));
    return true;
  } catch (const std::exception& e) {
    report_exception(doc_, e);
    return false;
  }
}

}  // namespace meshedit
