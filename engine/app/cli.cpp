// Command-line front doors of meshedit (see cli.h): the table of commands that the dispatch and the usage text both
// read, and the one place where errors become a one-line message on stderr and an exit status.
#include "app/cli.h"

#include <algorithm>
#include <exception>
#include <filesystem>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

#include "app/cli_commands.h"
#include "core/app_version.h"
#include "script/exception_text.h"

namespace meshedit {
namespace {

int run_help(const std::vector<std::string>& args, std::ostream& out);
int run_version(const std::vector<std::string>&, std::ostream& out) {
  out << kAppVersion << "\n";
  return 0;
}

struct CliCommand {
  const char* name;  // the first argument; "" for the window (no command, or a file first)
  int (*run)(const std::vector<std::string>& args, std::ostream& out);
  const char* usage;  // the usage lines: the synopsis, then what it does (each line indented to the column of text)
};

// Every command, in the order --help lists them.
const CliCommand kCommands[] = {
    {"", run_window,
     "[FILE] [--actions SCRIPT] [--size WxH] [--suite SUITE.lua] [--check]\n"
     "                                     the window (a mesh, a .bez patch set, a .bzc curve, a lesson or a\n"
     "                                     .meshedit bug report); --suite: the\n"
     "                                     suite File > Check my work runs; --check: run it as the window opens"},
    {"demo", run_demo,
     "demo [FILE]                          load a mesh (default: the teapot) and show what the core does"},
    {"info", run_info,
     "info FILE [--json]                   counts, topology and validation of a mesh, patch or curve file,\n"
     "                                     and what a repair would change"},
    {"convert", run_convert,
     "convert IN OUT                       convert between mesh formats\n"
     "                                     (.obj .dae .gltf .glb .ply .stl .off .bez -> .obj .gltf .glb .ply .stl)"},
    {"subdivide", run_subdivide,
     "subdivide IN -n LEVELS [--scheme loop|catmull-clark|linear] [--weights course|loop] -o OUT\n"
     "                                     subdivision (default Loop; --weights is Loop's), LEVELS times"},
    {"triangulate", run_triangulate,
     "triangulate IN -o OUT                every face of more than three corners split into triangles"},
    {"repair", run_repair,
     "repair IN -o OUT                     split bow-tie vertices, detach extra faces at an edge, drop repeated\n"
     "                                     and degenerate faces and unused vertices, re-orient faces;\n"
     "                                     lists each change"},
    {"render", run_render,
     "render FILE -o OUT.png [--shading flat|phong] [--wireframe] [--subdivide N] [--size WxH] [--up y|z]\n"
     "                                     a picture without a display (EGL); also --vertices --halfedges"},
    {"run", run_run,
     "run SCRIPT.lua [ARGS...]             run a Lua script with no window (print goes to stdout)\n"
     "run REPORT.meshedit                  a bug report's last run made again with its code; its diagnosis"},
    {"grade", run_grade,
     "grade --suite SUITE.lua --submission DIR [--results FILE] [--junit FILE] [--tap] [--visible-only]\n"
     "      [--report FILE] [--progress] [--language en|zh]\n"
     "      --suite SUITE.lua --submissions DIR... [--out FOLDER] [--jobs N] [--compare PREVIOUS_MARKS]\n"
     "      [--language en|zh]\n"
     "                                     grade Lua submissions (a class: also FOLDER/class.html)"},
    {"class-report", run_class_report,
     "class-report RESULTS.json... [-o FOLDER] [--compare PREVIOUS_MARKS]\n"
     "                                     the class at a glance from results files: FOLDER/class.html (scores,\n"
     "                                     each test, the mistakes ranked) and FOLDER/class.csv"},
    {"writeup", run_writeup,
     "writeup --submission DIR -o OUT [--settings FILE]\n"
     "                                     the write-up made by DIR's own functions: OUT/index.html (pictures\n"
     "                                     inside), OUT/writeup.md and OUT/figures/; DIR/writeup.json chooses\n"
     "                                     the curve, the camera, the mesh and the edges they show"},
    {"lesson", run_lesson,
     "lesson FILE.lua --headless [--answers ANSWERS.lua] [--student DIR]\n"
     "                                     run a lesson's steps with scripted answers (no window); your_turn\n"
     "                                     runs DIR's files (default scripts/student)"},
    {"paths", run_paths,
     "paths                                the folders of the lessons, assets, shaders, student and exercise\n"
     "                                     files and fonts this meshedit reads (beside it, installed, or the source)"},
    {"help", run_help, "help, --help, -h                     this text"},
    {"-h", run_help, nullptr},
    {"--help", run_help, nullptr},
    {"--version", run_version, "--version                            the version"},
};

int run_help(const std::vector<std::string>&, std::ostream& out) {
  out << "usage: meshedit <command> [arguments]\n\ncommands:\n";
  for (const CliCommand& command : kCommands) {
    if (command.usage) out << "  " << command.usage << "\n";
  }
  out << "\noptions for files with Bézier patches (.bez): --resolution N (tessellation per patch, default 16)\n"
         "with no command, or a file as the first argument, meshedit opens the window\n";
  return 0;
}

// The command the arguments name: a known command word; the window for no arguments or anything that looks like a
// file or an option (meshedit teapot.dae, meshedit --actions t.txt); else nullptr (an unknown command).
const CliCommand* find_command(const std::vector<std::string>& args) {
  const CliCommand* window = &kCommands[0];
  if (args.empty()) return window;
  const std::string& first = args.front();
  const auto* named = std::find_if(std::begin(kCommands) + 1, std::end(kCommands),
                                   [&](const CliCommand& c) { return first == c.name; });
  if (named != std::end(kCommands)) return named;
  const bool looks_like_file = first.find_first_of("./\\") != std::string::npos || std::filesystem::exists(first);
  return looks_like_file || first.rfind('-', 0) == 0 ? window : nullptr;
}

}  // namespace

int run_cli(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  try {
    const CliCommand* command = find_command(args);
    if (!command) throw UsageError("unknown command '" + args.front() + "'");
    if (*command->name) args.erase(args.begin());
    // `meshedit grade --help`: that command's lines of the usage text.
    if (*command->name && command->usage && args.size() == 1 && (args[0] == "--help" || args[0] == "-h")) {
      std::cout << "usage: meshedit " << command->usage << "\n";
      return 0;
    }
    return command->run(args, std::cout);
  } catch (const UsageError& e) {
    std::cerr << "meshedit: " << e.what() << " (see meshedit --help)\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "meshedit: " << exception_text(e) << "\n";  // "memory ran out", not "std::bad_alloc"
    return 1;
  }
}

}  // namespace meshedit
