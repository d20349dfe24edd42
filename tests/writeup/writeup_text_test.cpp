// The write-up as bytes (writeup/writeup_text.h), as the page's worker sends it: every field comes back, the broken
// mesh of a wrong flip record for record, and a request made of the student's files gives the write-up
// `meshedit writeup` makes of the same folder.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/mesh_records.h"
#include "grade/submission.h"
#include "support/test_support.h"
#include "writeup/writeup.h"
#include "writeup/writeup_page.h"
#include "writeup/writeup_settings.h"
#include "writeup/writeup_text.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;

fs::path solutions() { return testing::source_dir() / "tests" / "exercise" / "solutions"; }

// A folder of the solutions with `file` replaced by a graded student's.
fs::path student_folder(const fs::path& dir, const std::string& file, const std::string& fixture) {
  fs::create_directories(dir);
  for (const auto& entry : fs::directory_iterator(solutions())) {
    fs::copy_file(entry.path(), dir / entry.path().filename(), fs::copy_options::overwrite_existing);
  }
  fs::copy_file(testing::source_dir() / "tests" / "grading" / "students" / fixture, dir / file,
                fs::copy_options::overwrite_existing);
  return dir;
}

TEST(WriteupText, EveryFieldComesBackAndABrokenMeshRecordForRecord) {
  const fs::path folder = student_folder(testing::scratch_dir() / "student", "flip.lua", "flip_forgets_faces.lua");
  Writeup made = make_writeup(Submission::read(folder), read_writeup_settings(folder));
  made.parts.at(0).figures.at(0).pictures.at(0).png = std::string("\x89PNG\0\xff", 6);
  const Writeup back = decode_writeup(encode_writeup(made));
  EXPECT_EQ(back.folder, made.folder);
  EXPECT_EQ(back.failed_figures(), made.failed_figures());
  EXPECT_GT(made.failed_figures(), 0u);
  // The pages of both are the same text, pictures and all.
  EXPECT_EQ(writeup_files(back).html, writeup_files(made).html);
  EXPECT_EQ(writeup_files(back).markdown, writeup_files(made).markdown);
  for (size_t p = 0; p < made.parts.size(); ++p) {
    for (size_t f = 0; f < made.parts[p].figures.size(); ++f) {
      const WriteupFigure& a = made.parts[p].figures[f];
      const WriteupFigure& b = back.parts[p].figures[f];
      ASSERT_EQ(a.pictures.size(), b.pictures.size()) << a.number;
      for (size_t i = 0; i < a.pictures.size(); ++i) {
        ASSERT_EQ(a.pictures[i].content.index(), b.pictures[i].content.index()) << a.number;
        if (const auto* mesh = std::get_if<MeshPicture>(&a.pictures[i].content)) {
          const auto& other = std::get<MeshPicture>(b.pictures[i].content);
          ASSERT_EQ(bool(mesh->mesh), bool(other.mesh)) << a.number;
          if (mesh->mesh) {
            EXPECT_EQ(format_mesh_records(*mesh->mesh), format_mesh_records(*other.mesh)) << a.number;
          }
          EXPECT_EQ(mesh->marked, other.marked) << a.number;
          EXPECT_EQ(mesh->normals, other.normals) << a.number;
          EXPECT_EQ(mesh->net_lines, other.net_lines) << a.number;
          EXPECT_EQ(mesh->smooth, other.smooth) << a.number;
        } else {
          const auto& curve = std::get<CurvePicture>(a.pictures[i].content);
          const auto& other = std::get<CurvePicture>(b.pictures[i].content);
          EXPECT_EQ(curve.curve.control_points, other.curve.control_points);
          EXPECT_EQ(curve.yours.levels, other.yours.levels);
          EXPECT_EQ(curve.yours.message, other.yours.message);
          EXPECT_EQ(curve.level, other.level);
        }
      }
    }
  }
  EXPECT_THROW(decode_writeup(std::vector<uint8_t>{1, 2, 3}), std::runtime_error);
}

TEST(WriteupText, ARequestOfTheStudentsFilesMakesTheWriteupOfTheFolder) {
  const fs::path dir = testing::scratch_dir();
  const fs::path folder = student_folder(dir / "student", "split.lua", "split_wrong_face.lua");
  std::ofstream(folder / "writeup.json") << R"({"levels": 2, "mesh": "../meshes/cube.obj"})";
  std::vector<WriteupRequestFile> files;
  for (const auto& entry : fs::directory_iterator(folder)) {
    files.push_back({dir / "elsewhere" / "student" / entry.path().filename(), testing::read_text(entry.path())});
  }
  files.push_back({dir / "elsewhere" / "meshes" / "cube.obj",
                   "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n"});
  const Writeup made = make_requested_writeup(encode_writeup_request(dir / "elsewhere" / "student", files));
  EXPECT_TRUE(made.notes.empty()) << made.notes.front();
  fs::create_directories(dir / "meshes");
  fs::copy_file(dir / "elsewhere" / "meshes" / "cube.obj", dir / "meshes" / "cube.obj");
  const Writeup here = make_writeup(Submission::read(folder), read_writeup_settings(folder));
  EXPECT_EQ(made.failed_figures(), here.failed_figures());
  EXPECT_EQ(made.parts.at(5).figures.size(), here.parts.at(5).figures.size());
  EXPECT_EQ(std::get<MeshPicture>(made.parts.at(3).figures.at(0).pictures.at(0).content).mesh->num_faces(), 4u);
  EXPECT_EQ(made.parts.at(4).figures.at(0).problem, here.parts.at(4).figures.at(0).problem);
  EXPECT_THROW(make_requested_writeup(std::vector<uint8_t>{0xa0}), std::runtime_error);
}

}  // namespace
}  // namespace meshedit
