// File > Write-up and File > Use this view in the write-up: the run and its end in the status line, and the view saved
// into writeup.json (see writeup_room.h).
#include "app/writeup_room.h"

#include <cmath>
#include <exception>
#include <sstream>
#include <vector>

#include "app/check_process.h"
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

constexpr const char* kOutputFolder = "writeup";

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

WriteupRoom::WriteupRoom(DocumentRoom& document, ExerciseRoom& exercises, ViewRoom& view)
    : document_(document), exercises_(exercises), view_(view), program_(check_program()) {}

std::filesystem::path WriteupRoom::output_folder() const { return exercises_.session().folder() / kOutputFolder; }

Check WriteupRoom::start() {
  try {
    if (!available()) {
      const std::string why =
          "File > Write-up runs `meshedit writeup`, which a page cannot run yet: on a computer, run meshedit writeup "
          "--submission FOLDER -o OUT";
      document_.message(Severity::Warning, why);
      return Check::no(why);
    }
    const std::filesystem::path folder = exercises_.session().folder();
    const std::vector<std::string> args = {program_.string(), "writeup",           "--submission",
                                           folder.string(),   "-o", output_folder().string()};
    if (const std::string why = process_.start(args, SpawnedProgram::Output::StdoutAndStderr); !why.empty()) {
      const std::string words = "File > Write-up could not start " + program_.string() + ": " + why;
      document_.message(Severity::Error, words);
      return Check::no(words);
    }
    announced_ = false;
    const std::string unsaved = exercises_.unsaved_student_files();
    document_.message(unsaved.empty() ? Severity::Info : Severity::Warning,
                      unsaved.empty() ? std::string("Making your write-up from your files...")
                                      : "Making your write-up from your saved files; not saved, so not used: " + unsaved);
    return Check::yes();
  } catch (const std::exception& e) {
    document_.message(Severity::Error, std::string("File > Write-up: ") + e.what());
    return Check::no(e.what());
  }
}

void WriteupRoom::stop() {
  if (!running()) return;
  process_.stop();
  announced_ = true;
  document_.message(Severity::Warning, "The write-up was stopped before it was written");
}

void WriteupRoom::poll() {
  if (!process_.poll() || announced_) return;
  announced_ = true;
  try {
    std::vector<std::string> failed;
    std::string last;
    std::istringstream lines(process_.printed());
    for (std::string line; std::getline(lines, line);) {
      const size_t at = line.find(" problem: ");  // "4.1 problem: ..."
      if (at <= 4) failed.push_back(line.substr(0, at));
      if (!line.empty()) last = line;
    }
    const std::string page = (output_folder() / "index.html").string();
    const int code = process_.exit_code();
    if (code == 0) {
      document_.message(Severity::Info, "Write-up made, every figure by your code: " + page);
    } else if (code == 1 && !failed.empty()) {
      std::string numbers;
      for (const std::string& number : failed) numbers += (numbers.empty() ? "" : ", ") + number;
      document_.message(Severity::Warning, "Write-up made; " + std::to_string(failed.size()) +
                                               (failed.size() == 1 ? " figure has a problem" : " figures have problems") +
                                               " (" + numbers + "), said under each: " + page);
    } else {
      document_.message(Severity::Error, "The write-up was not made: " + (last.empty() ? "meshedit writeup " + process_.end_words() : last));
    }
  } catch (const std::exception& e) {
    document_.message(Severity::Error, std::string("File > Write-up: ") + e.what());
  }
}

Check WriteupRoom::save_view() {
  try {
    const std::filesystem::path folder = exercises_.session().folder();
    WriteupSettings settings = read_writeup_settings(folder);
    const std::string unreadable = settings.problems.empty() ? "" : "; replaced what could not be read (" +
                                                                     settings.problems.front() + ")";
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
