// The write-up's parts in the assignment's order, and what the part builders share (see writeup.h).
#include "writeup/writeup.h"

#include <exception>

#include "core/data_folders.h"
#include "core/mesh_build.h"
#include "core/patch_tessellation.h"
#include "grade/submission.h"
#include "io/bez_io.h"
#include "writeup/internal/writeup_parts.h"

namespace meshedit {

size_t Writeup::failed_figures() const {
  size_t failed = 0;
  for (const WriteupPart& part : parts) {
    for (const WriteupFigure& figure : part.figures) failed += figure.problem.empty() ? 0 : 1;
  }
  return failed;
}

LuaLimits writeup_limits() {
  LuaLimits limits;            // the grader's instruction budget and memory cap
  limits.wall_seconds = 10.0;  // a test's time limit in a suite
  return limits;
}

PartCode load_part_code(const Submission& submission, Exercise exercise) {
  const ExerciseInfo& info = exercise_info(exercise);
  PartCode part;
  part.made_by = std::string("your ") + info.function + " (" + info.file + ")";
  const SubmissionFile* file = submission.find(info.file);
  if (file == nullptr) {
    part.problem = std::string(info.file) + " is not in the submission, so " + info.function + " could not run";
    return part;
  }
  try {
    auto code = std::make_unique<StudentCode>(writeup_limits());
    code->load_text(file->text, info.file);
    if (!code->defines(exercise)) {
      part.problem = std::string(info.file) + " does not define " + info.function;
      return part;
    }
    part.code = std::move(code);
  } catch (const ScriptError& e) {
    part.problem = e.what();
  } catch (const std::exception& e) {  // memory running out while loading: said, never fatal
    part.problem = std::string(info.file) + ": " + e.what();
  }
  return part;
}

std::string difference_words(const ExerciseReport& report) {
  if (report.equal) return "";
  if (!report.mine.error.empty()) return report.mine.error;
  if (!report.differences.empty()) return report.differences.front();
  return report.summary();
}

std::shared_ptr<HalfedgeMesh> teapot_mesh(int resolution) {
  const std::vector<BezierPatch> patches = read_bez(data_folder("assets") / "teapot.bez");
  return std::make_shared<HalfedgeMesh>(build_halfedge_mesh(tessellate_patches(patches, resolution)));
}

Writeup make_writeup(const Submission& submission, const WriteupSettings& settings) {
  Writeup writeup;
  writeup.folder = submission.folder();
  writeup.camera = settings.camera;
  writeup.notes = submission.notes();
  writeup.notes.insert(writeup.notes.end(), settings.problems.begin(), settings.problems.end());
  writeup.parts.push_back(curve_part(submission, settings, writeup.notes));
  writeup.parts.push_back(patch_part(submission));
  writeup.parts.push_back(normals_part(submission));
  const std::shared_ptr<const HalfedgeMesh> edited = edit_mesh(settings, writeup.notes);
  writeup.parts.push_back(flip_part(submission, settings, edited));
  writeup.parts.push_back(split_part(submission, settings, edited));
  writeup.parts.push_back(upsample_part(submission, settings));
  return writeup;
}

}  // namespace meshedit
