// The write-up's contents (writeup/writeup.h, no pictures): on the correct solutions every figure is the reference's,
// geometry and structure alike; on the graded students' mistakes the broken part's figures differ and say why in the
// grader's words while the other parts stay right; a missing file, a syntax error, a runaway and a bad writeup.json
// are each named, and the write-up is still made.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/bezier.h"
#include "core/loop_subdivision.h"
#include "core/mesh_build.h"
#include "core/mesh_compare.h"
#include "core/mesh_ops.h"
#include "core/normals.h"
#include "core/primitives.h"
#include "grade/submission.h"
#include "io/mesh_file.h"
#include "support/test_support.h"
#include "writeup/writeup.h"
#include "writeup/writeup_page.h"
#include "writeup/writeup_settings.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;

// A submission of the solutions' files, with `replaced` ("flip.lua" -> the text) put in their place.
Submission submission_of(const std::vector<std::pair<std::string, std::string>>& replaced = {},
                         const std::vector<std::string>& left_out = {}) {
  std::vector<SubmissionFile> files;
  for (const char* name : {"curve.lua", "patch.lua", "normals.lua", "flip.lua", "split.lua", "upsample.lua"}) {
    if (std::find(left_out.begin(), left_out.end(), name) != left_out.end()) continue;
    std::string text = testing::read_text(testing::source_dir() / "tests" / "exercise" / "solutions" / name);
    for (const auto& [file, replacement] : replaced) {
      if (file == name) text = replacement;
    }
    files.push_back({name, name, text});
  }
  return Submission::from_files(std::move(files));
}

std::string student(const std::string& fixture) {
  return testing::read_text(testing::source_dir() / "tests" / "grading" / "students" / fixture);
}

const WriteupFigure& figure(const Writeup& writeup, const std::string& number) {
  for (const WriteupPart& part : writeup.parts) {
    for (const WriteupFigure& f : part.figures) {
      if (f.number == number) return f;
    }
  }
  throw std::runtime_error("no figure " + number);
}

const MeshPicture& mesh_of(const WriteupFigure& f, size_t index) {
  return std::get<MeshPicture>(f.pictures.at(index).content);
}

TEST(Writeup, OnTheSolutionsEveryFigureIsTheReferencesInEveryPart) {
  const Writeup writeup = make_writeup(submission_of(), WriteupSettings{});
  ASSERT_EQ(writeup.parts.size(), 6u);
  EXPECT_EQ(writeup.parts[3].heading, "Part 4: Edge flip");
  EXPECT_EQ(writeup.failed_figures(), 0u);
  size_t figures = 0;
  for (const WriteupPart& part : writeup.parts) {
    EXPECT_FALSE(part.questions.empty()) << part.heading;
    for (const WriteupFigure& f : part.figures) {
      ++figures;
      EXPECT_EQ(f.problem, "") << f.number;
      EXPECT_FALSE(f.pictures.empty()) << f.number;
      EXPECT_EQ(f.made_by.rfind("your ", 0), 0u) << f.number;
    }
  }
  EXPECT_EQ(figures, 12u);
}

TEST(Writeup, PartOneDrawsEveryLevelOfTheStudentsStepsDownToTheCurvePoint) {
  const Writeup writeup = make_writeup(submission_of(), WriteupSettings{});
  const WriteupFigure& levels = figure(writeup, "1.1");
  ASSERT_EQ(levels.pictures.size(), 6u);  // six points: levels 0 to 5
  const auto& last = std::get<CurvePicture>(levels.pictures.back().content);
  EXPECT_EQ(last.level, 5);
  EXPECT_TRUE(last.show_curve);
  const auto reference = de_casteljau_levels(std::span<const glm::dvec2>(last.curve.control_points), 0.5);
  ASSERT_EQ(last.yours.levels.size(), reference.size());
  for (size_t k = 0; k < reference.size(); ++k) {
    ASSERT_EQ(last.yours.levels[k].size(), reference[k].size());
    for (size_t i = 0; i < reference[k].size(); ++i) {
      EXPECT_NEAR(last.yours.levels[k][i].x, reference[k][i].x, 1e-12);
      EXPECT_NEAR(last.yours.levels[k][i].y, reference[k][i].y, 1e-12);
    }
  }
  const auto& first = std::get<CurvePicture>(levels.pictures.front().content);
  EXPECT_EQ(first.yours.message, "level 0 is the control points; each level after it comes from your evaluate_step");
}

