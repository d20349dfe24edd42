// WriteupRoom: File > Write-up and File > Use this view in the write-up (writeup/writeup.h). The write-up is made by
// `meshedit writeup` in a child process (spawned_program.h), from the student's saved files in the Exercises tab's
// folder into FOLDER/writeup/ (index.html, writeup.md, figures/); the view is saved into FOLDER/writeup.json, which
// that run reads.
//
// Invariants:
// - The window never waits: poll() (once per frame) notices the end and says it in the status line: where the page
//   is and which figures have a problem (the page says why under each). Starting again while one runs starts afresh.
// - Saving the view writes the camera's angles and zoom, the mesh file shown and the flips and splits made on it
//   since it opened (edges of the file's own mesh, in order), and keeps every other key of writeup.json.
// - Nothing here throws: every outcome is a sentence in the status line and a Check.
#pragma once

#include <filesystem>
#include <string>
#include <utility>

#include "app/spawned_program.h"
#include "core/check.h"

namespace meshedit {

class DocumentRoom;
class ExerciseRoom;
class ViewRoom;

class WriteupRoom {
 public:
  WriteupRoom(DocumentRoom& document, ExerciseRoom& exercises, ViewRoom& view);

  // Whether this host can run `meshedit writeup` (a desktop can; a page cannot yet).
  static bool available() { return SpawnedProgram::available(); }
  void set_program(std::filesystem::path program) { program_ = std::move(program); }
  std::filesystem::path output_folder() const;  // FOLDER/writeup

  Check start();
  void stop();
  bool running() const { return process_.running(); }
  void poll();
  const std::string& printed() const { return process_.printed(); }  // the last run's lines ("4.1 ok", ...)

  Check save_view();

 private:
  DocumentRoom& document_;
  ExerciseRoom& exercises_;
  ViewRoom& view_;
  std::filesystem::path program_;
  SpawnedProgram process_;
  bool announced_ = true;
};

}  // namespace meshedit
