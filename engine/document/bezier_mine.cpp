// "Mine" for the curve and patch views: see bezier_mine.h for the contract.
//
// The verdict is check_exercise's (report.equal); this file only finds the first point that differs, to name it,
// with the checker's own tolerance for a curve step (points_tolerance, core/mesh_compare.h).
#include "document/bezier_mine.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <exception>

#include <glm/geometric.hpp>

#include "core/mesh_compare.h"
#include "core/value_format.h"

namespace meshedit {
namespace {

std::string level_range(int last) { return last == 1 ? "level 1 is" : "levels 1 to " + std::to_string(last) + " are"; }

}  // namespace

void describe_curve_levels(CurveMineLevels& mine, int shown) {
  const int last = static_cast<int>(mine.levels.size()) - 1;
  if (mine.load_failed || (!mine.error.empty() && mine.failed_level <= shown)) {
    mine.message =
        mine.load_failed ? mine.error : mine.error + " (computing level " + std::to_string(mine.failed_level) + ")";
  } else if (mine.failed() && mine.failed_level <= shown) {
    const std::string level = "level " + std::to_string(mine.failed_level);
    if (mine.wrong_point >= 0) {
      mine.message = level + ", point " + std::to_string(mine.wrong_point + 1) + " of " +
                     std::to_string(mine.reference_level.size()) + ": yours is " + format_position(mine.mine_point) +
                     ", the reference's is " + format_position(mine.reference_point);
    } else {
      mine.message = level + ": " + (mine.details.empty() ? "differs from the reference" : mine.details.front());
    }
  } else if (const int visible = std::min(shown, mine.failed() ? mine.failed_level - 1 : last); visible <= 0) {
    mine.message = "press E: each level comes from your evaluate_step";
  } else {
    mine.message = level_range(visible) + " the reference's" +
                   (mine.complete() && visible == last ? ": your curve point is right" : "");
  }
}

CurveMineLevels start_curve_levels(std::span<const glm::dvec2> control_points) {
  CurveMineLevels mine;
  std::vector<glm::dvec3> level0;
  level0.reserve(control_points.size());
  for (const glm::dvec2& p : control_points) level0.emplace_back(p.x, p.y, 0.0);
  mine.levels.push_back(std::move(level0));
  return mine;
}

namespace {

// Level k (the next) of `mine` from the report of the student's step on level k - 1; true when it is the
// reference's, so the next level may follow.
bool add_curve_level(CurveMineLevels& mine, const ExerciseInput& input, const ExerciseReport& report) {
  const int k = static_cast<int>(mine.levels.size());
  if (!report.mine.error.empty()) {
    mine.failed_level = k;
    mine.error = report.mine.error;
    mine.reference_level = report.reference.points;
    return false;
  }
  mine.levels.push_back(report.mine.points);
  if (report.equal) return true;
  mine.failed_level = k;
  mine.reference_level = report.reference.points;
  mine.details = report.differences;
  const std::vector<glm::dvec3>& got = report.mine.points;
  const std::vector<glm::dvec3>& want = report.reference.points;
  const double tolerance = points_tolerance(input.points);
  for (size_t i = 0; i < std::min(got.size(), want.size()); ++i) {
    if (!(glm::distance(got[i], want[i]) <= tolerance)) {
      mine.wrong_point = static_cast<int>(i);
      mine.mine_point = got[i];
      mine.reference_point = want[i];
      break;
    }
  }
  return false;
}

bool needs_level(const CurveMineLevels& mine, int last_level) {
  return !mine.failed() && !mine.complete() && static_cast<int>(mine.levels.size()) <= last_level;
}

}  // namespace

void extend_curve_levels(StudentCode& code, CurveMineLevels& mine, double t, int last_level) {
  while (needs_level(mine, last_level)) {
    const ExerciseInput input = ExerciseInput::curve_step(mine.levels.back(), t);
    ExerciseReport report;
    try {
      report = check_exercise(code, Exercise::CurveStep, input);
    } catch (const std::exception& e) {  // check_exercise promises not to throw; a bug must not close the window
      report.mine.error = e.what();
    }
    if (!add_curve_level(mine, input, report)) break;
  }
  describe_curve_levels(mine, last_level);
}

namespace {

PatchMinePoint patch_point_of(const ExerciseReport& report, double u, double v) {
  PatchMinePoint mine;
  if (!report.reference.points.empty()) mine.reference = report.reference.points.front();
  const std::string where = "P(" + format_number(u) + ", " + format_number(v) + ")";
  if (!report.mine.error.empty()) {
    mine.error = report.mine.error;
    mine.message = mine.error;
    return mine;
  }
  mine.ran = true;
  mine.mine = report.mine.points.front();
  mine.equal = report.equal;
  mine.details = report.differences;
  mine.message = mine.equal ? "yours is the reference's " + where + " = " + format_position(mine.reference)
                            : where + ": yours is " + format_position(mine.mine) + ", the reference's is " +
                                  format_position(mine.reference);
  return mine;
}

}  // namespace

PatchMinePoint check_patch_point(StudentCode& code, const BezierPatch& patch, double u, double v) {
  ExerciseReport report;
  try {
    report = check_exercise(code, Exercise::PatchEvaluate, ExerciseInput::patch_point(patch, u, v));
  } catch (const std::exception& e) {
    report.mine.error = e.what();
  }
  return patch_point_of(report, u, v);
}

BezierMine::BezierMine(const std::filesystem::path& folder)
    : curve_file_(folder / exercise_info(Exercise::CurveStep).file),
      patch_file_(folder / exercise_info(Exercise::PatchEvaluate).file) {}

void BezierMine::set_folder(const std::filesystem::path& folder) {
  curve_file_.set_path(folder / exercise_info(Exercise::CurveStep).file);
  patch_file_.set_path(folder / exercise_info(Exercise::PatchEvaluate).file);
  curve_valid_ = patch_valid_ = false;
}

void BezierMine::set_curve_on(bool on) {
  curve_on_ = on;
  if (!on) abandon_call(true);
}

void BezierMine::set_patch_on(bool on) {
  patch_on_ = on;
  if (!on) abandon_call(false);
}

void BezierMine::abandon_call(bool curve) {
  if (!pending_ || pending_->curve != curve) return;
  work_.stop();
  if (curve) {
    ++curve_generation_;
    curve_valid_ = false;
  } else {
    ++patch_generation_;
    patch_valid_ = false;
  }
}

void BezierMine::stop_stale_call() {
  if (!pending_) return;
  const uint64_t current = pending_->curve ? curve_generation_ : patch_generation_;
  const auto age = std::chrono::steady_clock::now() - pending_->started;
  // A quick call is let end (the page would restart its worker); one that takes long is ended for the new inputs.
  if (pending_->generation != current && age > std::chrono::milliseconds(250)) work_.stop();
}

void BezierMine::poll() {
  if (pending_ && work_.done()) take_call();
}

bool BezierMine::start_call(StudentFile& file, Exercise exercise, ExerciseInput input, bool curve) {
  PendingCall pending;
  pending.curve = curve;
  pending.generation = curve ? curve_generation_ : patch_generation_;
  pending.started = std::chrono::steady_clock::now();
  StudentCall call;
  call.exercise = exercise;
  call.input = input;
  call.limits = limits_;
  try {
    pending.reference = run_reference(exercise, input);
    call.files.push_back(read_student_source(file.path()));
  } catch (const std::exception& e) {  // the file gone since it loaded, or memory running out: said as the run's error
    pending.input = std::move(input);
    pending.result.outcome.error = e.what();
    pending_ = std::move(pending);
    take_call();
    return false;
  }
  pending.input = std::move(input);
  pending_ = std::move(pending);
  work_.start(std::move(call));
  return true;
}

void BezierMine::take_call() {
  if (!pending_) return;
  PendingCall call = std::move(*pending_);
  pending_.reset();
  if (work_.busy()) call.result = work_.take();
  StudentCallResult& result = call.result;
  ExerciseOutcome mine = std::move(result.outcome);
  if (!result.load_error.empty()) mine.error = std::move(result.load_error);
  if (!result.thrown.empty()) mine.error = std::move(result.thrown);
  if (result.out_of_memory) mine.error = "memory ran out";
  const Exercise exercise = call.curve ? Exercise::CurveStep : Exercise::PatchEvaluate;
  ExerciseReport report;
  try {
    report = compare(exercise, call.input, std::move(mine), std::move(call.reference));
  } catch (const std::exception& e) {  // compare promises not to throw; a bug must not close the window
    report.mine.error = e.what();
  }
  if (call.curve && call.generation == curve_generation_) {
    add_curve_level(curve_, call.input, report);
  } else if (!call.curve && call.generation == patch_generation_) {
    patch_ = patch_point_of(report, patch_u_, patch_v_);
    patch_taken_ = patch_generation_;
  }
}

std::string BezierMine::running_words(const char* function) const {
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - pending_->started).count();
  return std::string("your ") + function + " is running (" + format_number(std::floor(seconds * 10.0) / 10.0) + " s)";
}

