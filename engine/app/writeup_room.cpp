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
#include "core/translation.h"
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
  if (edges.empty()) return "";
  std::string words;
  for (size_t i = 0; i + 1 < edges.size(); ++i) words += (i == 0 ? "e" : ", e") + std::to_string(edges[i]);
  const std::string last = "e" + std::to_string(edges.back());
  return edges.size() == 1 ? last : tr_format("{edges} and {edge}", {{"edges", words}, {"edge", last}});
}

// "3 flips (e4, e9 and e12)", "no flips".
std::string edits_words(const std::vector<uint32_t>& edges, EdgeOperation operation) {
  const bool flips = operation == EdgeOperation::Flip;
  if (edges.empty()) return flips ? tr("no flips") : tr("no splits");
  const MessageParts parts = {{"count", std::to_string(edges.size())}, {"edges", edge_list(edges)}};
  if (edges.size() == 1) return tr_format(flips ? "{count} flip ({edges})" : "{count} split ({edges})", parts);
  return tr_format(flips ? "{count} flips ({edges})" : "{count} splits ({edges})", parts);
}

}  // namespace

std::filesystem::path WriteupRoom::output_folder() const { return exercises_.session().folder() / "writeup"; }

Check WriteupRoom::start() {
  try {
    const std::string why = start_run(exercises_.session().folder());
    if (!why.empty()) {
      const std::string words = tr_format("File > Write-up could not start: {why}", {{"why", why}});
      document_.message(Severity::Error, words);
      return Check::no(words);
    }
    const std::string unsaved = exercises_.unsaved_student_files();
    document_.message(unsaved.empty() ? Severity::Info : Severity::Warning,
                      unsaved.empty()
                          ? std::string(tr("Making your write-up from your files..."))
                          : tr_format("Making your write-up from your saved files; not saved, so not used: {files}",
                                      {{"files", unsaved}}));
    return Check::yes();
  } catch (const std::exception& e) {
    document_.message(Severity::Error, tr_format("File > Write-up: {problem}", {{"problem", e.what()}}));
    return Check::no(e.what());
  }
}

void WriteupRoom::stop() {
  if (!running()) return;
  stop_run();
  document_.message(Severity::Warning, tr("The write-up was stopped before it was written"));
}

void WriteupRoom::poll() {
  try {
    if (const std::optional<RunEnd> end = poll_run()) announce(*end);
  } catch (const std::exception& e) {
    document_.message(Severity::Error, tr_format("File > Write-up: {problem}", {{"problem", e.what()}}));
  }
}

void WriteupRoom::announce(const RunEnd& end) {
  if (!end.made) {
    document_.message(Severity::Error, tr_format("The write-up was not made: {problem}", {{"problem", end.problem}}));
  } else if (end.failed.empty()) {
    document_.message(Severity::Info,
                      tr_format("Write-up made, every figure by your code: {where}", {{"where", end.where}}));
  } else {
    std::string numbers;
    for (const std::string& number : end.failed) numbers += (numbers.empty() ? "" : ", ") + number;
    const MessageParts parts = {
        {"count", std::to_string(end.failed.size())}, {"figures", numbers}, {"where", end.where}};
    document_.message(Severity::Warning,
                      end.failed.size() == 1
                          ? tr_format("Write-up made; {count} figure has a problem ({figures}), the page says why: "
                                      "{where}",
                                      parts)
                          : tr_format("Write-up made; {count} figures have problems ({figures}), the page says why: "
                                      "{where}",
                                      parts));
  }
}

Check WriteupRoom::save_view() {
  try {
    const std::filesystem::path folder = exercises_.session().folder();
    WriteupSettings settings = read_writeup_settings(folder);
    const std::string unreadable =
        settings.problems.empty()
            ? ""
            : tr_format("; replaced what could not be read ({problem})", {{"problem", settings.problems.front()}});
    const OrbitCamera& camera = view_.camera();
    settings.camera.yaw = one_decimal(std::remainder(camera.yaw_degrees(), 360.0));
    settings.camera.pitch = one_decimal(camera.pitch_degrees());
    settings.camera.zoom = one_decimal(std::clamp(camera.zoom_steps(), -20.0, 20.0));
    const MeshDocument& doc = document_.doc();
    const bool with_mesh = view_.mode() == ViewMode::Mesh && !doc.path.empty();  // else as they were
    std::string mesh_name;
    if (with_mesh) {
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
      mesh_name = std::filesystem::path(doc.path).filename().string();
    }
    const std::filesystem::path file = folder / kWriteupSettingsFile;
    write_file(file, format_writeup_settings(settings, folder));
    const MessageParts parts = {{"mesh", mesh_name},
                                {"flips", edits_words(settings.flip_edges, EdgeOperation::Flip)},
                                {"splits", edits_words(settings.split_edges, EdgeOperation::Split)},
                                {"unreadable", unreadable},
                                {"file", file.string()}};
    document_.message(Severity::Info,
                      !with_mesh
                          ? tr_format("Saved for the write-up: the camera (the mesh and edges stay as they were: open "
                                      "a mesh file to choose parts 4 and 5's){unreadable} ({file})",
                                      parts)
                          : tr_format("Saved for the write-up: the camera, {mesh}, {flips} and {splits}{unreadable} "
                                      "({file})",
                                      parts));
    return Check::yes();
  } catch (const std::exception& e) {  // the mesh file gone or not a manifold, writeup.json not writable, memory
    const std::string why = tr_format("The view was not saved for the write-up: {why}", {{"why", e.what()}});
    document_.message(Severity::Error, why);
    return Check::no(why);
  }
}

}  // namespace meshedit
