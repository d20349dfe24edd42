// A bug report: what a student chose to send to course staff (Help > Save a bug report), as one plain-text file that
// any editor shows and the window, the page and `meshedit run` read: a Lua chunk returning one table.
//
//   -- A MeshEdit bug report ...
//   return {
//     format = "meshedit bug report", version = 1, readable_by = 1, app = "meshedit 0.1", language = "zh",
//     lesson = "4_edge_flip.lua", step = 3,      -- the lesson and its step (1-based), when one runs
//     mesh_name = "cow.obj", selection = "e12",  -- the document's name and the selection (format_id)
//     camera = { up = "y", yaw = 30, pitch = 20, distance = 3.5, target = { 0, 0.5, 0 } },  -- the view's camera
//     mesh = [==[ meshedit mesh records 1 ... ]==],   -- the mesh shown, every record and id kept
//     operation = {                              -- the last run of the student's function on a mesh
//       exercise = "flip_edge", label = "mine: flip e12", element = "e12", verdict = "different: ...",
//       result_shown = true,                     -- the mesh above is the state the run left
//       input = [==[ meshedit mesh records 1 ... ]==],  -- the mesh the function was given
//     },
//     files = { ["flip.lua"] = [==[ ... ]==] },  -- the student's saved files the student chose to send
//   }
//
// Invariants:
// - parse_bug_report(format_bug_report(r)) is r. Texts are written in long brackets whose level none of them closes,
//   so code and meshes read back byte for byte.
// - Reading runs the chunk in a LuaRuntime with an empty table as its environment (no global, no library) and a
//   small budget, and reads the table raw (no metamethod runs): a report is data, never a program the reader trusts.
// - A report is refused with a ReportError naming the file (and the line for what Lua or the mesh records know a line
//   of): another kind of file, a version this reader cannot read (readable_by above kBugReportVersion, named with the
//   MeshEdit that saved it), a field of the wrong type (a camera's up not "y" or "z", a number that is not finite), a
//   file name with a folder in it or not a .lua. A newer report that says it stays readable by this version opens, its
//   unknown fields left out; an unknown field is ignored.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

#include "exercise/student_call.h"

namespace meshedit {

inline constexpr int kBugReportVersion = 1;
inline constexpr char kBugReportExtension[] = ".meshedit";

class ReportError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct BugReportOperation {
  std::string exercise;       // its function: "flip_edge", "upsample", a scripted exercise's
  std::string label;          // "mine: flip e12", as the window's status line said it
  std::string element;        // "e12"; "" for the whole mesh
  std::string verdict;        // what the window said of the run ("different: ...", the Lua error)
  bool result_shown = false;  // the report's mesh is the state the run left (nothing changed since)
  std::string input;          // the mesh the function was given, as mesh records (core/mesh_records.h)
};

// The mesh view's camera: its up axis ('y' or 'z'), its angles in degrees, its distance and its target.
struct BugReportCamera {
  char up = 'z';
  double yaw = 0.0, pitch = 0.0, distance = 1.0;
  glm::dvec3 target{0.0};
};

struct BugReport {
  int version = kBugReportVersion;
  int readable_by = kBugReportVersion;    // the oldest reader version that can open it
  std::string app;                        // the MeshEdit that saved it: "meshedit 0.1"
  std::string language;                   // the window's language when not English ("zh": its verdict's words)
  std::string lesson;                     // the lesson file's name in the lessons folder (or its path); "" none
  size_t step = 0;                        // its step, 1-based; 0 with no lesson
  std::string mesh_name;                  // the document's name ("cow.obj", "test 4.1: its input")
  std::string mesh;                       // the mesh shown, as mesh records; "" when no mesh was shown
  std::string selection;                  // format_id of the selection; "" none
  std::optional<BugReportCamera> camera;  // when the mesh view was shown
  std::optional<BugReportOperation> operation;
  std::vector<StudentSource> files;   // the student's files, by name ("flip.lua")
  std::vector<std::string> left_out;  // reading a newer report: the fields this version does not know
};

std::string format_bug_report(const BugReport& report);
// Reads a report's text; `name` is the file's name in the errors ("report.meshedit:3: ..."). Throws ReportError.
BugReport parse_bug_report(std::string_view text, const std::string& name);
// The report file at `path` read and parsed, named by its file name; throws ReportError (a file that cannot be read
// too).
BugReport read_bug_report(const std::filesystem::path& path);

// What `meshedit run report.meshedit` prints: the report's operation run again on its input with the report's code
// (loaded as the window loads it, under `limits`), its diagnosis in the window's words, and whether it is the one
// the student's window gave. Never throws for anything the student's code does; throws MeshError for an input that
// is not mesh records, ReportError for an operation this program has no exercise of.
struct BugReportReplay {
  bool replayed = false;      // the report has an operation and it ran
  bool equal = false;         // the student's function gave the reference's answer
  bool same_verdict = false;  // the replay's verdict is the one the report holds
  std::string text;           // what to print, lines ending in '\n'
};
BugReportReplay replay_bug_report(const BugReport& report, const std::string& name, const LuaLimits& limits);

}  // namespace meshedit
