// The file variants of tests/data/variants/README.md, one small file each (the forms other tools' readers had to
// learn): each opens as the window opens it, plainly or, for a file with faces of fewer than 3 corners, after one
// repair that drops each such face with its report, and then subdivides (Loop and Catmull-Clark) and validates.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "core/validate.h"
#include "io/mesh_file.h"
#include "io_test_util.h"
#include "support/test_support.h"
#include "window_open.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;
using testing::expect_subdivides;
using testing::open_as_the_window_does;
using testing::Opened;

fs::path variant(const std::string& name) { return testing::source_dir() / "tests" / "data" / "variants" / name; }

struct Expected {
  const char* file;
  size_t vertices;
  size_t faces;  // once opened (after the repair, when there is one)
  size_t boundaries;
  std::vector<const char*> drops;  // the repair's changes, in order; none: the file opens as read
  const char* refusal = "";        // part of the builder's message, for a file that needs the repair
};

const std::vector<Expected>& expected_files() {
  static const std::vector<Expected> files = {
      {"obj_empty_index_parts.obj", 8, 6, 0, {}},
      {"obj_vertex_colours.obj", 6, 8, 0, {}},
      {"obj_byte_order_mark.obj", 6, 8, 0, {}},
      {"obj_two_corner_faces.obj",
       8,
       6,
       0,
       {"face 2 has 2 corners: dropped", "face 6 repeats vertex 3: dropped"},
       "face 2 has 2 corners"},
      {"obj_negative_indices.obj", 5, 5, 0, {}},
      {"obj_line_continuations.obj", 5, 5, 0, {}},
      {"ply_short_faces.ply",
       8,
       6,
       0,
       {"face 2 has 1 corners: dropped", "face 5 has 0 corners: dropped"},
       "face 2 has 1 corners"},
      {"ply_tristrips.ply", 8, 12, 0, {}},
      {"ply_tristrips_big_endian.ply", 8, 12, 0, {}},
      {"ply_header_variants.ply", 4, 4, 0, {}},
      {"off_short_faces.off",
       8,
       6,
       0,
       {"face 2 has 2 corners: dropped", "face 5 repeats vertex 0: dropped"},
       "face 2 has 2 corners"},
      {"dae_short_polygon.dae", 8, 6, 0, {"face 2 has 2 corners: dropped"}, "face 2 has 2 corners"},
  };
  return files;
}

TEST(FileVariants, EachOpensAfterAtMostOneRepairThatReportsEachDroppedFaceAndSubdivides) {
  for (const Expected& expected : expected_files()) {
    SCOPED_TRACE(expected.file);
    const Opened opened = open_as_the_window_does(variant(expected.file));
    EXPECT_EQ(opened.repaired, !expected.drops.empty()) << opened.refusal;
    EXPECT_NE(opened.refusal.find(expected.refusal), std::string::npos) << opened.refusal;
    ASSERT_EQ(opened.report.changes.size(), expected.drops.size()) << opened.report.summary();
    for (size_t i = 0; i < expected.drops.size(); ++i) EXPECT_EQ(opened.report.changes[i], expected.drops[i]);
    EXPECT_EQ(opened.report.dropped_bad_faces, expected.drops.size());
    EXPECT_EQ(opened.mesh.num_vertices(), expected.vertices);
    EXPECT_EQ(opened.mesh.num_faces(), expected.faces);
    EXPECT_EQ(opened.mesh.num_boundaries(), expected.boundaries);
    EXPECT_TRUE(validate(opened.mesh).ok());
    expect_subdivides(opened.mesh);
  }
}

TEST(FileVariants, TheReadmeListsEveryFileAndEveryFileIsTested) {
  const std::string readme = testing::read_text(variant("README.md"));
  size_t meshes = 0;
  for (const auto& entry : fs::directory_iterator(variant(""))) {
    const std::string name = entry.path().filename().string();
    if (!is_readable(entry.path())) continue;
    ++meshes;
    EXPECT_NE(readme.find("`" + name + "`"), std::string::npos) << name << " is not in README.md";
    bool tested = false;
    for (const Expected& expected : expected_files()) tested = tested || name == expected.file;
    EXPECT_TRUE(tested) << name << " has no expectations in this test";
  }
  EXPECT_EQ(meshes, expected_files().size());
}

// What the readers make of the variants, before any repair: positions as written, colours and empty index parts
// dropped, the corners of every face, and the strips' triangles all facing one way.
TEST(FileVariants, ReadersKeepPositionsAndCornersAsTheFilesHaveThem) {
  const PolygonMesh colours = load_mesh(variant("obj_vertex_colours.obj"));
  EXPECT_EQ(colours.positions[3], glm::dvec3(0, -1, 0));
  EXPECT_EQ(load_mesh(variant("obj_byte_order_mark.obj")).positions[0], glm::dvec3(1, 0, 0));
  EXPECT_EQ(load_mesh(variant("obj_line_continuations.obj")).positions[1], glm::dvec3(1, 0, 0));
  const PolygonMesh empty_parts = load_mesh(variant("obj_empty_index_parts.obj"));
  EXPECT_EQ(std::vector<uint32_t>(empty_parts.face(0).begin(), empty_parts.face(0).end()),
            (std::vector<uint32_t>{0, 3, 2, 1}));
  const PolygonMesh negative = load_mesh(variant("obj_negative_indices.obj"));
  EXPECT_EQ(negative.indices, (std::vector<uint32_t>{0, 1, 2, 3, 0, 3, 4, 3, 2, 4, 2, 1, 4, 1, 0, 4}));
  const PolygonMesh short_faces = load_mesh(variant("ply_short_faces.ply"));
  ASSERT_EQ(short_faces.num_faces(), 8u);
  EXPECT_EQ(short_faces.face(2).size(), 1u);
  EXPECT_EQ(short_faces.face(5).size(), 0u);
  // Strip 4 0 5 1 6 2 7 3 4 0: every other triangle flipped; then the caps, whose joining triangles are skipped.
  const PolygonMesh strips = load_mesh(variant("ply_tristrips.ply"));
  EXPECT_EQ(strips.indices, (std::vector<uint32_t>{4, 0, 5, 5, 0, 1, 5, 1, 6, 6, 1, 2, 6, 2, 7, 7, 2, 3,
                                                   7, 3, 4, 4, 3, 0, 4, 5, 7, 7, 5, 6, 0, 3, 1, 1, 3, 2}));
  testing::expect_same_mesh(load_mesh(variant("ply_tristrips_big_endian.ply")), strips);
}

}  // namespace
}  // namespace meshedit
