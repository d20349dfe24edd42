// Id labels on screen (render/labels.h): anchors, visibility from the default view of the cube, text.
#include <algorithm>

#include <gtest/gtest.h>

#include "core/mesh_build.h"
#include "core/primitives.h"
#include "render/labels.h"
#include "render/mesh_geometry.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

using testing::near;

bool has(const std::vector<ScreenLabel>& labels, ElementRef e) {
  return std::any_of(labels.begin(), labels.end(), [&](const ScreenLabel& l) { return l.element == e; });
}

TEST(Labels, AnchorsSitOnTheirElements) {
  const HalfedgeMesh mesh = build_halfedge_mesh(make_cube());
  EXPECT_TRUE(near(*label_anchor(mesh, VertexId(7)), {0.5, 0.5, 0.5}, 0.0));
  const HalfedgeId h = mesh.halfedge(EdgeId(0));
  const glm::dvec3 mid = (mesh.position(mesh.vertex(h)) + mesh.position(mesh.vertex(mesh.twin(h)))) * 0.5;
  EXPECT_TRUE(near(*label_anchor(mesh, EdgeId(0)), mid, 0.0));
  const auto corners = *face_corners(mesh, FaceId::face(0));
  EXPECT_TRUE(near(*label_anchor(mesh, FaceId::face(0)), (corners[0] + corners[1] + corners[2]) / 3.0, 1e-15));
  const auto arrow = *halfedge_arrow(mesh, HalfedgeId(5));
  EXPECT_TRUE(near(*label_anchor(mesh, HalfedgeId(5)), (glm::dvec3(arrow.tail) + glm::dvec3(arrow.tip)) * 0.5, 0.0));
  EXPECT_FALSE(label_anchor(mesh, ElementRef()).has_value());
  EXPECT_FALSE(label_anchor(mesh, VertexId(99)).has_value());
  EXPECT_FALSE(label_anchor(mesh, ElementRef(ElementKind::Boundary, 0)).has_value());
}

TEST(Labels, OnlyWhatFacesTheCameraIsLabelledAtItsProjection) {
  const HalfedgeMesh mesh = build_halfedge_mesh(make_cube());
  OrbitCamera camera;
  camera.fit(mesh_bounds(mesh));
  const Viewport viewport{400, 300};
  LabelOptions options;
  options.halfedges = true;
  const std::vector<ScreenLabel> labels = visible_labels(mesh, camera, viewport, options);
  // The three-quarter view shows the -y, +x and +z sides: v2 = (-,+,-) is hidden, v5 = (+,-,+) shown.
  EXPECT_TRUE(has(labels, VertexId(5)));
  EXPECT_FALSE(has(labels, VertexId(2)));
  size_t faces = 0, halfedges = 0;
  for (const ScreenLabel& l : labels) {
    EXPECT_EQ(l.text, format_id(l.element));
    const ScreenPoint p = camera.project(*label_anchor(mesh, l.element), viewport);
    EXPECT_EQ(l.pixel, p.pixel);
    faces += l.element.kind == ElementKind::Face ? 1 : 0;
    halfedges += l.element.kind == ElementKind::Halfedge ? 1 : 0;
  }
  EXPECT_EQ(faces, 6u);       // two triangles on each of three sides
  EXPECT_EQ(halfedges, 18u);  // three per visible triangle
  // Seven corners are visible: every vertex but v2.
  for (uint32_t v = 0; v < 8; ++v) EXPECT_EQ(has(labels, VertexId(v)), v != 2) << v;
}

TEST(Labels, TheCountIsCappedAndKindsCanBeLeftOut) {
  const HalfedgeMesh mesh = build_halfedge_mesh(make_grid(10, 10));
  OrbitCamera camera;
  camera.fit(mesh_bounds(mesh));
  LabelOptions options;
  options.max_labels = 25;
  EXPECT_EQ(visible_labels(mesh, camera, {800, 600}, options).size(), 25u);
  options = LabelOptions{};
  options.vertices = options.edges = false;
  const auto faces = visible_labels(mesh, camera, {800, 600}, options);
  EXPECT_EQ(faces.size(), 200u);
  for (const ScreenLabel& l : faces) EXPECT_EQ(l.element.kind, ElementKind::Face);
}

}  // namespace
}  // namespace meshedit
