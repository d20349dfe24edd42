// CheckProcess in a page: a page cannot start a process, so the window offers no check there (see check_process.h).
#include "app/check_process.h"

namespace meshedit {

bool CheckProcess::available() { return false; }

std::filesystem::path check_program() { return {}; }

CheckProcess::~CheckProcess() = default;

double CheckProcess::seconds() const { return 0.0; }

bool CheckProcess::start(const std::filesystem::path&, const std::filesystem::path&, const std::filesystem::path&) {
  problem_ = "Check my work needs the desktop program in this version: a page cannot start the grader";
  return false;
}

void CheckProcess::poll() {}

void CheckProcess::stop() {}

}  // namespace meshedit
