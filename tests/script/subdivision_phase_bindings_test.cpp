// mesh:subdivision_phases(scheme) from Lua: each phase the core's, phase 1 changing nothing and its points read back
// by id, an undo point and a replayable record per later phase, the refusals (a changed mesh, a refused phase 1, an
// unknown scheme), and the one-call mesh at the end.
#include <gtest/gtest.h>

#include "core/catmull_clark.h"
#include "core/edit_log.h"
#include "core/linear_subdivision.h"
#include "core/loop_subdivision.h"
#include "core/primitives.h"
#include "core/value_format.h"
#include "mesh_script_fixture.h"
#include "script/edit_recorder.h"

namespace meshedit {
namespace {

using testing::MeshScript;
using testing::Strings;

TEST(SubdivisionPhaseBindings, CatmullClarkPhaseByPhaseWithItsPoints) {
  MeshScript s(make_cube_quads());
  const HalfedgeMesh start = *s.mesh;
  const CatmullClarkState core = catmull_clark_compute_points(start).value;
  HalfedgeMesh expected = start;
  ASSERT_TRUE(catmull_clark_subdivide(expected));
  EXPECT_EQ(s.run("p = m:subdivision_phases('catmull-clark')\n"
                  "return p.scheme, p.phase_count, p.next_phase, p.next_label, p:points()"),
            (Strings{"catmull-clark", "3", "1", "Catmull-Clark 1/3: compute face, edge and vertex points", "nil"}));
  EXPECT_EQ(s.run("return p:step()"), (Strings{"1", "Catmull-Clark 1/3: compute face, edge and vertex points"}));
  EXPECT_TRUE(s.mesh->same_as(start));
  // The points by the ids of the cube: face 2's point, edge 5's, vertex 7's, each the core's.
  EXPECT_EQ(s.run("local pts = p:points()\n"
                  "return tostring(pts.faces[2]), tostring(pts.edges[5]), tostring(pts.vertices[7]), "
                  "#pts.faces + 1, #pts.edges + 1, #pts.vertices + 1"),
            (Strings{format_position(core.face_point[2]), format_position(core.edge_point[5]),
                     format_position(core.vertex_point[7]), "6", "12", "8"}));
  EXPECT_EQ(s.run("return p:step()"),
            (Strings{"2", "Catmull-Clark 2/3: split every face into quads (nothing moves yet)"}));
  EXPECT_EQ(s.mesh->num_faces(), 24u);
  EXPECT_EQ(s.mesh->position(VertexId(7)), start.position(VertexId(7)));  // nothing moved yet
  EXPECT_EQ(s.run("local pts = p:points() return tostring(pts.vertices[7])"),
            Strings{format_position(core.vertex_point[7])});
  EXPECT_EQ(s.run("return p:step()"), (Strings{"3", "Catmull-Clark 3/3: move every vertex to its point"}));
  EXPECT_TRUE(s.mesh->same_as(expected));
  EXPECT_EQ(s.run("return p.next_phase, p:points()"), (Strings{"1", "nil"}));
  // Two undo points, each named for what it was.
  EXPECT_EQ(s.run("return m:undo(), m:num_faces()"), (Strings{"subdivision phase", "24"}));
  EXPECT_EQ(s.run("return m:undo(), m:num_faces()"), (Strings{"subdivision phase", "6"}));
  EXPECT_TRUE(s.mesh->same_as(start));
}

TEST(SubdivisionPhaseBindings, LoopAndLinearEndAtTheirOneCallMeshes) {
  MeshScript loop(make_tetrahedron());
  HalfedgeMesh loop_expected = *loop.mesh;
  ASSERT_TRUE(loop_subdivide(loop_expected));
  EXPECT_EQ(loop.run("local p = m:subdivision_phases('loop') local pts\n"
                     "for i = 1, 4 do local phase = p:step() if i == 1 then pts = p:points() end end\n"
                     "return #pts.vertices + 1, #pts.edges + 1, pts.faces == nil"),
            (Strings{"4", "6", "true"}));
  EXPECT_TRUE(loop.mesh->same_as(loop_expected));

  MeshScript linear(make_cube_quads());
  HalfedgeMesh linear_expected = *linear.mesh;
  ASSERT_TRUE(linear_subdivide(linear_expected));
  EXPECT_EQ(linear.run("local p = m:subdivision_phases('linear') p:step()\n"
                       "local pts = p:points() local face = pts.faces[0]\n"
                       "local a, b = p:step() return a, b, tostring(face), pts.vertices == nil"),
            (Strings{"2", "Linear 2/2: split every face (triangles in four, other faces into quads)",
                     format_position(linear_expected.position(VertexId(8 + 12))), "true"}));
  EXPECT_TRUE(linear.mesh->same_as(linear_expected));
}

TEST(SubdivisionPhaseBindings, RefusalsSayWhyAndChangeNothing) {
  MeshScript s(make_cube_quads());
  const HalfedgeMesh start = *s.mesh;
  // Loop refuses quads at phase 1, with the core's reason.
  EXPECT_EQ(s.run("local p = m:subdivision_phases('loop') local ok, why = p:step() return ok, why, p.next_phase"),
            (Strings{"nil", can_loop_subdivide(start).reason, "1"}));
  EXPECT_TRUE(s.mesh->same_as(start));
  // A change between phases: refused until restart().
  EXPECT_EQ(s.run("p = m:subdivision_phases('catmull-clark') p:step() m:linear_subdivide()\n"
                  "return p:step()"),
            (Strings{"nil", "the mesh changed after Catmull-Clark phase 1; phases:restart() starts again at phase 1"}));
  EXPECT_EQ(s.run("p:restart() return p.next_phase, p:points(), (p:step())"), (Strings{"1", "nil", "1"}));
  EXPECT_EQ(s.error("m:subdivision_phases('cc')"),
            "t.lua:1: bad argument #1 to 'subdivision_phases' (expected \"loop\", \"catmull-clark\" or \"linear\")");
  EXPECT_EQ(s.run("return tostring(m:subdivision_phases('linear'))"),
            Strings{"linear phases (next: Linear 1/2: compute edge midpoints and face centres)"});
}

// A recording of the phases replays to the same mesh (each later phase is recorded with the mesh it made); the
// one-call methods replay too.
TEST(SubdivisionPhaseBindings, RecordedPhasesReplay) {
  MeshScript s(make_cube_quads());
  EditRecorder recorder(s.lua.state(), s.mesh, {.keep_before = true, .max_edits = 100});
  s.run(
      "local p = m:subdivision_phases('catmull-clark') p:step() p:step() p:step() m:linear_subdivide()\n"
      "m:catmull_clark()");
  ASSERT_EQ(recorder.edits().size(), 4u);
  EXPECT_EQ(describe(recorder.edits()[0]), "subdivision phase");
  EXPECT_TRUE(replay(*recorder.before(), recorder.edits(), recorder.edits().size()).same_as(*s.mesh));
}

}  // namespace
}  // namespace meshedit
