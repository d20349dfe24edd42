// The write-up of a student's submission: the assignment's six parts, each with the figures its deliverables ask for,
// every figure made by the student's own functions (run in the exercises' sandbox under the grader's limits), the
// numbers read off the meshes, the questions the spec asks, and an empty place for the student's explanation.
// Plain data: app/writeup_pictures.h draws each picture, writeup_page.h writes the page.
//
//   const Writeup writeup = make_writeup(Submission::read(folder), read_writeup_settings(folder));
//   draw_writeup_pictures(writeup);                        // the PNG bytes of every picture
//   write_writeup_page(writeup, "out");                    // out/index.html, out/writeup.md, out/figures/*.png
//
// Invariants:
// - Every figure of the spec is there, whatever the submission does: a figure whose function is missing, does not
//   load, errors, never returns or differs from the reference keeps what could be drawn (the input, the student's
//   result as it is, a broken mesh as the window draws it) and names the problem in `problem`, in the words the
//   Exercises tab and the grader use (file:line for an error). Nothing here throws for anything a student file does.
// - A figure says which of the student's functions made it (`made_by`: "your flip_edge (flip.lua)"), and its
//   pictures of one figure share one camera (before and after line up).
// - The same submission and settings give the same write-up: no clock, no randomness; the ids are the meshes'.
#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include <glm/vec3.hpp>

#include "core/bezier.h"
#include "core/halfedge_mesh.h"
#include "document/bezier_mine.h"
#include "writeup/writeup_settings.h"

namespace meshedit {

class Submission;

// A mesh as the mesh view draws it.
struct MeshPicture {
  std::shared_ptr<const HalfedgeMesh> mesh;
  std::vector<ElementRef> marked;  // drawn in the "changed" colour (the edges flipped or split)
  bool smooth = false;             // Phong shading (with `normals` when given), else flat
  bool wireframe = true;
  std::vector<glm::vec3> normals;                  // by vertex id: the student's vertex_normal (empty: the renderer's)
  std::vector<std::vector<glm::dvec3>> net_lines;  // a Bézier patch's control net, drawn over the surface
};

// The curve view's canvas: the control points, the levels shown, and the student's levels (mine).
struct CurvePicture {
  BezierCurve curve;
  double t = 0.5;
  int level = 0;  // levels shown (0: the control polygon; n - 1: down to the curve point)
  bool show_curve = false;
  CurveMineLevels yours;  // computed by the student's evaluate_step as far as `level`
  std::string file;       // "curve.lua"
};

struct WriteupPicture {
  std::string label;  // under the picture: "level 2", "after 3 flips"
  std::variant<MeshPicture, CurvePicture> content;
  std::string png;  // the picture, filled by draw_writeup_pictures ("" until then, or when it could not be drawn)
};

struct WriteupFigure {
  std::string number;   // "4.1"
  std::string caption;  // what it shows
  std::string made_by;  // "your flip_edge (flip.lua)"
  std::vector<WriteupPicture> pictures;
  std::vector<std::string> numbers;             // read off the meshes: "corner v0 is 0.412 from the centre"
  std::vector<std::vector<std::string>> table;  // rows of a table under the figure (the first row is its header)
  std::string problem;                          // why the figure is not what the reference would give ("": it is)
};

struct WriteupPart {
  std::string heading;  // "Part 4: Edge flip"
  std::string task;     // what the part asks, in a sentence
  std::vector<WriteupFigure> figures;
  std::vector<std::string> questions;  // the spec's questions the student answers in their explanation
};

struct Writeup {
  std::filesystem::path folder;  // the submission's
  WriteupCamera camera;          // the 3D figures' view (a flat mesh is seen from above)
  std::vector<WriteupPart> parts;
  std::vector<std::string> notes;  // about the submission and the settings (a file found in a subfolder, a bad key)
  // Figures with a problem: `writeup` exits 1 when there are any.
  size_t failed_figures() const;
};

// The grader's limits for each call of the student's code here (instructions, memory, wall time).
LuaLimits writeup_limits();

// Runs the student's functions of `submission` and lays out every part. Never throws for the submission's contents.
Writeup make_writeup(const Submission& submission, const WriteupSettings& settings);

}  // namespace meshedit
