// The "Your code" tab in the real window under Xvfb, on lesson 4 with a copy of scripts/student/flip.lua: text typed
// into the editor runs only once saved (the save is written to the file, which the Exercises tab loads as it loads any
// save), a correct flip saved there is what Run mine runs and replays, and an error, at load or at run time, marks the
// line it names; a runaway loop runs beside the window until Stop ends it. At 1280x800 and 1024x640.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "app/window_test_support.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

using testing::run_window;
using testing::WindowRun;
using testing::XServer;
namespace fs = std::filesystem;

// A flip that matches the reference, on one line (the scripted actions give a line's words).
constexpr char kFlipLine[] =
    "local h0=e.halfedge local h1=h0.twin if h0.face:is_boundary() or h1.face:is_boundary() then return nil end "
    "local h2=h0.next local h3=h2.next local h4=h1.next local h5=h4.next local a=h0.vertex local b=h1.vertex "
    "local c=h3.vertex local d=h5.vertex local f0=h0.face local f1=h1.face h0.next=h3 h3.next=h4 h4.next=h0 "
    "h1.next=h5 h5.next=h2 h2.next=h1 h0.vertex=d h1.vertex=c h4.face=f0 h2.face=f1 f0.halfedge=h0 "
    "f1.halfedge=h1 if a.halfedge==h0 then a.halfedge=h4 end if b.halfedge==h1 then b.halfedge=h2 end return e";

