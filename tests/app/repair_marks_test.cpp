// RepairMarks (app/repair_marks.h): what a row of the Repairs tab selects, the spots the view highlights, and when
// they are current.
#include <gtest/gtest.h>

#include <vector>

#include "app/repair_marks.h"
#include "core/mesh_repair.h"

namespace meshedit {
namespace {

TEST(RepairMarks, ARowSelectsItsFirstVertexElseItsFirstFace) {
  RepairMarks marks;
  marks.rows = {"bow-tie", "reversed", "unused"};
  marks.spots = {RepairSpots{{0, 5}, {1}}, RepairSpots{{}, {2, 3}}, RepairSpots{}};
  EXPECT_EQ(marks.first_spot(0), ElementRef(VertexId(0)));
  EXPECT_EQ(marks.first_spot(1), ElementRef(FaceId::face(2)));
  EXPECT_FALSE(marks.first_spot(2).valid());
  EXPECT_FALSE(marks.first_spot(3).valid());
  EXPECT_EQ(marks.all_spots(),
            (std::vector<ElementRef>{VertexId(0), VertexId(5), FaceId::face(1), FaceId::face(2), FaceId::face(3)}));
}

TEST(RepairMarks, SpotsAreCurrentOnlyForTheGenerationAndVersionTheyWereMadeFor) {
  PolygonMesh p;
  p.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}};
  p.add_face({0, 1, 2});
  p.add_face({0, 3, 4});
  RepairMarks marks = marks_of_repair(repair_polygons(p).report);
  EXPECT_EQ(marks.summary, "repaired: 1 bow-tie vertex split");
  ASSERT_EQ(marks.rows.size(), 1u);
  EXPECT_EQ(marks.first_spot(0), ElementRef(VertexId(0)));
  marks.generation = 4;
  marks.version = 9;
  EXPECT_TRUE(marks.current(4, 9));
  EXPECT_FALSE(marks.current(4, 10));  // edited
  EXPECT_FALSE(marks.current(5, 9));   // another mesh
  EXPECT_FALSE(RepairMarks().current(0, 0));
}

}  // namespace
}  // namespace meshedit
