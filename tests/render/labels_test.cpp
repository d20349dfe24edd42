// Labels on screen (render/labels.h): anchors, visibility from the default view of the cube, text; the side each
// kind prefers, the requests' priorities and window coordinates; placed together (render/label_placement.h), a
// vertex label sits outside its corner, an edge label off its edge, and the flip lesson's diamond shows h0 h1 e0 f0
// f1 apart.
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

// ImGui's default font (ProggyClean, 13 px): 7 pixels per character.
glm::dvec2 proggy_size(const std::string& text) { return {7.0 * double(text.size()), 13.0}; }

glm::dvec2 pixel(const OrbitCamera& camera, Viewport viewport, const glm::dvec3& p) {
  const ScreenPoint s = camera.project(p, viewport);
  EXPECT_TRUE(s.in_front);
  return s.pixel;
}

// Whether the segment a-b passes through the rectangle (sampled every tenth of a pixel).
bool crosses(const LabelRect& rect, const glm::dvec2& a, const glm::dvec2& b) {
  const int steps = std::max(1, int(glm::length(b - a) * 10.0));
  for (int i = 0; i <= steps; ++i) {
    if (rect.contains(a + (b - a) * (double(i) / steps))) return true;
  }
  return false;
}

// Whether p is inside the triangle abc (either orientation).
bool in_triangle(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
  auto side = [](const glm::dvec2& u, const glm::dvec2& v, const glm::dvec2& w) {
    return (v.x - u.x) * (w.y - u.y) - (v.y - u.y) * (w.x - u.x);
  };
  const double s1 = side(a, b, p), s2 = side(b, c, p), s3 = side(c, a, p);
  return (s1 >= 0 && s2 >= 0 && s3 >= 0) || (s1 <= 0 && s2 <= 0 && s3 <= 0);
}

bool touches_triangle(const LabelRect& r, const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
  for (const glm::dvec2& corner : {r.min, r.max, glm::dvec2(r.min.x, r.max.y), glm::dvec2(r.max.x, r.min.y)}) {
    if (in_triangle(corner, a, b, c)) return true;
  }
  return crosses(r, a, b) || crosses(r, b, c) || crosses(r, c, a);
}

const PlacedLabel* find(const LabelPlacement& placement, ElementRef element, const std::string& text) {
  for (const PlacedLabel& l : placement.placed) {
    if (l.element == element && l.text == text) return &l;
  }
  return nullptr;
}

HalfedgeMesh triangle() {
  PolygonMesh polygons;
  polygons.positions = {{0.0, 0.0, 0.0}, {2.0, 0.0, 0.0}, {0.9, 1.7, 0.0}};
  polygons.add_face({0, 1, 2});
  return build_halfedge_mesh(polygons);
}

// lessons/4_edge_flip.lua's diamond: a-b shared by f0 = (a, b, c) and f1 = (b, a, d).
HalfedgeMesh diamond() {
  PolygonMesh polygons;
  polygons.positions = {{-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, -1.0, 0.0}};
  polygons.add_face({0, 1, 2});
  polygons.add_face({1, 0, 3});
  return build_halfedge_mesh(polygons);
}

// Seen from above: the triangle keeps its shape on screen.
OrbitCamera top_view(const HalfedgeMesh& mesh) {
  OrbitCamera camera;
  camera.fit(mesh_bounds(mesh));
  camera.set_angles(0.0, 89.0);
  return camera;
}

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

TEST(Labels, ABoundaryHalfedgeIsAnchoredAtItsEdgesMidpoint) {
  const HalfedgeMesh mesh = triangle();
  for (HalfedgeId h : mesh.halfedges()) {
    if (!mesh.face(h).is_boundary()) continue;
    const glm::dvec3 mid = (mesh.position(mesh.vertex(h)) + mesh.position(mesh.vertex(mesh.twin(h)))) * 0.5;
    EXPECT_TRUE(near(*label_anchor(mesh, h), mid, 1e-7)) << h.index;
  }
}

