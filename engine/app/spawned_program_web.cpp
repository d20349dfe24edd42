// SpawnedProgram in a page: a page starts no programs, so there is never a child (see spawned_program.h).
#include "app/spawned_program.h"

namespace meshedit {

bool SpawnedProgram::available() { return false; }

std::string SpawnedProgram::start(const std::vector<std::string>&, Output) {
  printed_.clear();
  return "a web page cannot start programs";
}

bool SpawnedProgram::poll() { return true; }

void SpawnedProgram::stop() {}

void SpawnedProgram::read_printed() {}

void SpawnedProgram::close_pipe() {}

int SpawnedProgram::exit_code() const { return -1; }

std::string SpawnedProgram::end_words() const { return "never started (a web page cannot start programs)"; }

}  // namespace meshedit
