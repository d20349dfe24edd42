// The decomposition of a wrong vertex normal (normal_recipes.h, normal_diagnosis.h) on a small irregular fan: the
// reference's own normal has nothing to say; each recipe a student's choices make (a face left out, one face alone,
// unit or angle weights, every face or one face the wrong way round, a missing normalisation, the boundary loop
// counted, and two choices at once) is recognised and told with the faces it names; a normal no recipe makes gets
// the numbers, and one very close to a recipe gets that recipe with its angle. The sums here are computed in the test
// from the corners, not by the code under test.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "core/mesh_build.h"
#include "core/normals.h"
#include "core/value_format.h"
#include "exercise/internal/normal_diagnosis.h"
#include "exercise/internal/normal_recipes.h"

namespace meshedit {
namespace {

// Five triangles of very different sizes and slopes around v0 (closed: v0 is interior); with `open`, the last is
// left out, so v0 is on the boundary.
HalfedgeMesh fan(bool open = false) {
  PolygonMesh p;
  for (const glm::dvec3& q : {glm::dvec3(0, 0, 0), glm::dvec3(3, 0, 0.5), glm::dvec3(0.5, 1, 0.2),
                              glm::dvec3(-1, 0.6, -0.3), glm::dvec3(-0.4, -0.8, 0.4), glm::dvec3(1, -2, -0.6)}) {
    p.add_vertex(q);
  }
  const std::vector<std::vector<uint32_t>> faces = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}, {0, 5, 1}};
  for (size_t i = 0; i < faces.size() - (open ? 1 : 0); ++i) p.add_face(faces[i]);
  return build_halfedge_mesh(p);
}

// What a student's code meets at each face around v0, computed from the face's corners (v0 first).
struct Corner {
  FaceId face;
  glm::dvec3 cross;  // (p1 - p0):cross(p2 - p0)
  double angle;      // at v0
};

std::vector<Corner> corners_at_v0(const HalfedgeMesh& mesh) {
  std::vector<Corner> out;
  for (FaceId f : mesh.faces()) {
    std::vector<VertexId> ring;
    mesh.for_each_face_halfedge(f, [&](HalfedgeId h) { ring.push_back(mesh.vertex(h)); });
    for (size_t i = 0; i < ring.size(); ++i) {
      if (ring[i] != VertexId(0)) continue;
      const glm::dvec3 p0 = mesh.position(ring[i]);
      const glm::dvec3 a = mesh.position(ring[(i + 1) % 3]) - p0, b = mesh.position(ring[(i + 2) % 3]) - p0;
      out.push_back({f, glm::cross(a, b), std::acos(glm::dot(glm::normalize(a), glm::normalize(b)))});
    }
  }
  return out;
}

glm::dvec3 sum_of(const std::vector<Corner>& corners, double (*weight)(const Corner&)) {
  glm::dvec3 sum(0.0);
  for (const Corner& c : corners) sum += weight(c) * glm::normalize(c.cross);
  return sum;
}
double area_weight(const Corner& c) { return glm::length(c.cross); }
double unit_weight(const Corner&) { return 1.0; }
double angle_weight(const Corner& c) { return c.angle; }

bool contains(const std::string& text, const std::string& words) { return text.find(words) != std::string::npos; }

class NormalDiagnosis : public ::testing::Test {
 protected:
  const HalfedgeMesh mesh = fan();
  const VertexId v0{0};
  const glm::dvec3 reference = vertex_normal(mesh, v0);
  const std::vector<Corner> corners = corners_at_v0(mesh);
  std::string explain(const glm::dvec3& yours) const { return explain_vertex_normal(mesh, v0, yours, reference); }
};

TEST_F(NormalDiagnosis, TheFanIsWhatTheTestsAssume) {
  ASSERT_EQ(corners.size(), 5u);
  EXPECT_LT(glm::distance(glm::normalize(sum_of(corners, area_weight)), reference), 1e-12);
  EXPECT_EQ(normal_recipes(mesh, v0).front().changes(), 0u);  // the course's recipe first
}

