// Command-line front doors of meshedit (see cli.h).
#include "app/cli.h"

#include <iostream>

namespace meshedit {

int run_cli(int argc, char** argv) {
  (void)argc;
  (void)argv;
  std::cerr << "meshedit: not implemented yet\n";
  return 2;
}

}  // namespace meshedit
