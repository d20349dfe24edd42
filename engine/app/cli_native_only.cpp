// The commands the web page's program does not have (only in the web build; engine/app/CMakeLists.txt): `grade` runs
// every test in a process of its own (fork) and `render` draws on an EGL context without a window, and a page has
// neither. Each says so and names the native command, instead of failing somewhere inside.
#include "app/cli_commands.h"

namespace meshedit {

int run_render(const std::vector<std::string>&, std::ostream&) {
  throw UsageError("`render` needs EGL and runs in the desktop meshedit only");
}

int run_grade(const std::vector<std::string>&, std::ostream&) {
  throw UsageError("`grade` runs each test in a process of its own and runs in the desktop meshedit only");
}

int run_writeup(const std::vector<std::string>&, std::ostream&) {
  throw UsageError(
      "`writeup` draws on an EGL context and runs in the desktop meshedit only (the page has File > "
      "Write-up)");
}

}  // namespace meshedit