const CurveMineLevels& BezierMine::curve_levels(std::span<const glm::dvec2> control_points, double t, int shown) {
  const bool loaded = curve_file_.ensure_loaded();
  const bool same =
      curve_valid_ && curve_serial_ == curve_file_.serial() && curve_t_ == t &&
      std::equal(control_points.begin(), control_points.end(), curve_points_.begin(), curve_points_.end());
  if (!same) {
    curve_ = start_curve_levels(control_points);
    curve_points_.assign(control_points.begin(), control_points.end());
    curve_t_ = t;
    curve_serial_ = curve_file_.serial();
    curve_valid_ = true;
    ++curve_generation_;
    if (!loaded) {
      curve_.failed_level = 1;
      curve_.load_failed = true;
      curve_.error = curve_file_.error();
    }
  }
  if (!background_) {
    if (loaded) extend_curve_levels(*curve_file_.code(), curve_, t, shown);
    describe_curve_levels(curve_, shown);
    return curve_;
  }
  if (pending_ && work_.done()) take_call();
  stop_stale_call();
  if (loaded && !pending_ && needs_level(curve_, shown)) {
    start_call(curve_file_, Exercise::CurveStep, ExerciseInput::curve_step(curve_.levels.back(), t), true);
  }
  describe_curve_levels(curve_, shown);
  curve_.running = pending_ && pending_->curve && pending_->generation == curve_generation_;
  if (curve_.running) {
    curve_.message = "level " + std::to_string(curve_.levels.size()) + ": " + running_words("evaluate_step");
  }
  return curve_;
}

