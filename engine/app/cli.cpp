// Command-line front doors of meshedit (see cli.h): argument dispatch, usage, and the one place where
// errors become a one-line message on stderr and an exit status.
#include "app/cli.h"

#include <exception>
#include <filesystem>
#include <iostream>
#include <set>
#include <string>
#include <vector>

#include "app/cli_commands.h"
#include "app/cli_grade.h"
#include "app/cli_lesson.h"
#include "script/exception_text.h"

namespace meshedit {
namespace {

constexpr const char* kUsage =
    "usage: meshedit <command> [arguments]\n"
    "\n"
    "commands:\n"
    "  [FILE] [--actions SCRIPT] [--size WxH]  the window (a mesh, a .bez patch set or a .bzc curve)\n"
    "  demo [FILE]                          load a mesh (default: the teapot) and show what the core does\n"
    "  info FILE [--json]                   counts, topology and validation of a mesh, patch or curve file\n"
    "  convert IN OUT                       convert between mesh formats\n"
    "                                       (.obj .dae .gltf .glb .ply .stl .off .bez -> .obj .gltf .glb .ply .stl)\n"
    "  subdivide IN -n LEVELS [--scheme loop|catmull-clark|linear] [--weights course|loop] -o OUT\n"
    "                                       subdivision (default Loop; --weights is Loop's), LEVELS times\n"
    "  triangulate IN -o OUT                every face of more than three corners split into triangles\n"
    "  repair IN -o OUT                     split bow-tie vertices, detach extra faces at an edge, drop repeated\n"
    "                                       and degenerate faces and unused vertices, re-orient faces;\n"
    "                                       lists each change\n"
    "  render FILE -o OUT.png [--shading flat|phong] [--wireframe] [--subdivide N] [--size WxH] [--up y|z]\n"
    "                                       a picture without a display (EGL); also --vertices --halfedges\n"
    "  run SCRIPT.lua [ARGS...]             run a Lua script with no window (print goes to stdout)\n"
    "  grade --suite SUITE.lua --submission DIR [--results FILE] [--junit FILE] [--tap]\n"
    "        --suite SUITE.lua --submissions DIR... [--out FOLDER] [--jobs N]   grade Lua submissions\n"
    "  lesson FILE.lua --headless [--answers ANSWERS.lua] [--student DIR]\n"
    "                                       run a lesson's steps with scripted answers (no window); your_turn\n"
    "                                       runs DIR's files (default scripts/student)\n"
    "\n"
    "options for files with Bézier patches (.bez): --resolution N (tessellation per patch, default 16)\n"
    "with no command, or a file as the first argument, meshedit opens the window\n";

// The command the arguments name: a known command word, "window" for no arguments or anything that looks
// like a file or an option (meshedit teapot.dae, meshedit --actions t.txt), else the word itself, which
// run_cli reports as unknown.
std::string command_name(const std::vector<std::string>& args) {
  static const std::set<std::string> commands = {"demo",  "info", "convert", "subdivide", "render", "run",
                                                 "lesson", "grade", "help", "-h",       "--help", "--version",
                                                 "triangulate", "repair"};
  if (args.empty()) return "window";
  const std::string& first = args.front();
  if (commands.count(first)) return first;
  const bool looks_like_file = first.find_first_of("./\\") != std::string::npos || std::filesystem::exists(first);
  return looks_like_file || first.rfind("-", 0) == 0 ? "window" : first;
}

}  // namespace

int run_cli(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  const std::string command = command_name(args);
  if (command != "window") args.erase(args.begin());
  try {
    if (command == "window") return run_window(args, std::cout);
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
    if (command == "triangulate") return run_triangulate(args, std::cout);
    if (command == "repair") return run_repair(args, std::cout);
    if (command == "render") return run_render(args, std::cout);
    if (command == "run") return run_run(args, std::cout);
    if (command == "grade") return run_grade(args, std::cout);
    if (command == "lesson") return run_lesson(args, std::cout);
    throw UsageError("unknown command '" + command + "'");
  } catch (const UsageError& e) {
    std::cerr << "meshedit: " << e.what() << " (see meshedit --help)\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "meshedit: " << exception_text(e) << "\n";  // "memory ran out", not "std::bad_alloc"
    return 1;
  }
}

}  // namespace meshedit