TEST(Labels, EachKindPrefersItsSide) {
  const HalfedgeMesh mesh = diamond();
  OrbitCamera camera;
  camera.fit(mesh_bounds(mesh));
  const Viewport viewport{1280, 800};
  auto at = [&](const glm::dvec3& p) { return pixel(camera, viewport, p); };
  const HalfedgeId h0 = mesh.halfedge(EdgeId(0)), h1 = mesh.twin(h0);
  const FaceId f0 = mesh.face(h0), f1 = mesh.face(h1);
  const glm::dvec2 f0_centre = at(*label_anchor(mesh, f0)), f1_centre = at(*label_anchor(mesh, f1));
  const glm::dvec2 mid = at(*label_anchor(mesh, EdgeId(0)));

  // The shared edge: perpendicular to it on screen, upwards.
  const glm::dvec2 a = at(mesh.position(mesh.vertex(h0))), b = at(mesh.position(mesh.vertex(h1)));
  const glm::dvec2 e0 = *label_direction(mesh, camera, viewport, EdgeId(0));
  EXPECT_NEAR(glm::dot(glm::normalize(e0), glm::normalize(b - a)), 0.0, 1e-9);
  EXPECT_LT(e0.y, 0.0);
  // h0 and h1 towards their own faces, which lie on either side of the shared edge.
  const glm::dvec2 d0 = *label_direction(mesh, camera, viewport, h0);
  const glm::dvec2 d1 = *label_direction(mesh, camera, viewport, h1);
  EXPECT_GT(glm::dot(d0, f0_centre - mid), 0.0);
  EXPECT_GT(glm::dot(d1, f1_centre - mid), 0.0);
  EXPECT_LT(glm::dot(d0, d1), 0.0);
  // A face: none.
  EXPECT_EQ(*label_direction(mesh, camera, viewport, f0), glm::dvec2(0.0));
  // A boundary edge and the boundary halfedge along it: away from the face.
  const HalfedgeId h2 = mesh.next(h0), h6 = mesh.twin(h2);
  const glm::dvec2 e2_mid = at(*label_anchor(mesh, mesh.edge(h2)));
  EXPECT_LT(glm::dot(*label_direction(mesh, camera, viewport, mesh.edge(h2)), f0_centre - e2_mid), 0.0);
  EXPECT_LT(glm::dot(*label_direction(mesh, camera, viewport, h6), f0_centre - e2_mid), 0.0);
  // A corner: away from the mesh (c, the top corner, upwards; a, the left one, to the left of b).
  const VertexId c = mesh.vertex(mesh.next(h2));
  EXPECT_LT(label_direction(mesh, camera, viewport, c)->y, 0.0);
  EXPECT_LT(glm::dot(*label_direction(mesh, camera, viewport, mesh.vertex(h0)), b - a), 0.0);
}

TEST(Labels, AVertexLabelSitsOutsideItsFacesCorner) {
  const HalfedgeMesh mesh = triangle();
  const OrbitCamera camera = top_view(mesh);
  const Viewport viewport{800, 600};
  LabelScene scene;
  scene.ids.edges = scene.ids.faces = false;
  const LabelView view{{{0.0, 0.0}, {800.0, 600.0}}, viewport};
  const std::vector<LabelRequest> requests = label_requests(mesh, camera, view, scene, proggy_size);
  ASSERT_EQ(requests.size(), 3u);
  const LabelPlacement placement = place_labels(requests, view.window);
  ASSERT_EQ(placement.placed.size(), 3u);
  const glm::dvec2 p0 = pixel(camera, viewport, mesh.position(VertexId(0)));
  const glm::dvec2 p1 = pixel(camera, viewport, mesh.position(VertexId(1)));
  const glm::dvec2 p2 = pixel(camera, viewport, mesh.position(VertexId(2)));
  const glm::dvec2 centre = (p0 + p1 + p2) / 3.0;
  for (const PlacedLabel& label : placement.placed) {
    ASSERT_EQ(label.element.kind, ElementKind::Vertex);
    const glm::dvec2 corner = pixel(camera, viewport, mesh.position(VertexId(label.element.index)));
    EXPECT_FALSE(touches_triangle(label.rect, p0, p1, p2)) << label.text;
    EXPECT_GT(glm::length(label.rect.centre() - centre), glm::length(corner - centre)) << label.text;
    EXPECT_LT(glm::length(label.rect.centre() - corner), 30.0) << label.text;  // beside its corner
  }
}