std::string read_text(const fs::path& file) {
  std::ifstream in(file);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// A copy of the template in dir/student, and the number of its `return nil` line (the body of flip_edge).
size_t copy_template(const fs::path& dir) {
  fs::create_directories(dir / "student");
  fs::copy_file(testing::source_dir() / "scripts" / "student" / "flip.lua", dir / "student" / "flip.lua",
                fs::copy_options::overwrite_existing);
  std::istringstream lines(read_text(dir / "student" / "flip.lua"));
  size_t number = 0;
  for (std::string line; std::getline(lines, line);) {
    number += 1;
    if (line == "  return nil") return number;
  }
  return 0;
}

std::string start(const fs::path& dir, size_t line) {
  return "frames 3\nkey X\nexercise flip " + (dir / "student").string() +
         "\neditor-open\nframes 2\nexpect-editor-line " + std::to_string(line) +
         " return nil\nexpect-editor-error none\n";
}

// Each test: an X server (skipped without one), a scratch folder holding a copy of the template, and the number of its
// `return nil` line (n, as text for the scripts).
class WindowStudentEditor : public ::testing::Test {
 protected:
  void SetUp() override {
    if (x.display().empty()) GTEST_SKIP() << "no X server and no Xvfb";
    line = copy_template(dir);
    ASSERT_GT(line, 0u) << "scripts/student/flip.lua has no '  return nil' line";
    n = std::to_string(line);
  }
  // Plays `actions` in the window on lesson 4, and expects it to end with every expectation held.
  WindowRun play(const std::string& actions, const std::string& size = "1280x800") {
    WindowRun run = run_window(x.display(), testing::source_dir() / "lessons" / "4_edge_flip.lua", actions, dir, size);
    EXPECT_EQ(run.status, 0) << run.output;
    EXPECT_NE(run.output.find("actions: all expectations held"), std::string::npos) << run.output;
    return run;
  }
  XServer x;
  const fs::path dir = testing::scratch_dir();
  size_t line = 0;
  std::string n;
};

TEST_F(WindowStudentEditor, ASavedEditIsWhatRunMineRunsAndReplays) {
  const std::string actions = start(dir, line) +
                              // Typed but not saved: Run mine still runs the template.
                              "editor-set-line " + n + " " + kFlipLine +
                              "\nselect e0\nrun-mine\nexpect-exercise-run changed nothing\n"
                              // Saved: the same run is the reference's flip, and its writes replay.
                              "editor-save\nexpect-message saved flip.lua\nexpect-editor-error none\n"
                              "select e0\nrun-mine\nexpect-exercise-run same as the reference\n"
                              "replay-start\nexpect-field h0 next h1\nreplay-step 1\nexpect-field h0 next h2\n"
                              "replay-finish\nexpect-field h0 vertex v3\nexpect-field h3 vertex v2\nexpect-valid\n"
                              "frames 2\nscreenshot " +
                              (dir / "saved.png").string() + "\nframes 2\nquit\n";
  play(actions);
  EXPECT_NE(read_text(dir / "student" / "flip.lua").find(kFlipLine), std::string::npos) << "the save was not written";
}

TEST_F(WindowStudentEditor, UnsavedTextStaysWithItsFileWhileTheStudentSwitchesExercises) {
  fs::copy_file(testing::source_dir() / "scripts" / "student" / "split.lua", dir / "student" / "split.lua");
  const std::string folder = (dir / "student").string();
  const std::string actions =
      start(dir, line) + "editor-set-line " + n + " return e -- typed in flip.lua\n" + "exercise split " + folder +
      "\nframes 2\nexpect-editor-line 1 edge split\n" + "editor-set-line 1 -- typed in split.lua\n" + "exercise flip " +
      folder + "\nframes 2\nexpect-editor-line " + n + " return e -- typed in flip.lua\n" + "exercise split " + folder +
      "\nframes 2\nexpect-editor-line 1 -- typed in split.lua\n" + "quit\n";
  play(actions);
  EXPECT_EQ(read_text(dir / "student" / "flip.lua"),
            read_text(testing::source_dir() / "scripts" / "student" / "flip.lua"))
      << "unsaved text was written";
}

// Ctrl+Q with unsaved text in Your code asks first: Keep editing keeps the window and the text; Save and quit writes
// the file and closes. The actions after a close never run, so one that cannot hold shows the window stayed open.
TEST_F(WindowStudentEditor, QuittingWithUnsavedCodeAsksAndSaveAndQuitWritesIt) {
  const std::string actions =
      start(dir, line) + "editor-set-line " + n + " return e -- typed\n" +
      "key ctrl+Q\nframes 2\nexpect-unsaved-code flip.lua\nframes 1\nscreenshot " + (dir / "asking.png").string() +
      "\nframes 2\nunsaved-code keep\nframes 2\n" + "expect-editor-line " + n + " return e -- typed\n" +
      "key ctrl+Q\nframes 2\nunsaved-code save\nframes 3\n" + "expect-message the window was still open\n";
  play(actions);
  EXPECT_NE(read_text(dir / "student" / "flip.lua").find("return e -- typed"), std::string::npos)
      << "Save and quit did not write the file";
  EXPECT_TRUE(fs::exists(dir / "asking.png"));
}

TEST_F(WindowStudentEditor, QuitWithoutSavingClosesAndLeavesTheFile) {
  const std::string before = read_text(dir / "student" / "flip.lua");
  const std::string actions = start(dir, line) + "editor-set-line " + n +
                              " return e -- typed\nkey ctrl+Q\nframes 2\nunsaved-code discard\nframes 3\n" +
                              "expect-message the window was still open\n";
  play(actions);
  EXPECT_EQ(read_text(dir / "student" / "flip.lua"), before);
  // With nothing unsaved, Ctrl+Q closes at once.
  play(start(dir, line) + "key ctrl+Q\nframes 3\nexpect-message the window was still open\n");
}

TEST_F(WindowStudentEditor, AnErrorMarksTheLineItNames) {
  const std::string actions =
      start(dir, line) +
      // A syntax error: the file does not load, and its line is marked.
      "editor-set-line " + n + " return nil nil )\neditor-save\nexpect-message does not load\n" +
      "expect-editor-error " + n + " flip.lua:" + n + ":\nselect e0\nrun-mine-fails flip.lua:" + n +
      ":\nframes 2\nscreenshot " + (dir / "syntax.png").string() +
      "\nframes 2\n"
      // An error at run time: the file loads, Run mine fails on that line, and the line is marked.
      "editor-set-line " +
      n + " error(\"not yet\")\neditor-save\nexpect-editor-error none\nselect e0\nrun-mine-fails not yet\n" +
      "expect-editor-error " + n + " not yet\n" +
      // Fixed: no line is marked.
      "editor-set-line " + n + " " + kFlipLine + "\neditor-save\nselect e0\nrun-mine\nexpect-editor-error none\nquit\n";
  play(actions, "1024x640");
}

// A flip_edge that never returns: Run mine runs it on its own thread, so the window goes on drawing frames and
// answering while it runs (the status line still says it is running after them, long before any limit), the Stop
// button ends it at the line it was on, and the console answers afterwards.
TEST_F(WindowStudentEditor, ARunawayLoopRunsBesideTheWindowAndStopEndsItAtItsLine) {
  const std::string actions = start(dir, line) + "editor-set-line " + n +
                              " while true do end\neditor-save\nselect e0\nstart-mine\nframes 10\n"
                              "expect-message mine: flip e0: your code is running (Stop ends it)\nscreenshot " +
                              (dir / "running.png").string() +
                              "\nframes 2\nstop-mine\nwait-message 300 stopped: you pressed Stop\n"
                              "expect-message mine (error): flip e0\nexpect-editor-error " +
                              n +
                              " stopped: you pressed Stop\nconsole print(1 + 1)\nframes 2\nexpect-console 2\nquit\n";
  play(actions);
  EXPECT_TRUE(fs::exists(dir / "running.png"));
}

}  // namespace
}  // namespace meshedit
