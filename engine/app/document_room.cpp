// DocumentRoom: reading a file into what the window shows, whole or nothing, saving the mesh, and the recent-files
// list (see document_room.h). The Repairs tab is document_repairs.cpp's.
//
// Whole or nothing: everything that can fail (reading the file, building the mesh, tessellating patches, the window
// title, the new recent list, the message) is made by prepare_file while the window still shows what it showed; the
// take_* steps then switch to it with steps that cannot fail (replace_mesh moves the mesh in, its own message falling
// back to kMemoryRanOut; the strings and lists are swapped or moved in). Saving makes the new recent list and the
// message before it writes the file, and only swaps them in after.
#include "app/document_room.h"

#include <new>
#include <stdexcept>
#include <type_traits>

#include "app/mesh_loading.h"
#include "app/window_host.h"
#include "core/mesh_build.h"
#include "core/mesh_error.h"
#include "core/mesh_repair.h"
#include "core/translation.h"
#include "document/exception_report.h"
#include "io/mesh_file.h"

namespace meshedit {
namespace {

constexpr size_t kRecentFiles = 8;

// Moved in whole, without allocating (the view's take_curve and take_patches).
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

}  // namespace

std::string DocumentRoom::window_title(const std::string& name) { return std::string(kStartTitle) + " - " + name; }

void DocumentRoom::message(Severity severity, const std::string& text) { set_message(doc_, severity, text); }

PreparedFile DocumentRoom::prepare_file(const std::filesystem::path& path, bool& not_a_manifold) const {
  not_a_manifold = false;
  LoadedFile file = load_file(path);
  PreparedFile prepared;
  switch (file.kind) {
    case FileKind::Curve: prepared.curve = make_curve_editor(std::move(file.curve)); break;
    case FileKind::Patches: prepared.patches = tessellated_view(file.patches); break;
    case FileKind::Mesh:
      not_a_manifold = true;
      prepared.mesh = build_from_file(file.mesh, path).mesh;
      not_a_manifold = false;
  }
  if (file.kind != FileKind::Curve) prepared.up_axis = file.up_axis;  // a curve is drawn in its plane
  prepared.title = window_title(path.filename().string());
  prepared.name = path.string();
  prepared.recent = with_recent(recent_, path.string());
  prepared.message =
      file.joined_vertices > 0
          ? tr_format(
                "opened {file} ({count} vertices the file repeats at one position, for its normals or texture "
                "coordinates, joined)",
                {{"file", path.string()}, {"count", std::to_string(file.joined_vertices)}})
          : tr_format("opened {file}", {{"file", path.string()}});
  return prepared;
}

PreparedFile DocumentRoom::prepare_repaired() const {
  if (repairable_path_.empty()) {
    throw std::runtime_error(tr("no file to repair: open one that is not a manifold first"));
  }
  const std::filesystem::path path = repairable_path_;
  LoadedFile file = load_file(path);
  if (file.kind != FileKind::Mesh) {
    throw std::runtime_error(tr_format("{file} is not a mesh file", {{"file", path.string()}}));
  }
  const RepairResult repaired = repair_polygons(file.mesh);
  PreparedFile prepared;
  prepared.mesh = build_from_file(repaired.polygons, path).mesh;
  prepared.repairs = marks_of_repair(repaired.report);
  prepared.up_axis = file.up_axis;
  prepared.title = window_title(tr_format("{file} (repaired)", {{"file", path.filename().string()}}));
  prepared.name = path.string() + " (repaired)";
  prepared.recent = recent_;  // a repaired copy is no file of its own: the list stays
  prepared.message = tr_format(
      "opened a repaired copy of {file}: {summary} (the Repairs tab lists each change; click one to select it)",
      {{"file", path.string()}, {"summary", repaired.report.summary()}});
  return prepared;
}

void DocumentRoom::refuse(const std::filesystem::path& path, const std::exception& error, bool repairable) noexcept {
  report_exception(doc_, error);  // the report needs no memory, so nothing escapes
  try {
    repairable_path_ = repairable ? path.string() : std::string();
    if (repairable) {
      doc_.message.text = tr_format("{message} (File > Open a repaired copy)", {{"message", doc_.message.text}});
    }
  } catch (const std::bad_alloc&) {
    repairable_path_.clear();  // the refusal's message stays as report_exception left it
  }
}

void DocumentRoom::take_mesh(HalfedgeMesh&& mesh, std::string&& name) noexcept {
  replace_mesh(doc_, std::move(mesh), std::move(name));
  selection_ = {};
}

void DocumentRoom::take_opened(PreparedFile& file) noexcept {
  take_title(file.title, false);
  recent_.swap(file.recent);
  repairable_path_.clear();
  repairs_ = RepairMarks();  // the Repairs tab belongs to the repaired copy this file replaces
  if (file.repairs) {
    repairs_ = std::move(*file.repairs);
    repairs_.generation = doc_.generation;
    repairs_.version = doc_.mesh.version();
    repairs_tab_open_ = true;
    repair_row_clicked_ = SIZE_MAX;
  }
  set_message(doc_, Severity::Info, std::move(file.message));
}

void DocumentRoom::take_title(std::string& title, bool names_lesson) noexcept {
  title_.swap(title);
  title_names_lesson_ = names_lesson;
}

bool DocumentRoom::save(const std::filesystem::path& path) {
  try {
    std::deque<std::string> recent = with_recent(recent_, path.string());
    std::string text = tr_format("saved {file}", {{"file", path.string()}});
    save_mesh(path, to_polygon_mesh(doc_.mesh));
    if (const std::string handed = host_hand_over(path); !handed.empty()) {
      text = tr_format("saved and {handed}", {{"handed", handed}});
    }
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
