// Command-line front doors of meshedit (see cli.h): argument dispatch, usage, and the one place where
// errors become a one-line message on stderr and an exit status.
#include "app/cli.h"

#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "app/cli_commands.h"

namespace meshedit {
namespace {

constexpr const char* kUsage =
    "usage: meshedit <command> [arguments]\n"
    "\n"
    "commands:\n"
    "  demo [FILE]                          load a mesh (default: the teapot) and show what the core does\n"
    "  info FILE [--json]                   counts, topology and validation of a mesh, patch or curve file\n"
    "  convert IN OUT                       convert between mesh formats (.obj .dae .gltf .glb .bez -> .obj .gltf .glb)\n"
    "  subdivide IN -n LEVELS [--weights course|loop] -o OUT\n"
    "                                       Loop subdivision, LEVELS times\n"
    "\n"
    "options for files with Bézier patches (.bez): --resolution N (tessellation per patch, default 16)\n"
    "with no command, meshedit runs the demo (the window arrives in a later version)\n";

}  // namespace

int run_cli(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  const std::string command = args.empty() ? "demo" : args.front();
  if (!args.empty()) args.erase(args.begin());
  try {
    if (command == "-h" || command == "--help" || command == "help") {
      std::cout << kUsage;
      return 0;
    }
    if (command == "--version") {
      std::cout << "meshedit 0.1\n";
      return 0;
    }
    if (command == "demo") return run_demo(args, std::cout);
    if (command == "info") return run_info(args, std::cout);
    if (command == "convert") return run_convert(args, std::cout);
    if (command == "subdivide") return run_subdivide(args, std::cout);
    throw UsageError("unknown command '" + command + "'");
  } catch (const UsageError& e) {
    std::cerr << "meshedit: " << e.what() << " (see meshedit --help)\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "meshedit: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace meshedit
