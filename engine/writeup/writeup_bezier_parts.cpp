// Parts 1 and 2 of the write-up: the student's de Casteljau levels of a six-point curve (evaluate_step) and the
// teapot's patches evaluated by their evaluate, with and without the control net.
#include <cmath>
#include <exception>
#include <limits>

#include <glm/geometric.hpp>

#include "core/data_folders.h"
#include "core/mesh_build.h"
#include "core/patch_tessellation.h"
#include "core/value_format.h"
#include "grade/submission.h"
#include "io/bez_io.h"
#include "io/bzc_io.h"
#include "writeup/internal/writeup_parts.h"

namespace meshedit {
namespace {

constexpr int kPatchResolution = 8;

// Six points, so the levels run 0 to 5 (the spec's own curve has six).
BezierCurve six_point_curve() {
  return BezierCurve{{{0.1, 0.25}, {0.2, 0.75}, {0.45, 0.9}, {0.6, 0.2}, {0.8, 0.15}, {0.9, 0.7}}};
}

// The same curve with two of its points moved (the spec asks for a second picture with moved points).
BezierCurve moved(BezierCurve curve) {
  auto& points = curve.control_points;
  if (points.size() > 1) points[1] += glm::dvec2(0.08, -0.3);
  if (points.size() > 3) points[points.size() - 2] += glm::dvec2(-0.1, 0.4);
  return curve;
}

// The student's levels of `curve` at t, down to the curve point (or to where theirs stop).
CurveMineLevels student_levels(const PartCode& code, const BezierCurve& curve, double t) {
  CurveMineLevels mine = start_curve_levels(curve.control_points);
  const int last = std::max(0, static_cast<int>(curve.control_points.size()) - 1);
  if (code.code) {
    extend_curve_levels(*code.code, mine, t, last);
  } else {
    mine.failed_level = 1;
    mine.load_failed = true;
    mine.error = code.problem;
  }
  describe_curve_levels(mine, last);
  return mine;
}

CurvePicture curve_picture(const BezierCurve& curve, double t, int level, const CurveMineLevels& yours) {
  CurvePicture picture;
  picture.curve = curve;
  picture.t = t;
  picture.level = level;
  picture.show_curve = level + 1 >= static_cast<int>(curve.control_points.size());
  picture.yours = yours;
  describe_curve_levels(picture.yours, level);
  if (level == 0 && !picture.yours.failed()) {  // the window's "press E" has no key to press on a page
    picture.yours.message = "level 0 is the control points; each level after it comes from your evaluate_step";
  }
  picture.file = exercise_info(Exercise::CurveStep).file;
  return picture;
}

std::string curve_problem(const CurveMineLevels& mine) { return mine.failed() ? mine.message : ""; }

// The control net of each patch: its four rows and four columns of control points.
std::vector<std::vector<glm::dvec3>> control_net(const std::vector<BezierPatch>& patches) {
  std::vector<std::vector<glm::dvec3>> lines;
  for (const BezierPatch& patch : patches) {
    for (int i = 0; i < 4; ++i) {
      std::vector<glm::dvec3> row, column;
      for (int j = 0; j < 4; ++j) {
        row.push_back(patch.at(i, j));
        column.push_back(patch.at(j, i));
      }
      lines.push_back(std::move(row));
      lines.push_back(std::move(column));
    }
  }
  return lines;
}

}  // namespace

WriteupPart curve_part(const Submission& submission, const WriteupSettings& settings, std::vector<std::string>& notes) {
  WriteupPart part;
  part.heading = "Part 1: Bezier curves with 1D de Casteljau subdivision";
  part.task =
      "evaluate_step(points, t) does one step of de Casteljau's algorithm; repeated, it reaches the curve point.";
  BezierCurve curve = six_point_curve();
  std::string curve_name = "a six-point curve";
  std::string curve_refused;  // why the student's .bzc was not used (its file and line)
  if (settings.curve) {
    try {
      curve = read_bzc(*settings.curve);
      curve_name = settings.curve->filename().string();
    } catch (const std::exception& e) {
      curve_refused = std::string(e.what()) + " (the six-point curve is used)";
      notes.push_back(curve_refused);
    }
  }
  const PartCode code = load_part_code(submission, Exercise::CurveStep);
  const int n = static_cast<int>(curve.control_points.size());

  WriteupFigure levels;
  levels.number = "1.1";
  levels.caption = "Every de Casteljau level of " + curve_name + " at t = " + format_number(settings.t) +
                   ", from the control points down to the curve point";
  levels.made_by = code.made_by;
  const CurveMineLevels yours = student_levels(code, curve, settings.t);
  for (int k = 0; k < n; ++k) {
    levels.pictures.push_back({k == 0 ? "level 0: the control points" : "level " + std::to_string(k),
                               curve_picture(curve, settings.t, k, yours), ""});
  }
  levels.problem = curve_problem(yours);
  if (!curve_refused.empty()) levels.numbers.push_back("your curve file: " + curve_refused);
  part.figures.push_back(std::move(levels));

  WriteupFigure other;
  other.number = "1.2";
  other.caption = "The same curve with two control points moved, at t = " + format_number(settings.other_t);
  other.made_by = code.made_by;
  const BezierCurve moved_curve = moved(curve);
  const CurveMineLevels moved_levels = student_levels(code, moved_curve, settings.other_t);
  other.pictures.push_back({"t = " + format_number(settings.other_t),
                            curve_picture(moved_curve, settings.other_t, n - 1, moved_levels), ""});
  other.problem = curve_problem(moved_levels);
  part.figures.push_back(std::move(other));
  part.questions = {
      "How does de Casteljau's algorithm evaluate a Bezier curve, and how does your evaluate_step do it?"};
  return part;
}

WriteupPart patch_part(const Submission& submission) {
  WriteupPart part;
  part.heading = "Part 2: Bezier surfaces with separable 1D de Casteljau";
  part.task = "evaluate(patch, u, v) evaluates a bicubic Bezier patch by de Casteljau in u, then in v.";
  const PartCode code = load_part_code(submission, Exercise::PatchEvaluate);
  WriteupFigure figure;
  figure.number = "2.1";
  figure.caption = "teapot.bez evaluated by your evaluate (each patch on a " + std::to_string(kPatchResolution) + "x" +
                   std::to_string(kPatchResolution) + " grid), with and without its control net";
  figure.made_by = code.made_by;
  figure.problem = code.problem;
  std::vector<BezierPatch> patches;
  try {
    patches = read_bez(data_folder("assets") / "teapot.bez");
  } catch (const std::exception& e) {
    figure.problem = e.what();
  }
  MeshPicture surface;
  surface.smooth = true;
  surface.wireframe = false;
  if (code.code && !patches.empty()) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    bool stopped = false;
    const PatchSampler sample = [&](size_t p, double u, double v) {
      if (stopped) return glm::dvec3(nan);
      const ExerciseInput input = ExerciseInput::patch_point(patches[p], u, v);
      const ExerciseOutcome mine = code.code->run(Exercise::PatchEvaluate, input);
      if (!mine.error.empty() || mine.points.empty()) {
        stopped = true;  // one error says it; the rest of the surface is left undrawn
        figure.problem = "patch " + std::to_string(p + 1) + ", " + input.describe(Exercise::PatchEvaluate) + ": " +
                         (mine.error.empty() ? "evaluate returned " + mine.returned : mine.error);
        return glm::dvec3(nan);
      }
      const glm::dvec3 reference = evaluate_patch(patches[p], u, v);
      if (figure.problem.empty() && !(glm::distance(mine.points.front(), reference) <= 1e-9)) {
        const ExerciseReport report = check_exercise(*code.code, Exercise::PatchEvaluate, input);
        const std::string words = difference_words(report);
        if (!words.empty()) figure.problem = "patch " + std::to_string(p + 1) + ": " + words;
      }
      return mine.points.front();
    };
    try {
      surface.mesh =
          std::make_shared<HalfedgeMesh>(build_halfedge_mesh(tessellate_patches(patches, kPatchResolution, sample)));
    } catch (const std::exception& e) {  // the student's points do not make a manifold surface
      if (figure.problem.empty()) figure.problem = std::string("your points do not make a surface: ") + e.what();
    }
  }
  MeshPicture with_net = surface;
  with_net.net_lines = control_net(patches);
  figure.pictures.push_back({"with the control net", with_net, ""});
  figure.pictures.push_back({"without", surface, ""});
  part.figures.push_back(std::move(figure));
  part.questions = {"How does the 1D algorithm extend to a bicubic patch, and how does your evaluate use it?"};
  return part;
}

}  // namespace meshedit