TEST_F(NormalDiagnosis, TheReferencesNormalHasNothingToSay) {
  EXPECT_EQ(explain(reference), "");
  EXPECT_EQ(explain(reference + glm::dvec3(1e-12, 0, 0)), "");  // rounding
  EXPECT_FALSE(match_normal(mesh, v0, reference, reference).has_value());
}

TEST_F(NormalDiagnosis, UnitAndAngleWeightsAreNamed) {
  const std::string unit = explain(glm::normalize(sum_of(corners, unit_weight)));
  EXPECT_EQ(unit, "your normal " + format_position(glm::normalize(sum_of(corners, unit_weight))) +
                      " is the average of the faces' unit normals; the reference " + format_position(reference) +
                      " weights each face by its area: add the cross products themselves, then normalise");
  const std::string angle = explain(glm::normalize(sum_of(corners, angle_weight)));
  EXPECT_TRUE(contains(angle, " weights each face by its angle at v0 (an angle-weighted normal); the reference "))
      << angle;
  EXPECT_TRUE(contains(angle, "weights each face by its area: add the cross products themselves")) << angle;
}

TEST_F(NormalDiagnosis, AFaceLeftOutIsNamed) {
  for (const Corner& missing : corners) {
    const glm::dvec3 yours = glm::normalize(sum_of(corners, area_weight) - missing.cross);
    const std::string text = explain(yours);
    EXPECT_TRUE(contains(text, " leaves out " + format_id(missing.face) +
                                   ", one of the 5 faces around v0; the "
                                   "reference "))
        << text;
    EXPECT_TRUE(contains(text, "adds the cross products of all 5: walk h = h.twin.next until h is back at v.halfedge"))
        << text;
    const auto match = match_normal(mesh, v0, yours, reference);
    ASSERT_TRUE(match.has_value());
    EXPECT_EQ(match->recipe.faces, FacesCounted::AllButOne);
    EXPECT_EQ(match->recipe.face, missing.face);
  }
}

TEST_F(NormalDiagnosis, OneFaceAloneIsNamed) {
  for (const Corner& only : corners) {
    const std::string text = explain(glm::normalize(only.cross));
    EXPECT_TRUE(contains(text, " is the normal of " + format_id(only.face) + " alone, one of the 5 faces around v0"))
        << text;
    EXPECT_TRUE(contains(text, "(sum = sum + ..., not sum = ...) and return after the loop")) << text;
  }
}

TEST_F(NormalDiagnosis, EveryFaceOrOneFaceTheWrongWayRoundIsNamed) {
  EXPECT_EQ(explain(-reference), "your normal " + format_position(-reference) + " points inwards (the reference's is " +
                                     format_position(reference) +
                                     "): take the cross product of the edges in the face's order, "
                                     "(p1 - p0):cross(p2 - p0)");
  for (const Corner& flipped : corners) {
    const std::string text = explain(glm::normalize(sum_of(corners, area_weight) - 2.0 * flipped.cross));
    EXPECT_TRUE(contains(text, " takes " + format_id(flipped.face) + "'s cross product the wrong way round")) << text;
  }
}

TEST_F(NormalDiagnosis, AMissingNormalisationIsNamedAloneAndBesideAnotherChoice) {
  const glm::dvec3 long_normal = 2.5 * reference;
  EXPECT_EQ(explain(long_normal), "your normal " + format_position(long_normal) + " points the right way but has " +
                                      "length " + format_number(glm::length(long_normal)) +
                                      "; normalise it (n:normalized())");
  const glm::dvec3 raw = sum_of(corners, area_weight) - corners[2].cross;  // a face left out, not normalised
  const std::string text = explain(raw);
  EXPECT_TRUE(contains(text, " leaves out " + format_id(corners[2].face))) << text;
  EXPECT_TRUE(contains(text, "; and normalise the sum (n:normalized()): yours has length ")) << text;
}