TEST(Writeup, PartsThreeToSixHoldTheReferencesMeshesPointerForPointer) {
  const Writeup writeup = make_writeup(submission_of(), WriteupSettings{});
  // Part 3: the student's normals are the core's area-weighted ones.
  const MeshPicture& phong = mesh_of(figure(writeup, "3.1"), 1);
  ASSERT_TRUE(phong.mesh);
  ASSERT_EQ(phong.normals.size(), phong.mesh->vertex_capacity());
  for (const VertexId v : phong.mesh->vertices()) {
    const glm::dvec3 n = vertex_normal(*phong.mesh, v);
    EXPECT_NEAR(phong.normals[v.index].x, n.x, 1e-6);
    EXPECT_NEAR(phong.normals[v.index].z, n.z, 1e-6);
  }
  // Part 4: the grid after the three flips is the core's flips of the same edges.
  const WriteupFigure& flips = figure(writeup, "4.1");
  HalfedgeMesh grid = build_halfedge_mesh(make_grid(4, 3));
  ASSERT_EQ(flips.pictures.at(0).content.index(), 0u);
  for (const ElementRef e : mesh_of(flips, 0).marked) ASSERT_TRUE(flip(grid, EdgeId(e.index)).ok()) << format_id(e);
  EXPECT_EQ(mesh_of(flips, 0).marked.size(), 3u);
  EXPECT_TRUE(compare_meshes(*mesh_of(flips, 1).mesh, grid).equal);
  // The pointer table names h0..h5 as lesson 4 does: h0's next is h2 before the flip.
  ASSERT_EQ(flips.table.size(), 7u);
  EXPECT_EQ(flips.table[1][0], "h0");
  EXPECT_EQ(flips.table[1][2], "h2");
  EXPECT_EQ(flips.table[1][4], "a");
  EXPECT_EQ(flips.table[1][5], "d");  // after the flip h0 leaves d (lesson 4: h0 runs from d to c)
  // Part 6: the cube after three levels is the core's Loop subdivision of it, up to renumbering.
  const WriteupFigure& cube = figure(writeup, "6.1");
  ASSERT_EQ(cube.pictures.size(), 4u);
  HalfedgeMesh reference = build_halfedge_mesh(make_cube());
  ASSERT_TRUE(loop_subdivide(reference, LoopWeights::Course, 3).ok);
  EXPECT_TRUE(compare_meshes(*mesh_of(cube, 3).mesh, reference).equal);
  ASSERT_EQ(cube.numbers.size(), 4u);
  EXPECT_NE(cube.numbers[0].find("all 0.866 from the centre"), std::string::npos) << cube.numbers[0];
  // The pre-split cube subdivides symmetrically, the plain one does not.
  EXPECT_NE(figure(writeup, "6.2").numbers.back().find("(symmetric)"), std::string::npos);
  EXPECT_EQ(cube.numbers.back().find("(symmetric)"), std::string::npos) << cube.numbers.back();
}

TEST(Writeup, AFlipThatForgetsTheFacesFailsPartFourInTheGradersWordsAndDrawsWhatItLeft) {
  const Writeup writeup = make_writeup(submission_of({{"flip.lua", student("flip_forgets_faces.lua")}}), {});
  const WriteupFigure& flips = figure(writeup, "4.1");
  EXPECT_NE(flips.problem.find("flipping e"), std::string::npos) << flips.problem;
  EXPECT_NE(flips.problem.find("is not valid"), std::string::npos) << flips.problem;
  ASSERT_TRUE(mesh_of(flips, 1).mesh);
  EXPECT_FALSE(validate(*mesh_of(flips, 1).mesh).ok());  // the broken mesh as the student left it
  EXPECT_NE(figure(writeup, "5.2").problem, "");         // the mix uses their flip too
  for (const char* fine : {"1.1", "2.1", "3.1", "5.1", "6.1"}) EXPECT_EQ(figure(writeup, fine).problem, "") << fine;
}

TEST(Writeup, EachBuggyPartSaysWhyAndOnlyItsFiguresFail) {
  struct Case {
    const char* file;
    const char* fixture;
    const char* figure;
    const char* words;
  };
  const Case cases[] = {
      {"curve.lua", "curve_swapped_weights.lua", "1.2", "level 1, point 1 of 5"},
      {"patch.lua", "patch_columns_first.lua", "2.1", "u and v are swapped"},
      {"normals.lua", "normals_unit_average.lua", "3.1", "average of the faces' unit normals"},
      {"split.lua", "split_wrong_face.lua", "5.1", "splitting e"},
      {"upsample.lua", "upsample_flips_split_halves.lua", "6.1", "a half of a split edge) was flipped"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.fixture);
    const Writeup writeup = make_writeup(submission_of({{c.file, student(c.fixture)}}), {});
    EXPECT_NE(figure(writeup, c.figure).problem.find(c.words), std::string::npos) << figure(writeup, c.figure).problem;
    EXPECT_EQ(figure(writeup, "4.1").problem, "");
  }
}

