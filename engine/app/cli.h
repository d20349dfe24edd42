// The command line of `meshedit`: parses arguments and runs one front door (info, convert, subdivide,
// demo...). Returns the process exit status; never calls exit(), so tests can run it in-process.
#pragma once

namespace meshedit {

int run_cli(int argc, char** argv);

}  // namespace meshedit