TEST_F(NormalDiagnosis, TwoChoicesAtOnceAreDescribedWithAFixForEach) {
  glm::dvec3 unit_but_one(0.0);
  for (const Corner& c : corners) {
    if (c.face != corners[3].face) unit_but_one += glm::normalize(c.cross);
  }
  const std::string f = format_id(corners[3].face);
  const std::string text = explain(glm::normalize(unit_but_one));
  EXPECT_EQ(text, "your normal " + format_position(glm::normalize(unit_but_one)) +
                      " is the normalised sum of the unit normals of the faces around v0 except " + f +
                      "; the reference " + format_position(reference) +
                      " is the normalised sum of the cross products of the 5 faces around v0: count " + f +
                      " too (walk h = h.twin.next until h is back at v.halfedge); weight each face by its area (add "
                      "the cross products themselves)");
  const std::string inward_angles = explain(-glm::normalize(sum_of(corners, angle_weight)));
  EXPECT_TRUE(contains(inward_angles, "each weighted by its face's angle at v0, each taken the wrong way round"))
      << inward_angles;
}

TEST_F(NormalDiagnosis, ANormalNoRecipeMakesGetsTheNumbers) {
  const glm::dvec3 yours(1, 0, 0);
  EXPECT_EQ(explain(yours), "your normal (1, 0, 0) differs from the reference's " + format_position(reference) +
                                " by " + format_number(glm::distance(yours, reference)));
  EXPECT_EQ(explain(glm::dvec3(0.0)), "your normal (0, 0, 0) differs from the reference's " +
                                          format_position(reference) + " by " + format_number(glm::length(reference)));
}

TEST_F(NormalDiagnosis, ANormalVeryCloseToARecipeGetsItWithItsAngle) {
  const glm::dvec3 unit = glm::normalize(sum_of(corners, unit_weight));
  const glm::dvec3 side = glm::normalize(glm::cross(unit, glm::dvec3(0, 0, 1)));
  const glm::dvec3 yours = glm::normalize(unit + 1e-3 * side);  // 0.057 degrees away
  const std::string text = explain(yours);
  EXPECT_TRUE(contains(text,
                       " is close to (0.06 degrees from) the normalised sum of the unit normals of the 5 faces "
                       "around v0; the reference "))
      << text;
  const glm::dvec3 far = glm::normalize(unit + 0.05 * side);  // about as far from the recipe as from the reference
  EXPECT_TRUE(contains(explain(far), " differs from the reference's ")) << explain(far);
}

TEST(NormalDiagnosisAtTheBoundary, TheBoundaryLoopCountedAsAFaceIsNamed) {
  const HalfedgeMesh mesh = fan(true);
  const VertexId v0(0);
  ASSERT_TRUE(mesh.is_boundary(v0));
  const glm::dvec3 reference = vertex_normal(mesh, v0);
  // The loop's corner at v0 as a student's code takes it: from v0's boundary halfedge, (p1 - p0):cross(p2 - p0).
  glm::dvec3 loop_cross(0.0), faces(0.0);
  FaceId loop;
  mesh.for_each_outgoing(v0, [&](HalfedgeId h) {
    const glm::dvec3 p0 = mesh.position(v0), p1 = mesh.position(mesh.vertex(mesh.next(h)));
    const glm::dvec3 p2 = mesh.position(mesh.vertex(mesh.next(mesh.next(h))));
    const glm::dvec3 cross = glm::cross(p1 - p0, p2 - p0);
    if (mesh.face(h).is_boundary()) {
      loop = mesh.face(h);
      loop_cross = cross;
    } else {
      faces += cross;
    }
  });
  const std::string text = explain_vertex_normal(mesh, v0, glm::normalize(faces + loop_cross), reference);
  EXPECT_EQ(text.rfind("your normal " + format_position(glm::normalize(faces + loop_cross)) +
                           " counts the boundary loop as a face (" + format_id(loop) + "); the reference " +
                           format_position(reference) +
                           " adds only the 4 real faces around v0: skip faces with f:is_boundary()",
                       0),
            0u)
      << text;
  EXPECT_EQ(format_id(loop), "b0");
  // The loop's corner at v0 is a face's corner the other way round: counting it cancels that face, and the message
  // says that this reads as the face left out, too.
  EXPECT_NE(text.find("; on this mesh that is also the normalised sum of the cross products of the faces around v0 "
                      "except f"),
            std::string::npos)
      << text;
}

}  // namespace
}  // namespace meshedit