TEST(Labels, AnEdgeLabelKeepsOffItsEdgeOnTheOutside) {
  const HalfedgeMesh mesh = triangle();
  const OrbitCamera camera = top_view(mesh);
  const Viewport viewport{800, 600};
  LabelScene scene;
  scene.ids.vertices = scene.ids.faces = false;
  const LabelView view{{{0.0, 0.0}, {800.0, 600.0}}, viewport};
  const LabelPlacement placement = place_labels(label_requests(mesh, camera, view, scene, proggy_size), view.window);
  ASSERT_EQ(placement.placed.size(), 3u);
  const glm::dvec2 centre = pixel(camera, viewport, *label_anchor(mesh, FaceId::face(0)));
  for (const PlacedLabel& label : placement.placed) {
    const auto segment = *edge_segment(mesh, EdgeId(label.element.index));
    const glm::dvec2 a = pixel(camera, viewport, glm::dvec3(segment.start));
    const glm::dvec2 b = pixel(camera, viewport, glm::dvec3(segment.end));
    EXPECT_FALSE(label.rect.contains((a + b) * 0.5)) << label.text;
    EXPECT_FALSE(crosses(label.rect, a, b)) << label.text;
    // On the side away from the face.
    const glm::dvec2 n(-(b - a).y, (b - a).x);
    EXPECT_LT(glm::dot(n, label.rect.centre() - a) * glm::dot(n, centre - a), 0.0) << label.text;
  }
}

TEST(Labels, RequestsCarryPrioritiesAndWindowCoordinates) {
  const HalfedgeMesh mesh = diamond();
  OrbitCamera camera;
  camera.fit(mesh_bounds(mesh));
  // A view at (100, 40) in the window, drawn at twice the window's pixel density.
  const LabelView view{{{100.0, 40.0}, {740.0, 440.0}}, {1280, 800}};
  const HalfedgeId h0 = mesh.halfedge(EdgeId(0));
  const std::vector<std::pair<ElementRef, std::string>> lesson = {
      {h0, "h0"}, {FaceId::face(0), "f0"}, {VertexId(0), "a"}};
  LabelScene scene;
  scene.lesson = lesson;
  scene.selected = mesh.twin(h0);  // a halfedge, though halfedge labels are off
  scene.hovered = EdgeId(0);
  const std::vector<LabelRequest> requests = label_requests(mesh, camera, view, scene, proggy_size);
  auto find_request = [&](ElementRef e, LabelSource source) -> const LabelRequest* {
    for (const LabelRequest& r : requests) {
      if (r.element == e && r.source == source) return &r;
    }
    return nullptr;
  };
  ASSERT_TRUE(find_request(h0, LabelSource::Lesson));
  EXPECT_EQ(find_request(h0, LabelSource::Lesson)->priority, kLessonLabelPriority);
  EXPECT_FALSE(find_request(h0, LabelSource::Id));  // halfedge id labels are off
  ASSERT_TRUE(find_request(mesh.twin(h0), LabelSource::Id));
  EXPECT_EQ(find_request(mesh.twin(h0), LabelSource::Id)->priority, kSelectedLabelPriority);
  EXPECT_EQ(find_request(EdgeId(0), LabelSource::Id)->priority, kHoveredLabelPriority);
  EXPECT_EQ(find_request(EdgeId(1), LabelSource::Id)->priority, kOtherLabelPriority);
  // The lesson's "f0" on f0 is its id already: one label, the lesson's. "a" on v0 is not: both.
  EXPECT_TRUE(find_request(FaceId::face(0), LabelSource::Lesson));
  EXPECT_FALSE(find_request(FaceId::face(0), LabelSource::Id));
  EXPECT_TRUE(find_request(VertexId(0), LabelSource::Lesson));
  EXPECT_TRUE(find_request(VertexId(0), LabelSource::Id));
  // Anchors in window coordinates: half the framebuffer pixel, from the view's corner; text measured.
  const LabelRequest& v0 = *find_request(VertexId(0), LabelSource::Id);
  const glm::dvec2 fb = pixel(camera, view.framebuffer, mesh.position(VertexId(0)));
  EXPECT_DOUBLE_EQ(v0.anchor.x, 100.0 + fb.x * 0.5);
  EXPECT_DOUBLE_EQ(v0.anchor.y, 40.0 + fb.y * 0.5);
  EXPECT_EQ(v0.text, "v0");
  EXPECT_EQ(v0.text_size, glm::dvec2(14.0, 13.0));
  // Without id labels only the lesson's remain.
  scene.id_labels = false;
  for (const LabelRequest& r : label_requests(mesh, camera, view, scene, proggy_size)) {
    EXPECT_EQ(r.source, LabelSource::Lesson) << r.text;
  }
}

