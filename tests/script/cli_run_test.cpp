// `meshedit run` end to end: the built binary runs a script with `arg`, prints to stdout, and reports a Lua
// error with its file:line on stderr and exit status 1. Skips when the binary has not been built (this
// binary links the script module only; build the `meshedit` target first). Scripts run by a relative path, as
// Lua shortens long chunk names in messages ("...ts/fails.lua:3:").
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "support/test_support.h"

namespace meshedit {
namespace {

struct Outcome {
  int status = -1;
  std::string out, err;
};

// `dir` is the test's scratch_dir() (calling scratch_dir() again would empty it).
Outcome run_meshedit(const std::filesystem::path& dir, const std::string& arguments) {
  const auto out = dir / "run_stdout.txt", err = dir / "run_stderr.txt";
  const std::string command = "cd '" + dir.string() + "' && '" + std::string(MESHEDIT_BINARY) + "' " + arguments +
                              " >'" + out.string() + "' 2>'" + err.string() + "'";
  const int raw = std::system(command.c_str());
  Outcome o;
  o.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  o.out = testing::read_text(out);
  o.err = testing::read_text(err);
  return o;
}

std::filesystem::path write_script(const std::filesystem::path& dir, const std::string& name, const std::string& text) {
  const auto path = dir / name;
  std::ofstream(path) << text;
  return path;
}

TEST(CliRun, RunsAScriptWithArgumentsAndAMesh) {
  if (!std::filesystem::exists(MESHEDIT_BINARY)) GTEST_SKIP() << "meshedit not built";
  const auto dir = testing::scratch_dir();
  write_script(dir, "hello.lua",
               "print(#arg, arg[1], arg[2], select('#', ...))\n"
               "local m = meshedit.grid(2, 1)\n"
               "print(tostring(m), (m:validate()))\n");
  const Outcome o = run_meshedit(dir, "run hello.lua one --two");
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_EQ(o.out, "2\tone\t--two\t2\nmesh (6 vertices, 9 edges, 4 faces)\ttrue\n");
  EXPECT_EQ(o.err, "");
}

TEST(CliRun, ALuaErrorGoesToStderrWithFileAndLine) {
  if (!std::filesystem::exists(MESHEDIT_BINARY)) GTEST_SKIP() << "meshedit not built";
  const auto dir = testing::scratch_dir();
  write_script(dir, "fails.lua", "print('before')\nlocal m = meshedit.cube()\nlocal x = m:halfedge(0).nxt\n");
  const Outcome o = run_meshedit(dir, "run fails.lua");
  EXPECT_EQ(o.status, 1);
  EXPECT_EQ(o.out, "before\n");
  EXPECT_EQ(o.err, "meshedit: fails.lua:3: h0 has no field 'nxt'\n");
}

TEST(CliRun, MissingScriptIsAUsageError) {
  if (!std::filesystem::exists(MESHEDIT_BINARY)) GTEST_SKIP() << "meshedit not built";
  const Outcome o = run_meshedit(testing::scratch_dir(), "run");
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(o.err, "meshedit: run needs a script: meshedit run SCRIPT.lua [ARGS...] (see meshedit --help)\n");
}

}  // namespace
}  // namespace meshedit
