// File > Write-up and File > Use this view in the write-up, what the desktop and the page share: the run's start and
// end in the status line, and the view saved into writeup.json (see writeup_room.h).
#include "app/writeup_room.h"

#include <cmath>
#include <exception>
#include <vector>

#include "app/document_room.h"
#include "app/exercise_room.h"
#include "app/view_room.h"
#include "core/mesh_build.h"
#include "document/edge_edit_label.h"
#include "io/file_access.h"
#include "io/mesh_file.h"
#include "writeup/writeup_settings.h"

namespace meshedit {
namespace {

// 32.5 for 32.4871: writeup.json stays readable.
double one_decimal(double value) { return std::round(value * 10.0) / 10.0 + 0.0; }  // + 0.0: never -0

// "e4, e9 and e12".
std::string edge_list(const std::vector<uint32_t>& edges) {
  std::string words;
  for (size_t i = 0; i < edges.size(); ++i) {
    words += (i == 0 ? "" : i + 1 == edges.size() ? " and " : ", ") + std::string("e") + std::to_string(edges[i]);
  }
  return words;
}

// "3 flips (e4, e9 and e12)", "no flips".
std::string edits_words(const std::vector<uint32_t>& edges, const std::string& noun) {
  if (edges.empty()) return "no " + noun + "s";
  return std::to_string(edges.size()) + " " + noun + (edges.size() == 1 ? "" : "s") + " (" + edge_list(edges) + ")";
}

}  // namespace

std::filesystem::path WriteupRoom::output_folder() const { return exercises_.session().folder() / "writeup"; }

Check WriteupRoom::start() {
  try {
    const std::string why = start_run(exercises_.session().folder());
    if (!why.empty()) {
      const std::string words = "File > Write-up could not start: " + why;
      document_.message(Severity::Error, words);
      return Check::no(words);
    }
    const std::string unsaved = exercises_.unsaved_student_files();
    document_.message(unsaved.empty() ? Severity::Info : Severity::Warning,
                      unsaved.empty()
                          ? std::string("Making your write-up from your files...")
                          : "Making your write-up from your saved files; not saved, so not used: " + unsaved);
    return Check::yes();
  } catch (const std::exception& e) {
    document_.message(Severity::Error, std::string("File > Write-up: ") + e.what());
    return Check::no(e.what());
  }
}

void WriteupRoom::stop() {
  if (!running()) return;
  stop_run();
  document_.message(Severity::Warning, "The write-up was stopped before it was written");
}

void WriteupRoom::poll() {
  try {
    if (const std::optional<RunEnd> end = poll_run()) announce(*end);
  } catch (const std::exception& e) {
    document_.message(Severity::Error, std::string("File > Write-up: ") + e.what());
  }
}

void WriteupRoom::announce(const RunEnd& end) {
  if (!end.made) {
    document_.message(Severity::Error, "The write-up was not made: " + end.problem);
  } else if (end.failed.empty()) {
    document_.message(Severity::Info, "Write-up made, every figure by your code: " + end.where);
  } else {
    std::string numbers;
    for (const std::string& number : end.failed) numbers += (numbers.empty() ? "" : ", ") + number;
    document_.message(Severity::Warning,
                      "Write-up made; " + std::to_string(end.failed.size()) +
                          (end.failed.size() == 1 ? " figure has a problem" : " figures have problems") + " (" +
                          numbers + "), the page says why: " + end.where);
  }
}

Check WriteupRoom::save_view() {
  try {
    const std::filesystem::path folder = exercises_.session().folder();
    WriteupSettings settings = read_writeup_settings(folder);
    const std::string unreadable =
        settings.problems.empty() ? "" : "; replaced what could not be read (" + settings.problems.front() + ")";
    const OrbitCamera& camera = view_.camera();
    settings.camera.yaw = one_decimal(std::remainder(camera.yaw_degrees(), 360.0));
    settings.camera.pitch = one_decimal(camera.pitch_degrees());
    settings.camera.zoom = one_decimal(std::clamp(camera.zoom_steps(), -20.0, 20.0));
    std::string saved = "the camera";
    const MeshDocument& doc = document_.doc();
    if (view_.mode() == ViewMode::Mesh && !doc.path.empty()) {
      // The file's own mesh names the edges: an edge a split made, or anything after another kind of edit (which may
      // renumber), is not one of its edges.
      const HalfedgeMesh opened = build_halfedge_mesh(load_mesh(doc.path));
      settings.mesh = std::filesystem::absolute(doc.path);
      settings.flip_edges.clear();
      settings.split_edges.clear();
      for (const std::string& label : doc.history.undo_labels()) {
        const std::optional<EdgeEditLabel> edit = read_edge_edit_label(label);
        if (!edit || edit->operation == EdgeOperation::Collapse) break;
        auto& edges = edit->operation == EdgeOperation::Flip ? settings.flip_edges : settings.split_edges;
        if (edit->edge.index >= opened.edge_capacity() || edges.size() == kMaxWriteupEdges) continue;
        edges.push_back(edit->edge.index);
      }
      saved += ", " + std::filesystem::path(doc.path).filename().string() + ", " +
               edits_words(settings.flip_edges, "flip") + " and " + edits_words(settings.split_edges, "split");
    } else {
      saved += " (the mesh and edges stay as they were: open a mesh file to choose parts 4 and 5's)";
    }
    const std::filesystem::path file = folder / kWriteupSettingsFile;
    write_file(file, format_writeup_settings(settings, folder));
    document_.message(Severity::Info, "Saved for the write-up: " + saved + unreadable + " (" + file.string() + ")");
    return Check::yes();
  } catch (const std::exception& e) {  // the mesh file gone or not a manifold, writeup.json not writable, memory
    const std::string why = std::string("The view was not saved for the write-up: ") + e.what();
    document_.message(Severity::Error, why);
    return Check::no(why);
  }
}

}  // namespace meshedit