const PatchMinePoint& BezierMine::patch_point(const BezierPatch& patch, double u, double v) {
  const bool loaded = patch_file_.ensure_loaded();
  const bool same = patch_valid_ && patch_serial_ == patch_file_.serial() && patch_u_ == u && patch_v_ == v &&
                    std::memcmp(&patch_input_, &patch, sizeof(BezierPatch)) == 0;
  if (!same) {
    patch_input_ = patch;
    patch_u_ = u;
    patch_v_ = v;
    patch_serial_ = patch_file_.serial();
    patch_valid_ = true;
    ++patch_generation_;
    if (!loaded) {
      patch_ = PatchMinePoint{};
      patch_.error = patch_file_.error();
      patch_.message = patch_.error;
      patch_taken_ = patch_generation_;
    } else if (!background_) {
      patch_ = check_patch_point(*patch_file_.code(), patch, u, v);
      patch_taken_ = patch_generation_;
    }
  }
  if (!background_) return patch_;
  if (pending_ && work_.done()) take_call();
  stop_stale_call();
  if (loaded && !pending_ && patch_taken_ != patch_generation_) {
    start_call(patch_file_, Exercise::PatchEvaluate, ExerciseInput::patch_point(patch, u, v), false);
  }
  if (pending_ && !pending_->curve && pending_->generation == patch_generation_) {
    patch_ = PatchMinePoint{};
    patch_.message = "P(" + format_number(u) + ", " + format_number(v) + "): " + running_words("evaluate");
  }
  return patch_;
}

}  // namespace meshedit
