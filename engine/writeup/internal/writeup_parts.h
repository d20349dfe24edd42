// The builders of the write-up's parts (writeup.h), one per part of the assignment, and what they share: the
// student's code of one exercise loaded from the submission, and the grader's words for a result that differs.
#pragma once

#include <memory>
#include <string>

#include "core/halfedge_mesh.h"
#include "exercise/exercises.h"
#include "writeup/writeup.h"

namespace meshedit {

// The student's file of one exercise, loaded alone into a fresh sandbox with the grader's limits.
struct PartCode {
  std::unique_ptr<StudentCode> code;  // null when it could not be loaded: then `problem` says why
  std::string problem;                // "flip.lua is not in the submission", "flip.lua:3: ...", "... does not define"
  std::string made_by;                // "your flip_edge (flip.lua)"
};
PartCode load_part_code(const Submission& submission, Exercise exercise);

// What a figure says when the student's run differs from the reference's: the diagnosis first, in the grader's
// words ("your split_edge left h12.face = f0 ..."); "" when they agree.
std::string difference_words(const ExerciseReport& report);

// The Utah teapot of assets/teapot.bez, tessellated at `resolution` per patch (the figures' mesh for parts 3 and 6).
std::shared_ptr<HalfedgeMesh> teapot_mesh(int resolution);

WriteupPart curve_part(const Submission& submission, const WriteupSettings& settings, std::vector<std::string>& notes);
WriteupPart patch_part(const Submission& submission);
WriteupPart normals_part(const Submission& submission);
// Parts 4 and 5's mesh: the file writeup.json names, or a 4x3 grid (with a note saying why when the file does not
// open).
std::shared_ptr<const HalfedgeMesh> edit_mesh(const WriteupSettings& settings, std::vector<std::string>& notes);
WriteupPart flip_part(const Submission& submission, const WriteupSettings& settings,
                      const std::shared_ptr<const HalfedgeMesh>& mesh);
WriteupPart split_part(const Submission& submission, const WriteupSettings& settings,
                       const std::shared_ptr<const HalfedgeMesh>& mesh);
WriteupPart upsample_part(const Submission& submission, const WriteupSettings& settings);

}  // namespace meshedit