// The flip lesson's first step: every element named by the lesson, the id labels of a small mesh, the fitted view in
// the window's centre at 1280 x 800 with its default columns (528 x 736 pixels from x = 352, y = 22).
TEST(Labels, TheFlipLessonsDiamondShowsItsNamesApart) {
  const HalfedgeMesh mesh = diamond();
  OrbitCamera camera;
  camera.fit(mesh_bounds(mesh));
  const Viewport viewport{528, 736};
  const LabelView view{{{352.0, 22.0}, {352.0 + 528.0, 22.0 + 736.0}}, viewport};
  // As lessons/4_edge_flip.lua names them, walking from h0 = e0.halfedge.
  const HalfedgeId h0 = mesh.halfedge(EdgeId(0)), h1 = mesh.twin(h0);
  const HalfedgeId h2 = mesh.next(h0), h3 = mesh.next(h2), h4 = mesh.next(h1), h5 = mesh.next(h4);
  const FaceId f0 = mesh.face(h0), f1 = mesh.face(h1);
  const std::vector<std::pair<ElementRef, std::string>> lesson = {{mesh.vertex(h0), "a"},
                                                                  {mesh.vertex(h1), "b"},
                                                                  {mesh.vertex(h3), "c"},
                                                                  {mesh.vertex(h5), "d"},
                                                                  {f0, "f0"},
                                                                  {f1, "f1"},
                                                                  {h0, "h0"},
                                                                  {h1, "h1"},
                                                                  {h2, "h2"},
                                                                  {h3, "h3"},
                                                                  {h4, "h4"},
                                                                  {h5, "h5"},
                                                                  {mesh.twin(h2), "h6"},
                                                                  {mesh.twin(h3), "h7"},
                                                                  {mesh.twin(h4), "h8"},
                                                                  {mesh.twin(h5), "h9"}};
  LabelScene scene;
  scene.lesson = lesson;
  const std::vector<LabelRequest> requests = label_requests(mesh, camera, view, scene, proggy_size);
  const LabelPlacement placement = place_labels(requests, view.window);

  const PlacedLabel* named[] = {find(placement, h0, "h0"), find(placement, h1, "h1"), find(placement, EdgeId(0), "e0"),
                                find(placement, f0, "f0"), find(placement, f1, "f1")};
  for (const PlacedLabel* label : named) ASSERT_NE(label, nullptr);
  for (size_t i = 0; i < 5; ++i) {
    for (size_t j = i + 1; j < 5; ++j) EXPECT_FALSE(named[i]->rect.overlaps(named[j]->rect)) << i << " " << j;
  }
  // Every lesson label is drawn; no two labels overlap.
  for (const auto& [element, text] : lesson) EXPECT_NE(find(placement, element, text), nullptr) << text;
  for (size_t i = 0; i < placement.placed.size(); ++i) {
    for (size_t j = i + 1; j < placement.placed.size(); ++j) {
      EXPECT_FALSE(placement.placed[i].rect.overlaps(placement.placed[j].rect))
          << placement.placed[i].text << " " << placement.placed[j].text;
    }
  }
  // Where they are: h0 on f0's side of the shared edge and h1 on f1's, e0 off its midpoint, f0 and f1 on their
  // centres.
  // Projected pixels count from the view's corner; the placed rectangles are in window coordinates.
  const glm::dvec2 origin = view.window.min;
  const glm::dvec2 a = origin + pixel(camera, viewport, mesh.position(mesh.vertex(h0)));
  const glm::dvec2 b = origin + pixel(camera, viewport, mesh.position(mesh.vertex(h1)));
  const glm::dvec2 n(-(b - a).y, (b - a).x);
  const glm::dvec2 f0_centre = origin + pixel(camera, viewport, *label_anchor(mesh, f0));
  const glm::dvec2 f1_centre = origin + pixel(camera, viewport, *label_anchor(mesh, f1));
  EXPECT_GT(glm::dot(n, named[0]->rect.centre() - a) * glm::dot(n, f0_centre - a), 0.0);
  EXPECT_GT(glm::dot(n, named[1]->rect.centre() - a) * glm::dot(n, f1_centre - a), 0.0);
  const glm::dvec2 e0_mid = origin + pixel(camera, viewport, *label_anchor(mesh, EdgeId(0)));
  EXPECT_FALSE(named[2]->rect.contains(e0_mid))
      << e0_mid.x << " " << e0_mid.y << " in " << named[2]->rect.min.x << " " << named[2]->rect.min.y << " "
      << named[2]->rect.max.x << " " << named[2]->rect.max.y;
  EXPECT_TRUE(named[3]->rect.contains(f0_centre));
  EXPECT_TRUE(named[4]->rect.contains(f1_centre));
}

}  // namespace
}  // namespace meshedit