TEST(Writeup, AMissingFileASyntaxErrorAndARunawayAreNamedAndTheRestIsMade) {
  const Writeup writeup =
      make_writeup(submission_of({{"patch.lua", "function evaluate(patch, u, v)\n  while true do end\nend\n"},
                                  {"split.lua", "function split_edge(e\n"}},
                                 {"normals.lua"}),
                   {});
  EXPECT_EQ(figure(writeup, "3.1").problem, "normals.lua is not in the submission, so vertex_normal could not run");
  EXPECT_EQ(figure(writeup, "5.1").problem.rfind("split.lua:2:", 0), 0u) << figure(writeup, "5.1").problem;
  EXPECT_NE(figure(writeup, "2.1").problem.find("patch.lua:2: instruction budget exceeded"), std::string::npos)
      << figure(writeup, "2.1").problem;
  EXPECT_FALSE(figure(writeup, "2.1").pictures.empty());
  EXPECT_EQ(figure(writeup, "4.1").problem, "");
  EXPECT_EQ(writeup.failed_figures(), 5u);  // 2.1, 3.1 and split's 5.1 to 5.3
}

TEST(WriteupSettings, EveryKeyIsReadAndEveryBadValueNamedWithTheDefaultKept) {
  const WriteupSettings good = parse_writeup_settings(
      R"({"curve": "c.bzc", "t": 0.25, "camera": {"yaw": 10, "pitch": 45, "zoom": 1}, "flip_edges": [7, 9],
          "levels": 2})",
      "writeup.json", "/student");
  EXPECT_TRUE(good.problems.empty());
  EXPECT_EQ(*good.curve, fs::path("/student/c.bzc"));
  EXPECT_EQ(good.t, 0.25);
  EXPECT_EQ(good.camera.pitch, 45.0);
  EXPECT_EQ(good.flip_edges, (std::vector<uint32_t>{7, 9}));
  EXPECT_EQ(good.levels, 2);
  const WriteupSettings read_back = parse_writeup_settings(format_writeup_settings(good, "/student"), "x", "/student");
  EXPECT_EQ(*read_back.curve, *good.curve);
  EXPECT_EQ(read_back.flip_edges, good.flip_edges);
  WriteupSettings elsewhere = good;
  elsewhere.mesh = "/meshes/cow.obj";  // outside the folder: named whole, not as ../meshes/cow.obj
  EXPECT_NE(format_writeup_settings(elsewhere, "/student").find("\"mesh\": \"/meshes/cow.obj\""), std::string::npos);
  EXPECT_EQ(*parse_writeup_settings(format_writeup_settings(elsewhere, "/student"), "x", "/student").mesh,
            fs::path("/meshes/cow.obj"));

  const WriteupSettings bad =
      parse_writeup_settings(R"({"t": 2, "flip_edges": "e3", "levels": 1.5, "colour": 1})", "writeup.json", "/s");
  ASSERT_EQ(bad.problems.size(), 4u);
  EXPECT_EQ(bad.t, 0.5);
  EXPECT_TRUE(bad.flip_edges.empty());
  EXPECT_EQ(bad.levels, 3);
  EXPECT_EQ(bad.problems[0], "writeup.json: unknown key \"colour\" (left alone)");
  EXPECT_NE(parse_writeup_settings("{oops", "writeup.json", "/s").problems.at(0).find("writeup.json: not JSON"),
            std::string::npos);
}

TEST(Writeup, ACurveFileThatDoesNotParseIsNamedWithItsLineWhereTheCurveIsDrawn) {
  const fs::path dir = testing::scratch_dir();
  std::ofstream(dir / "mine.bzc") << "3\n0 0\n1 oops\n2 0\n";
  WriteupSettings settings;
  settings.curve = dir / "mine.bzc";
  const Writeup writeup = make_writeup(submission_of(), settings);
  ASSERT_EQ(writeup.notes.size(), 1u);
  EXPECT_NE(writeup.notes[0].find("mine.bzc:3"), std::string::npos) << writeup.notes[0];
  const WriteupFigure& levels = figure(writeup, "1.1");
  ASSERT_FALSE(levels.numbers.empty());
  EXPECT_NE(levels.numbers.back().find("your curve file: "), std::string::npos);
  EXPECT_NE(levels.numbers.back().find("mine.bzc:3"), std::string::npos) << levels.numbers.back();
  EXPECT_EQ(levels.pictures.size(), 6u);  // the six-point curve, drawn all the same
  EXPECT_EQ(levels.problem, "");
}

