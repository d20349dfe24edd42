// WriteupRoom's run on the desktop: `meshedit writeup` in a process of its own (see writeup_room.h), its lines
// ("4.1 ok", "4.1 problem: ...", then where it wrote) read for the status line.
#include <sstream>

#include "app/check_process.h"
#include "app/exercise_room.h"
#include "app/spawned_program.h"
#include "app/writeup_room.h"
#include "core/translation.h"

namespace meshedit {

struct WriteupRoom::Host {
  SpawnedProgram process;
  bool announced = true;
};

WriteupRoom::WriteupRoom(DocumentRoom& document, ExerciseRoom& exercises, ViewRoom& view)
    : document_(document),
      exercises_(exercises),
      view_(view),
      program_(check_program()),
      host_(std::make_unique<Host>()) {}

WriteupRoom::~WriteupRoom() = default;  // the process is killed and reaped with it

bool WriteupRoom::running() const { return host_->process.running(); }

std::string WriteupRoom::start_run(const std::filesystem::path& folder) {
  const std::vector<std::string> args = {program_.string(), "writeup", "--submission",
                                         folder.string(),   "-o",      output_folder().string()};
  const std::string why = host_->process.start(args, SpawnedProgram::Output::StdoutAndStderr);
  host_->announced = !why.empty();
  return why.empty() ? "" : program_.string() + ": " + why;
}

void WriteupRoom::stop_run() {
  host_->process.stop();
  host_->announced = true;
}

std::optional<WriteupRoom::RunEnd> WriteupRoom::poll_run() {
  if (!host_->process.poll() || host_->announced) return std::nullopt;
  host_->announced = true;
  RunEnd end;
  std::string last;
  std::istringstream lines(host_->process.printed());
  for (std::string line; std::getline(lines, line);) {
    const size_t at = line.find(" problem: ");  // "4.1 problem: ..."
    if (at <= 4) end.failed.push_back(line.substr(0, at));
    if (line.starts_with("not drawn: ")) end.failed.push_back(tr("a picture not drawn"));
    if (!line.empty()) last = line;
  }
  const int code = host_->process.exit_code();
  end.made = code == 0 || (code == 1 && last.starts_with("wrote "));
  end.problem = last.empty() ? "meshedit writeup " + host_->process.end_words() : last;
  end.where = (output_folder() / "index.html").string();
  return end;
}

void WriteupRoom::finish_made() {}

}  // namespace meshedit
