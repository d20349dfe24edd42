// The three schemes stepped one phase per call (core/subdivision_phases.h): the phases in turn give the one-call
// mesh id for id, phase 1 changes nothing and holds the points the later phases place, a refusal leaves the stepper
// at phase 1, and the names, labels and summaries the window, the answers files and Lua show.
#include <gtest/gtest.h>

#include "core/catmull_clark.h"
#include "core/linear_subdivision.h"
#include "core/loop_subdivision.h"
#include "core/mesh_build.h"
#include "core/primitives.h"
#include "core/subdivision_phases.h"
#include "core/validate.h"

namespace meshedit {
namespace {

// Runs every phase of `scheme` on `mesh`, checking that only phase 1 leaves it as it was.
void run_all_phases(SubdivisionScheme scheme, HalfedgeMesh& mesh) {
  SubdivisionPhases phases(scheme);
  const HalfedgeMesh start = mesh;
  for (int phase = 1; phase <= phase_count(scheme); ++phase) {
    ASSERT_EQ(phases.next_phase(), phase);
    ASSERT_TRUE(phases.run_next(mesh).ok);
    if (phase == 1) EXPECT_TRUE(mesh.same_as(start)) << scheme_name(scheme) << ": phase 1 changed the mesh";
    else EXPECT_TRUE(validate(mesh).ok()) << scheme_name(scheme) << " phase " << phase;
  }
  EXPECT_EQ(phases.next_phase(), 1);
  EXPECT_FALSE(phases.computed());
}

TEST(SubdivisionPhases, EachSchemeByPhasesIsItsOneCallMesh) {
  for (const PolygonMesh& polygons : {make_cube(), make_tetrahedron(), make_grid(3, 2)}) {
    const HalfedgeMesh start = build_halfedge_mesh(polygons);
    HalfedgeMesh loop = start, loop_expected = start;
    run_all_phases(SubdivisionScheme::Loop, loop);
    ASSERT_TRUE(loop_subdivide(loop_expected));
    EXPECT_TRUE(loop.same_as(loop_expected));
    HalfedgeMesh cc = start, cc_expected = start;
    run_all_phases(SubdivisionScheme::CatmullClark, cc);
    ASSERT_TRUE(catmull_clark_subdivide(cc_expected));
    EXPECT_TRUE(cc.same_as(cc_expected));
  }
  for (const PolygonMesh& polygons : {make_cube_quads(), make_icosahedron()}) {
    const HalfedgeMesh start = build_halfedge_mesh(polygons);
    HalfedgeMesh linear = start, linear_expected = start;
    run_all_phases(SubdivisionScheme::Linear, linear);
    ASSERT_TRUE(linear_subdivide(linear_expected));
    EXPECT_TRUE(linear.same_as(linear_expected));
  }
}

// Linear phase 1 on a quad cube (corners at +-1): every edge's point its midpoint, every face's its centroid, and
// phase 2 puts the new vertices exactly there.
TEST(SubdivisionPhases, LinearPhaseOneComputesMidpointsAndCentres) {
  HalfedgeMesh mesh = build_halfedge_mesh(make_cube_quads());
  SubdivisionPhases phases(SubdivisionScheme::Linear);
  ASSERT_TRUE(phases.run_next(mesh).ok);
  const LinearState* state = phases.linear_state();
  ASSERT_NE(state, nullptr);
  EXPECT_EQ(phases.catmull_clark_state(), nullptr);
  for (EdgeId e : mesh.edges()) {
    const HalfedgeId h = mesh.halfedge(e);
    const glm::dvec3 mid = (mesh.position(mesh.vertex(h)) + mesh.position(mesh.vertex(mesh.twin(h)))) * 0.5;
    EXPECT_EQ(state->position[state->layout.edge_vertex[e.index]], mid) << "e" << e.index;
  }
  for (FaceId f : mesh.faces()) {
    glm::dvec3 sum(0.0);
    mesh.for_each_face_halfedge(f, [&](HalfedgeId h) { sum += mesh.position(mesh.vertex(h)); });
    EXPECT_EQ(state->position[state->layout.face_vertex[f.slot()]], sum / 4.0) << "f" << f.slot();
  }
  EXPECT_EQ(phases.computed_summary(), "12 edge midpoints, 6 face centres");
  const LinearState kept = *state;
  ASSERT_TRUE(phases.run_next(mesh).ok);
  for (size_t v = 0; v < kept.position.size(); ++v) EXPECT_EQ(mesh.position(VertexId(uint32_t(v))), kept.position[v]);
  EXPECT_EQ(mesh.num_faces(), 24u);
}

TEST(SubdivisionPhases, SummariesCountWhatPhaseOneComputed) {
  HalfedgeMesh cube = build_halfedge_mesh(make_cube_quads());
  SubdivisionPhases cc(SubdivisionScheme::CatmullClark);
  EXPECT_EQ(cc.computed_summary(), "");
  ASSERT_TRUE(cc.run_next(cube).ok);
  EXPECT_EQ(cc.computed_summary(), "6 face points, 12 edge points, 8 vertex points");
  HalfedgeMesh tetrahedron = build_halfedge_mesh(make_tetrahedron());
  SubdivisionPhases loop(SubdivisionScheme::Loop);
  ASSERT_TRUE(loop.run_next(tetrahedron).ok);
  EXPECT_EQ(loop.computed_summary(), "4 vertex positions, 6 edge points");
}

// Loop refuses quads at phase 1: nothing changes, the stepper stays at phase 1 with nothing computed.
TEST(SubdivisionPhases, ARefusedFirstPhaseLeavesEverythingAsItWas) {
  HalfedgeMesh mesh = build_halfedge_mesh(make_cube_quads());
  const HalfedgeMesh start = mesh;
  SubdivisionPhases phases(SubdivisionScheme::Loop);
  const Check check = phases.run_next(mesh);
  EXPECT_FALSE(check.ok);
  EXPECT_EQ(check.reason, can_loop_subdivide(start).reason);
  EXPECT_EQ(phases.next_phase(), 1);
  EXPECT_FALSE(phases.computed());
  EXPECT_EQ(phases.loop_state(), nullptr);
  EXPECT_TRUE(mesh.same_as(start));
}

TEST(SubdivisionPhases, RestartDropsWhatPhaseOneComputed) {
  HalfedgeMesh mesh = build_halfedge_mesh(make_cube_quads());
  SubdivisionPhases phases(SubdivisionScheme::CatmullClark);
  ASSERT_TRUE(phases.run_next(mesh).ok);
  ASSERT_NE(phases.catmull_clark_state(), nullptr);
  phases.restart();
  EXPECT_EQ(phases.next_phase(), 1);
  EXPECT_EQ(phases.catmull_clark_state(), nullptr);
}

// A later phase given another mesh (here one level of linear subdivision made in between, which a caller should have
// noticed) refuses and starts again rather than read past what phase 1 computed; the whole-mesh operations move the
// mesh's version on, so callers do notice.
TEST(SubdivisionPhases, ALaterPhaseRefusesAnotherMesh) {
  HalfedgeMesh mesh = build_halfedge_mesh(make_cube_quads());
  SubdivisionPhases phases(SubdivisionScheme::CatmullClark);
  ASSERT_TRUE(phases.run_next(mesh).ok);
  const uint64_t seen = mesh.version();
  ASSERT_TRUE(linear_subdivide(mesh).ok);
  EXPECT_GT(mesh.version(), seen);
  const HalfedgeMesh changed = mesh;
  const Check check = phases.run_next(mesh);
  EXPECT_FALSE(check.ok);
  EXPECT_EQ(check.reason, "the mesh changed after Catmull-Clark phase 1; the phases start again at phase 1");
  EXPECT_EQ(phases.next_phase(), 1);
  EXPECT_TRUE(mesh.same_as(changed));
}

TEST(SubdivisionPhases, NamesAndLabels) {
  for (SubdivisionScheme scheme :
       {SubdivisionScheme::Loop, SubdivisionScheme::CatmullClark, SubdivisionScheme::Linear}) {
    EXPECT_EQ(scheme_named(scheme_name(scheme)), scheme);
  }
  EXPECT_EQ(scheme_named("catmull_clark"), std::nullopt);
  EXPECT_EQ(phase_label(SubdivisionScheme::Loop, 2), "Loop 2/4: split every original edge");
  EXPECT_EQ(phase_label(SubdivisionScheme::CatmullClark, 3), "Catmull-Clark 3/3: move every vertex to its point");
  EXPECT_EQ(phase_label(SubdivisionScheme::Linear, 1), "Linear 1/2: compute edge midpoints and face centres");
  EXPECT_EQ(SubdivisionPhases(SubdivisionScheme::Linear).next_label(), phase_label(SubdivisionScheme::Linear, 1));
  EXPECT_STREQ(scheme_names(), "\"loop\", \"catmull-clark\" or \"linear\"");
  EXPECT_EQ(phase_count(SubdivisionScheme::Loop), 4);
  EXPECT_EQ(phase_count(SubdivisionScheme::CatmullClark), 3);
  EXPECT_EQ(phase_count(SubdivisionScheme::Linear), 2);
}

// subdivide(mesh, scheme) is the scheme's own call, with Loop's weights and levels passed through.
TEST(SubdivisionPhases, SubdivideByNameIsEachSchemesOwnCall) {
  const HalfedgeMesh start = build_halfedge_mesh(make_cube());
  HalfedgeMesh loop = start, loop_expected = start;
  ASSERT_TRUE(subdivide(loop, SubdivisionScheme::Loop, LoopWeights::Loop, 2, 2));
  ASSERT_TRUE(loop_subdivide(loop_expected, LoopWeights::Loop, 2));
  EXPECT_TRUE(loop.same_as(loop_expected));
  HalfedgeMesh course = start, course_expected = start;  // by default one level with the course's weights
  ASSERT_TRUE(subdivide(course, SubdivisionScheme::Loop));
  ASSERT_TRUE(loop_subdivide(course_expected, LoopWeights::Course));
  EXPECT_TRUE(course.same_as(course_expected));
  HalfedgeMesh cc = start, cc_expected = start;
  ASSERT_TRUE(subdivide(cc, SubdivisionScheme::CatmullClark, LoopWeights::Course, 2));
  ASSERT_TRUE(catmull_clark_subdivide(cc_expected, 2));
  EXPECT_TRUE(cc.same_as(cc_expected));
  HalfedgeMesh linear = start, linear_expected = start;
  ASSERT_TRUE(subdivide(linear, SubdivisionScheme::Linear));
  ASSERT_TRUE(linear_subdivide(linear_expected));
  EXPECT_TRUE(linear.same_as(linear_expected));
  EXPECT_FALSE(linear.same_as(cc));
}

}  // namespace
}  // namespace meshedit
