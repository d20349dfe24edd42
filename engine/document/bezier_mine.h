// "Mine" in the curve and patch views (parts 1 and 2 of the assignment): the curve view's de Casteljau levels
// computed by the student's evaluate_step (scripts/student/curve.lua), and the patch view's probe point by the
// student's evaluate (patch.lua), each checked against the reference with check_exercise (exercises.h). Plain
// data, no ImGui: curve_editor.cpp and patch_view.cpp draw what is here, the app owns one BezierMine.
//
// Invariants:
// - Level k of "mine" is the student's evaluate_step run on mine's level k - 1 (level 0 is the control points)
//   at the view's t, and is checked by check_exercise(CurveStep) on that same input. The levels stop at the first
//   one that fails (a Lua error, a limit, a return value that is not a list of points) or differs from the
//   reference: that level is kept, to be drawn in the palette's "wrong" colour, and nothing after it is computed. So
//   every level before `failed_level` is the reference's, up to the checker's tolerance.
// - Levels are computed only as far as the view shows them (E reveals one more, and that is when the student's
//   code runs for it), and kept while the control points, t and the loaded code stay the same (compared
//   exactly): an idle frame runs no Lua, a broken function is not run again every frame.
// - In the background (set_in_background: the window and the page), each level and each probe point is one call of
//   the student's code off the window's thread (student_call_work.h), on the file's text loaded afresh: the frame
//   draws what is there with "your evaluate_step is running (1.2 s)", and the next frame after the call ended takes
//   it (a result for inputs changed meanwhile is dropped, and the new inputs' call starts then). A runaway is ended
//   by the call's limits (the window's deadline) with its line, never by holding the frame; one whose inputs have
//   changed, or whose switch is turned off, is stopped.
// - The student files are StudentFiles (student_file.h): saved means reloaded on the next frame that asks.
// - Nothing here throws for anything a student file does; errors keep their "curve.lua:LINE:" prefix.
// - Point numbers in messages count from 1, as Lua lists do (points[1] is "point 1").
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/bezier.h"
#include "document/student_call_work.h"
#include "document/student_file.h"
#include "exercise/exercises.h"

namespace meshedit {

// The curve view's levels as the student's code made them.
struct CurveMineLevels {
  std::vector<std::vector<glm::dvec3>> levels;  // [0]: the control points (z = 0); [k]: yours, k = 1, 2, ...
  int failed_level = -1;            // the level where yours stopped: the last of `levels` when it differs, one past
                                    // the last for an error (1 when the file did not load); -1 while all match
  bool load_failed = false;         // the file did not load: no level can be computed
  std::string error;                // why that level could not be computed: the load error or the Lua error, file:line
  int wrong_point = -1;             // 0-based index of the first point of failed_level that differs (-1: none does,
                                    // e.g. a missing point)
  glm::dvec3 mine_point{0.0};       // that point, yours
  glm::dvec3 reference_point{0.0};  // and the reference's
  std::vector<glm::dvec3> reference_level;  // the reference's step on failed_level's input
  std::vector<std::string> details;         // the checker's differences, the likely mistake first
  // One line for the view, about the levels shown (set by describe_curve_levels): "level 2, point 1 of 2: yours
  // is (...), the reference's is (...)", "curve.lua:7: ... (computing level 1)", "levels 1 to 2 are the
  // reference's". A failure past the shown levels is not mentioned yet (only a file that does not load is).
  std::string message;
  bool running = false;  // the student's evaluate_step runs for the next level now (in the background)

  bool failed() const { return failed_level >= 0; }
  // Every level down to the single curve point is computed and is the reference's.
  bool complete() const { return !failed() && !levels.empty() && levels.back().size() <= 1; }
};

// Starts from the control points (level 0, nothing computed, message "").
CurveMineLevels start_curve_levels(std::span<const glm::dvec2> control_points);
// Computes levels with the student's evaluate_step until `last_level` exists, one fails, or a single point is
// reached; then sets message for `last_level` shown.
void extend_curve_levels(StudentCode& code, CurveMineLevels& mine, double t, int last_level);
// Sets mine.message for levels 0..shown on screen.
void describe_curve_levels(CurveMineLevels& mine, int shown);

// The patch view's probe point as the student's code made it.
struct PatchMinePoint {
  bool ran = false;    // yours returned a point
  bool equal = false;  // and it is the reference's (up to the checker's tolerance)
  glm::dvec3 mine{0.0};
  glm::dvec3 reference{0.0};
  std::string error;  // the load error or the Lua error, file:line
  std::vector<std::string> details;
  std::string message;  // one line for the panel
};

PatchMinePoint check_patch_point(StudentCode& code, const BezierPatch& patch, double u, double v);

// The two switches with their files and cached results.
class BezierMine {
 public:
  explicit BezierMine(const std::filesystem::path& folder = default_student_folder());