TEST(Writeup, SettingsChooseTheEdgesAndAnEdgeThatIsNotThereIsNamed) {
  WriteupSettings settings;
  settings.flip_edges = {5, 999};
  const Writeup writeup = make_writeup(submission_of(), settings);
  const WriteupFigure& flips = figure(writeup, "4.1");
  EXPECT_EQ(flips.problem, "e999 is not an edge of the mesh (writeup.json names it)");
  EXPECT_EQ(mesh_of(flips, 0).marked.front(), ElementRef(EdgeId(5)));
}

TEST(Writeup, TheChosenMeshFileIsFlippedAndSplitAndOneThatDoesNotOpenIsNamedWithTheGridUsed) {
  const fs::path dir = testing::scratch_dir();
  save_mesh(dir / "cube.obj", make_cube());
  WriteupSettings settings =
      parse_writeup_settings(R"({"mesh": "cube.obj", "flip_edges": [2], "split_edges": [4]})", "writeup.json", dir);
  ASSERT_TRUE(settings.problems.empty()) << settings.problems.front();
  const Writeup writeup = make_writeup(submission_of(), settings);
  EXPECT_TRUE(writeup.notes.empty()) << writeup.notes.front();
  HalfedgeMesh cube = build_halfedge_mesh(load_mesh(dir / "cube.obj"));
  ASSERT_TRUE(compare_meshes(*mesh_of(figure(writeup, "4.1"), 0).mesh, cube).equal);
  ASSERT_TRUE(flip(cube, EdgeId(2)).ok());
  EXPECT_TRUE(compare_meshes(*mesh_of(figure(writeup, "4.1"), 1).mesh, cube).equal);
  EXPECT_EQ(figure(writeup, "4.1").problem, "");
  EXPECT_EQ(figure(writeup, "5.1").problem, "");
  EXPECT_EQ(mesh_of(figure(writeup, "5.1"), 1).mesh->num_vertices(), 9u);  // the cube's 8 and the new one
  // A closed mesh has no boundary edge: said, not failed.
  EXPECT_EQ(figure(writeup, "5.3").problem, "");
  EXPECT_NE(figure(writeup, "5.3").numbers.at(0).find("no boundary edge"), std::string::npos);
  const std::string saved = format_writeup_settings(settings, dir);
  EXPECT_NE(saved.find("\"mesh\": \"cube.obj\""), std::string::npos) << saved;

  settings.mesh = dir / "gone.obj";
  const Writeup fallback = make_writeup(submission_of(), settings);
  ASSERT_EQ(fallback.notes.size(), 1u);
  EXPECT_NE(fallback.notes[0].find("writeup.json: \"mesh\": "), std::string::npos) << fallback.notes[0];
  EXPECT_NE(fallback.notes[0].find("gone.obj"), std::string::npos) << fallback.notes[0];
  EXPECT_NE(fallback.notes[0].find("parts 4 and 5 use the grid"), std::string::npos) << fallback.notes[0];
  EXPECT_EQ(mesh_of(figure(fallback, "4.1"), 0).mesh->num_faces(), 24u);  // the 4x3 grid's triangles
}

TEST(WriteupPage, BothFilesHoldEveryFigureTheProblemsEscapedAndAGapForAnUndrawnPicture) {
  Writeup writeup = make_writeup(submission_of({{"split.lua", "error('<script>alert(1)</script>')"}}), {});
  writeup.parts[0].figures[0].pictures[0].png = "PNGBYTES";
  const WriteupFiles files = writeup_files(writeup);
  for (const WriteupPart& part : writeup.parts) {
    for (const WriteupFigure& f : part.figures) {
      EXPECT_NE(files.html.find("Figure " + f.number + ":"), std::string::npos) << f.number;
      EXPECT_NE(files.markdown.find("### Figure " + f.number + ":"), std::string::npos) << f.number;
    }
  }
  EXPECT_EQ(files.html.find("<script>"), std::string::npos);
  EXPECT_NE(files.html.find("&lt;script&gt;"), std::string::npos);
  EXPECT_NE(files.html.find("src=\"data:image/png;base64,UE5HQllURVM=\""), std::string::npos);
  EXPECT_NE(files.html.find("this picture could not be drawn"), std::string::npos);
  ASSERT_EQ(files.images.size(), 1u);
  EXPECT_EQ(files.images[0].first, "figures/1.1-a.png");
  EXPECT_NE(files.markdown.find("](figures/1.1-a.png)"), std::string::npos);
  EXPECT_NE(files.html.find("yours to write"), std::string::npos);
  // The same submission makes the same page.
  Writeup again = make_writeup(submission_of({{"split.lua", "error('<script>alert(1)</script>')"}}), {});
  again.parts[0].figures[0].pictures[0].png = "PNGBYTES";
  EXPECT_EQ(writeup_files(again).html, files.html);
}

}  // namespace
}  // namespace meshedit
