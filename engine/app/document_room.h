// DocumentRoom: the open document and its files. Owns what the window edits (the mesh document with its history and
// its status line, the selection, the mesh edits' settings), the window's title, the recent files, the mesh file the
// last open refused as not a manifold and the marks of its repaired copy (the Repairs tab), and the Open or save
// dialog's paths. Every room reports into the document's status line (message()).
//
// Invariants:
// - Opening is whole or nothing: prepare_file and prepare_repaired read and build everything a file needs and throw
// with
//   nothing changed; take_mesh and take_opened switch to it with steps that cannot fail (the window's switch, which
//   also turns the view: EditorApp::take_file, editor_files.cpp).
// - A file saved is reported saved and put first in the recent list; one not saved changes neither (save makes both
//   before it writes). save() and refuse() never throw: their report falls back to kMemoryRanOut, which needs no
//   memory (document/exception_report.h).
// - The repaired spots select and are drawn only while they are the shown mesh's (RepairMarks::current).
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <exception>
#include <filesystem>
#include <optional>
#include <string>

#include "app/repair_marks.h"
#include "core/palette.h"
#include "document/curve_view_state.h"
#include "document/mesh_document.h"
#include "document/mesh_edits.h"
#include "document/patch_view_state.h"
#include "document/selection.h"
#include "io/file_up_axis.h"

namespace meshedit {

// A file read and built, ready to be shown: exactly one of mesh, curve and patches is set.
struct PreparedFile {
  std::optional<HalfedgeMesh> mesh;
  std::optional<CurveEditorState> curve;
  std::optional<PatchViewState> patches;  // tessellated already
  std::optional<FileUpAxis> up_axis;      // nullopt for a curve: drawn in its plane, the mesh view keeps its axis
  std::string title;                      // "MeshEdit - bunny.obj"
  std::string name;                       // the document's name: the file's path
  std::string message;                    // "opened bunny.obj"
  std::deque<std::string> recent;         // the recent list with this file first
  std::optional<RepairMarks> repairs;     // a repaired copy's changes and their spots
};

class DocumentRoom {
 public:
  static constexpr char kStartTitle[] = "MeshEdit";  // the title before a file or a lesson names the window
  // "MeshEdit - <name>": the title naming a file or a lesson.
  static std::string window_title(const std::string& name);

  MeshDocument& doc() { return doc_; }
  const MeshDocument& doc() const { return doc_; }
  Selection& selection() { return selection_; }
  const Selection& selection() const { return selection_; }
  MeshEditState& mesh_edits() { return mesh_edits_; }  // Loop's weights, the Catmull-Clark and linear steppers
  void message(Severity severity, const std::string& text);

  // Reads `path` (a mesh, a curve or patches) into what the window will show, or throws with nothing changed;
  // `not_a_manifold` tells whether it was the builder that refused the mesh (a repaired copy can then be opened).
  PreparedFile prepare_file(const std::filesystem::path& path, bool& not_a_manifold) const;
  // The mesh file the last open refused as not a manifold, repaired (core/mesh_repair.h), or throws.
  PreparedFile prepare_repaired() const;
  bool can_open_repaired() const { return !repairable_path_.empty(); }
  // After prepare_file or prepare_repaired threw: reports why and remembers `path` for a repaired copy when
  // `repairable`, saying so in the message. Never throws.
  void refuse(const std::filesystem::path& path, const std::exception& error, bool repairable) noexcept;

  // The steps that switch to a prepared file, which cannot fail: the document takes the mesh (the selection cleared),
  // then the title, the recent list, the repair marks and the message.
  void take_mesh(HalfedgeMesh&& mesh, std::string&& name) noexcept;
  void take_opened(PreparedFile& file) noexcept;
  // The title naming a file (names_lesson false) or the running lesson (true: a reload renames it).
  void take_title(std::string& title, bool names_lesson) noexcept;
  const std::string& title() const { return title_; }
  bool title_names_lesson() const { return title_names_lesson_; }
  const std::deque<std::string>& recent_files() const { return recent_; }

  // Saves the current mesh (in any format save_mesh writes) and reports the outcome; a page's browser then downloads
  // the file (host_hand_over, window_host.h).
  bool save(const std::filesystem::path& path);

  // The Repairs tab (document_repairs.cpp): its marks, whether their spots are the shown mesh's (`mesh_shown`: the mesh
  // view is on screen), a row clicked (selects its first spot; refused with a Warning when there is no such row, it
  // has no spot or the spots are stale) and the tab drawn.
  const RepairMarks& repair_marks() const { return repairs_; }
  bool repair_spots_current(bool mesh_shown) const;
  bool click_repair_row(size_t row, bool mesh_shown);
  void draw_repairs_tab(bool mesh_shown, Theme theme);
  bool& repairs_tab_open() { return repairs_tab_open_; }

  // The Open or save dialog's path fields.
  std::string& open_path_input() { return open_path_input_; }
  std::string& save_path_input() { return save_path_input_; }

 private:
  MeshDocument doc_;
  Selection selection_;
  MeshEditState mesh_edits_;
  std::string title_ = kStartTitle;
  bool title_names_lesson_ = false;  // title_ is the running lesson's, not a file's: reloads rename it
  std::deque<std::string> recent_;
  std::string repairable_path_;  // the mesh file the last open refused as not a manifold
  RepairMarks repairs_;          // the last repaired copy's changes and their spots
  bool repairs_tab_open_ = false;
  size_t repair_row_clicked_ = SIZE_MAX;  // the row last clicked (shown selected while the spots are current)
  std::string open_path_input_;
  std::string save_path_input_;
};

}  // namespace meshedit