  // Where curve.lua and patch.lua are read from (the files are loaded afresh on the next use).
  void set_folder(const std::filesystem::path& folder);
  const StudentFile& curve_file() const { return curve_file_; }
  const StudentFile& patch_file() const { return patch_file_; }

  // Switching one off stops its call running in the background (its result is dropped).
  bool curve_on() const { return curve_on_; }
  void set_curve_on(bool on);
  bool patch_on() const { return patch_on_; }
  void set_patch_on(bool on);

  // The levels of the curve `control_points` at t, computed as far as level `shown` (reloading curve.lua if it
  // was saved). Call once per frame while the switch is on.
  const CurveMineLevels& curve_levels(std::span<const glm::dvec2> control_points, double t, int shown);
  // The probe point of `patch` at (u, v) (reloading patch.lua if it was saved).
  const PatchMinePoint& patch_point(const BezierPatch& patch, double u, double v);

  // The last results (empty before the first call).
  const CurveMineLevels& curve() const { return curve_; }
  const PatchMinePoint& patch() const { return patch_; }

  // From now on each call of the student's code runs off the caller's thread (student_call_work.h; the window's and
  // the page's way): curve_levels and patch_point start it and return what they have (the line says the code is
  // running), and a later call takes its result. Without it (tests, the headless views) each call runs at once.
  void set_in_background(bool background) { background_ = background; }
  // The limits of the calls run in the background (LuaLimits' own until set).
  void set_limits(const LuaLimits& limits) { limits_ = limits; }
  // A call started in the background has not been taken yet (it runs, or a frame has still to take it).
  bool running() const { return pending_.has_value(); }
  // Takes a call that has ended (the next frame's view starts the next level); call once per frame.
  void poll();

 private:
  // A call of the student's code between its start and its result, and what it is for.
  struct PendingCall {
    bool curve = true;        // a level of the curve, or the patch's probe point
    uint64_t generation = 0;  // of the inputs it was started on: a result for older inputs is dropped
    ExerciseInput input;
    ExerciseOutcome reference;
    StudentCallResult result;  // set at once when the call could not start
    std::chrono::steady_clock::time_point started;
  };

  // Starts the student's `exercise` on `input` (the reference's outcome made here first); false when it could not
  // start (then its error is taken at once).
  bool start_call(StudentFile& file, Exercise exercise, ExerciseInput input, bool curve);
  // Takes the ended call into the curve's levels or the probe point, when it is for their current inputs.
  void take_call();
  // Stops the running call of the curve (or of the probe point) when there is one and drops what it returns.
  void abandon_call(bool curve);
  // Stops a call started for inputs that have changed since, once it has run a quarter of a second.
  void stop_stale_call();
  std::string running_words(const char* function) const;  // "your evaluate is running (1.5 s)"

  StudentFile curve_file_;
  StudentFile patch_file_;
  bool curve_on_ = false;
  bool patch_on_ = false;

  CurveMineLevels curve_;
  std::vector<glm::dvec2> curve_points_;  // what curve_ was computed from
  double curve_t_ = -1.0;
  uint64_t curve_serial_ = 0;
  bool curve_valid_ = false;

  PatchMinePoint patch_;
  BezierPatch patch_input_;
  double patch_u_ = -1.0, patch_v_ = -1.0;
  uint64_t patch_serial_ = 0;
  bool patch_valid_ = false;

  bool background_ = false;
  LuaLimits limits_;
  uint64_t curve_generation_ = 0;  // +1 each time the curve's inputs change
  uint64_t patch_generation_ = 0;  // the same for the probe point
  uint64_t patch_taken_ = 0;       // the generation patch_ was made for
  std::optional<PendingCall> pending_;
  StudentCallWork work_;  // last: destroyed first, it ends the call that pending_ started
};

}  // namespace meshedit
