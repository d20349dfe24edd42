// `meshedit writeup --submission DIR -o OUT [--settings FILE]`: the write-up of a student's folder, made by their own
// functions (writeup/writeup.h): OUT/index.html (one file, its pictures inside), OUT/writeup.md and OUT/figures/*.png.
// The pictures are drawn without a display (EGL), by the window's renderers (app/writeup_pictures.h). --settings reads
// the student's choices from FILE instead of DIR/writeup.json.
// Prints one line per figure ("4.1 ok" or "4.1 problem: ..."), then where the files are. The exit status:
// 0 every figure is the reference's, 1 some figure failed or could not be drawn (the files are still written), or the
// folder is missing or a file cannot be written; 2 bad arguments.
#include <filesystem>
#include <ostream>

#include "app/cli_commands.h"
#include "app/writeup_pictures.h"
#include "core/file_bytes.h"
#include "grade/submission.h"
#include "render/offscreen_context.h"
#include "writeup/writeup.h"
#include "writeup/writeup_page.h"
#include "writeup/writeup_settings.h"

namespace meshedit {

int run_writeup(const std::vector<std::string>& arguments, std::ostream& out) {
  std::vector<std::string> args = arguments;
  const auto folder = take_option(args, "--submission");
  const auto output = take_option(args, "--output", "-o");
  const auto settings_file = take_option(args, "--settings");
  reject_unknown_options(args);
  if (!args.empty()) throw UsageError("writeup takes no file arguments (the folder is --submission DIR)");
  if (!folder) throw UsageError("writeup needs --submission DIR (the student's folder of .lua files)");
  if (!output) throw UsageError("writeup needs -o OUT (the folder for index.html and writeup.md)");

  const Submission submission = Submission::read(*folder);
  WriteupSettings settings;
  if (settings_file) {
    const FileBytes text = read_file_bytes(*settings_file, size_t(1) << 20);
    if (!text.ok()) throw GradeError(*settings_file + ": " + text.error);
    settings = parse_writeup_settings(text.bytes, std::filesystem::path(*settings_file).filename().string(), *folder);
  } else {
    settings = read_writeup_settings(*folder);
  }
  Writeup writeup = make_writeup(submission, settings);

  OffscreenContext context;
  const std::string not_drawn = draw_writeup_pictures(writeup);
  const std::string not_written = write_writeup_files(writeup_files(writeup), *output);
  if (!not_written.empty()) throw GradeError("writeup: " + not_written);

  for (const std::string& note : writeup.notes) out << "note: " << note << "\n";
  for (const WriteupPart& part : writeup.parts) {
    for (const WriteupFigure& figure : part.figures) {
      out << figure.number << " " << (figure.problem.empty() ? "ok" : "problem: " + figure.problem) << "\n";
    }
  }
  if (!not_drawn.empty()) out << "not drawn: " << not_drawn << "\n";
  const size_t failed = writeup.failed_figures();
  out << "wrote " << (std::filesystem::path(*output) / "index.html").string() << " and writeup.md: " << failed
      << (failed == 1 ? " figure has a problem" : " figures have problems") << "\n";
  return failed == 0 && not_drawn.empty() ? 0 : 1;
}

}  // namespace meshedit
