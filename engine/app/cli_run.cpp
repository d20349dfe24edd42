// `meshedit run SCRIPT.lua [ARGS...]`: runs a Lua script with no window. Everything after the script path
// is the script's (in `arg` and `...`, as lua.c does), even words starting with '-'. `print` writes to
// `out`; a Lua error (with its file:line) propagates as ScriptError, which run_cli prints on stderr with
// exit status 1.
#include <string>
#include <vector>

#include "app/cli_commands.h"
#include "script/lua_runtime.h"
#include "script/script_runtime.h"

namespace meshedit {

int run_run(const std::vector<std::string>& args, std::ostream& out) {
  if (args.empty()) throw UsageError("run needs a script: meshedit run SCRIPT.lua [ARGS...]");
  const std::vector<std::string> script_args(args.begin() + 1, args.end());
  ScriptRuntime lua;
  lua.set_print([&out](const std::string& line) { out << line << '\n'; });
  try {
    lua.run_file(args.front(), script_args);
  } catch (...) {
    out.flush();  // what the script printed before failing comes before the error
    throw;
  }
  out.flush();
  return 0;
}

}  // namespace meshedit
