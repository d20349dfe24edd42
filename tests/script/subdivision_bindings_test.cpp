// mesh:catmull_clark() and mesh:linear_subdivide() from Lua: the core's mesh, an undo point named after the method,
// nil and the core's reason on a broken mesh, and the face cap.
#include <gtest/gtest.h>

#include "core/catmull_clark.h"
#include "core/linear_subdivision.h"
#include "core/primitives.h"
#include "mesh_script_fixture.h"

namespace meshedit {
namespace {

using testing::MeshScript;
using testing::Strings;

TEST(SubdivisionBindings, CatmullClarkGivesTheCoresMeshAndIsAnUndoPoint) {
  MeshScript s(make_cube_quads());
  const HalfedgeMesh start = *s.mesh;
  HalfedgeMesh expected = start;
  ASSERT_TRUE(catmull_clark_subdivide(expected));
  EXPECT_EQ(s.run("local ok = m:catmull_clark() return ok, (m:validate()), m:num_vertices(), m:num_faces()"),
            (Strings{"true", "true", "26", "24"}));
  EXPECT_TRUE(s.mesh->same_as(expected));
  EXPECT_EQ(s.run("return m:undo(), m:num_faces()"), (Strings{"catmull_clark", "6"}));
  EXPECT_TRUE(s.mesh->same_as(start));
}

TEST(SubdivisionBindings, LinearGivesTheCoresMeshAndIsAnUndoPoint) {
  MeshScript s(make_tetrahedron());
  const HalfedgeMesh start = *s.mesh;
  HalfedgeMesh expected = start;
  ASSERT_TRUE(linear_subdivide(expected));
  EXPECT_EQ(s.run("local p = m:vertex(0).position local ok = m:linear_subdivide() "
                  "return ok, m:num_faces(), m:vertex(0).position == p"),
            (Strings{"true", "16", "true"}));
  EXPECT_TRUE(s.mesh->same_as(expected));
  EXPECT_EQ(s.run("return m:undo()"), Strings{"linear_subdivide"});
  EXPECT_TRUE(s.mesh->same_as(start));
}

TEST(SubdivisionBindings, RefusalsSayWhyAndChangeNothing) {
  MeshScript s(make_cube_quads());
  s.mesh->set_next(HalfedgeId(0), HalfedgeId(0));
  const HalfedgeMesh broken = *s.mesh;
  const Strings cc = s.run("return m:catmull_clark()");
  ASSERT_EQ(cc.size(), 2u);
  EXPECT_EQ(cc[0], "nil");
  EXPECT_EQ(cc[1], can_catmull_clark(broken).reason);
  const Strings linear = s.run("return m:linear_subdivide()");
  ASSERT_EQ(linear.size(), 2u);
  EXPECT_EQ(linear[1], can_linear_subdivide(broken).reason);
  EXPECT_TRUE(s.mesh->same_as(broken));
  // 1,050,000 triangles: linear subdivision would make 4,200,000, past the cap of 4,194,304; Catmull-Clark makes
  // 3 quads of each, 3,150,000, under it.
  EXPECT_EQ(s.run("local g = meshedit.grid(1000, 525) return g:linear_subdivide()"),
            (Strings{"nil", "Linear subdivision would make 4200000 faces; scripts may make at most 4194304"}));
}

}  // namespace
}  // namespace meshedit
