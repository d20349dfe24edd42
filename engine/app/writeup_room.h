// WriteupRoom: File > Write-up and File > Use this view in the write-up (writeup/writeup.h). The write-up is made from
// the student's saved files in the Exercises tab's folder into FOLDER/writeup/ (index.html, writeup.md, figures/): on
// the desktop by `meshedit writeup` in a process of its own (writeup_room_native.cpp, spawned_program.h); in a page by
// the page's Web Worker for student code (writeup_room_web.cpp: the worker runs the student's functions and sends the
// write-up back as bytes, writeup/writeup_text.h), its pictures drawn on the page's thread between two frames by the
// same renderers (writeup_pictures.h) and index.html downloaded by the browser. The view is saved into
// FOLDER/writeup.json, which the write-up reads.
//
// Invariants:
// - The window never waits for student code: poll() (once per frame) notices the end and says it in the status line:
//   where the page is (or that it was downloaded) and which figures have a problem (the page says why under each).
//   Starting again while one runs starts afresh.
// - Saving the view writes the camera's angles and zoom, the mesh file shown and the flips and splits made on it
//   since it opened (edges of the file's own mesh, in order), and keeps every other key of writeup.json.
// - Nothing here throws: every outcome is a sentence in the status line and a Check.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/check.h"

namespace meshedit {

class DocumentRoom;
class ExerciseRoom;
class ViewRoom;

class WriteupRoom {
 public:
  WriteupRoom(DocumentRoom& document, ExerciseRoom& exercises, ViewRoom& view);
  ~WriteupRoom();
  WriteupRoom(const WriteupRoom&) = delete;
  WriteupRoom& operator=(const WriteupRoom&) = delete;

  void set_program(std::filesystem::path program) { program_ = std::move(program); }  // the desktop's meshedit
  std::filesystem::path output_folder() const;                                        // FOLDER/writeup

  Check start();
  void stop();
  bool running() const;
  void poll();
  // A page's write-up made by its worker: its pictures drawn, its files written and index.html handed to the browser.
  // Call between ImGui's rendering and the buffer swap (no ImGui frame open, the window's GL context current), as the
  // window's screenshot is written. Nothing to do on the desktop, whose process draws its own.
  void finish_made();

  Check save_view();

 private:
  // How a run ended: the figures that have a problem, or why no write-up was made.
  struct RunEnd {
    bool made = false;
    std::vector<std::string> failed;  // "4.1", "5.2"
    std::string problem;              // when not made
    std::string where;                // the page: its path, or "downloaded as index.html"
  };
  struct Host;                                                 // the desktop's process, or the page's worker job
  std::string start_run(const std::filesystem::path& folder);  // "" when started, else why not
  std::optional<RunEnd> poll_run();                            // nullopt while it runs
  void stop_run();
  void announce(const RunEnd& end);

  DocumentRoom& document_;
  ExerciseRoom& exercises_;
  ViewRoom& view_;
  std::filesystem::path program_;
  std::unique_ptr<Host> host_;
};

}  // namespace meshedit
