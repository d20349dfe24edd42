// Picking on a rendered cube (EGL, 256x256), checked against exact CPU ray casts and projections, both by the
// exact id pass and by the faces-only pass large meshes get (pick_from_faces.h; the threshold lowered to the
// cube), and the renderer's upload accounting: an idle frame or a selection change does no geometry work.
#include <cmath>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "core/mesh_build.h"
#include "core/normals.h"
#include "core/primitives.h"
#include "gl_test_support.h"
#include "ray_cast.h"
#include "render/mesh_geometry.h"
#include "render/overlay_renderer.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

constexpr Viewport kViewport{256, 256};

// The exact answers, for this test's viewport.
ElementRef cast(const HalfedgeMesh& mesh, const OrbitCamera& camera, int x, int y) {
  return testing::cast(mesh, camera, kViewport, x, y);
}
using testing::edge_between;

class Picking : public testing::GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    if (IsSkipped()) return;
    mesh_ = build_halfedge_mesh(make_cube());
    shaders_ = std::make_unique<ShaderLibrary>();
    renderer_ = std::make_unique<MeshRenderer>(*shaders_);
    target_ = std::make_unique<RenderTarget>(kViewport.width, kViewport.height, 4);
    renderer_->update(mesh_);
    camera_.fit(renderer_->bounds());
  }
  void TearDown() override {
    renderer_.reset();
    target_.reset();
  }
  void check_arrows_pick_their_halfedges();
  ElementRef draw_and_pick(int x, int y, const ViewOptions& options = {}) {
    target_->clear(renderer_->style().background);
    renderer_->update(mesh_);
    renderer_->draw(camera_, kViewport, options, {});
    return renderer_->pick(camera_, kViewport, x, y);
  }
  // Large-mesh picking (a faces-only id pass) for any mesh, or the default threshold again.
  void use_large_mesh_path(bool large) {
    renderer_->style().large_mesh_triangles = large ? 0 : RenderStyle().large_mesh_triangles;
  }
  glm::ivec2 pixel_of(const glm::dvec3& p) const {
    const ScreenPoint s = camera_.project(p, kViewport);
    return {int(std::floor(s.pixel.x)), int(std::floor(s.pixel.y))};
  }

  HalfedgeMesh mesh_;
  std::unique_ptr<ShaderLibrary> shaders_;
  std::unique_ptr<MeshRenderer> renderer_;
  std::unique_ptr<RenderTarget> target_;
  OrbitCamera camera_;
};

TEST_F(Picking, CentrePixelPicksTheFaceARayCastMeets) {
  const ElementRef expected = cast(mesh_, camera_, 128, 128);
  ASSERT_TRUE(expected.valid());
  EXPECT_EQ(expected.kind, ElementKind::Face);
  // The ray through the centre meets the front (y = -0.5) side, in the default Z-up view.
  const auto corners = face_corners(mesh_, expected.face_id());
  ASSERT_TRUE(corners.has_value());
  for (const glm::dvec3& c : *corners) EXPECT_EQ(c.y, -0.5);
  EXPECT_EQ(draw_and_pick(128, 128), expected) << format_id(draw_and_pick(128, 128));
}

TEST_F(Picking, FacesAcrossTheImageMatchExactRayCasts) {
  // Pixels well inside faces (no edge within the pick window's reach) agree with the CPU ray cast.
  int checked = 0;
  for (int y = 20; y < 256; y += 24) {
    for (int x = 20; x < 256; x += 24) {
      const ElementRef picked = draw_and_pick(x, y);
      if (picked.kind != ElementKind::Face && picked.valid()) continue;  // near an edge or vertex
      EXPECT_EQ(picked, cast(mesh_, camera_, x, y)) << "pixel " << x << "," << y;
      ++checked;
    }
  }
  EXPECT_GT(checked, 50);
}

TEST_F(Picking, TheNearestCornerPicksItsVertex) {
  for (const bool large : {false, true}) {
    SCOPED_TRACE(large ? "faces-only pass" : "exact pass");
    use_large_mesh_path(large);
    // v5 = (+0.5, -0.5, +0.5) is the corner nearest the eye in the three-quarter view (front, right, top).
    const glm::ivec2 p = pixel_of(mesh_.position(VertexId(5)));
    EXPECT_EQ(draw_and_pick(p.x, p.y), ElementRef(VertexId(5)));
    EXPECT_EQ(renderer_->stats().last_id_pass_faces_only, large);
    // A few pixels off still finds it (kVertexPickRadius).
    EXPECT_EQ(draw_and_pick(p.x + 3, p.y + 3), ElementRef(VertexId(5)));
    EXPECT_NE(draw_and_pick(p.x + 6, p.y + 6), ElementRef(VertexId(5)));
  }
}

TEST_F(Picking, AnEdgeMidpointPicksTheEdge) {
  for (const bool large : {false, true}) {
    SCOPED_TRACE(large ? "faces-only pass" : "exact pass");
    use_large_mesh_path(large);
    // The edge v4-v5 runs along the top of the front side, visible from above.
    const EdgeId e = edge_between(mesh_, VertexId(4), VertexId(5));
    ASSERT_TRUE(e.valid());
    const glm::ivec2 p = pixel_of((mesh_.position(VertexId(4)) + mesh_.position(VertexId(5))) * 0.5);
    EXPECT_EQ(draw_and_pick(p.x, p.y), ElementRef(e));
    // Also without the wireframe: edges stay pickable.
    ViewOptions plain;
    plain.wireframe = false;
    EXPECT_EQ(draw_and_pick(p.x, p.y, plain), ElementRef(e));
    // The edge v2-v6 lies on the back, hidden: a pixel on its image gives what is in front, never the edge.
    const EdgeId back = edge_between(mesh_, VertexId(2), VertexId(6));
    ASSERT_TRUE(back.valid());
    const glm::ivec2 q = pixel_of((mesh_.position(VertexId(2)) + mesh_.position(VertexId(6))) * 0.5);
    EXPECT_NE(draw_and_pick(q.x, q.y), ElementRef(back));
  }
}

TEST_F(Picking, ShownArrowsPickTheirHalfedge) {
  for (const bool large : {false, true}) {
    SCOPED_TRACE(large ? "faces-only pass" : "exact pass");
    use_large_mesh_path(large);
    check_arrows_pick_their_halfedges();
  }
}

void Picking::check_arrows_pick_their_halfedges() {
  ViewOptions options;
  options.show_halfedges = true;
  int checked = 0;
  for (HalfedgeId h : mesh_.halfedges()) {
    const auto arrow = halfedge_arrow(mesh_, h);
    ASSERT_TRUE(arrow.has_value());
    const glm::dvec3 middle = (glm::dvec3(arrow->tail) + glm::dvec3(arrow->tip)) * 0.5;
    // Only arrows on faces turned to the camera can be seen.
    if (glm::dot(face_normal(mesh_, mesh_.face(h)), camera_.eye() - middle) <= 0.0) continue;
    const glm::ivec2 p = pixel_of(middle);
    EXPECT_EQ(draw_and_pick(p.x, p.y, options), ElementRef(h)) << format_id(h);
    ++checked;
  }
  EXPECT_EQ(checked, 18);  // three sides of two triangles of three halfedges
  // Hidden arrows are not pickable: the same pixels then give the face or a nearby edge.
  for (HalfedgeId h : mesh_.halfedges()) {
    const auto arrow = halfedge_arrow(mesh_, h);
    const glm::dvec3 middle = (glm::dvec3(arrow->tail) + glm::dvec3(arrow->tip)) * 0.5;
    if (glm::dot(face_normal(mesh_, mesh_.face(h)), camera_.eye() - middle) <= 0.0) continue;
    const glm::ivec2 p = pixel_of(middle);
    const ElementRef picked = draw_and_pick(p.x, p.y);
    EXPECT_TRUE(picked.kind == ElementKind::Face || picked.kind == ElementKind::Edge) << format_id(picked);
  }
}

TEST_F(Picking, OnADenseGridEveryVertexPicksItself) {
  // 40x40 cells in about 200 pixels: vertices five pixels apart, all within each other's reach.
  mesh_ = build_halfedge_mesh(make_grid(40, 40));
  renderer_->update(mesh_);
  camera_.fit(renderer_->bounds());
  for (const bool large : {false, true}) {
    SCOPED_TRACE(large ? "faces-only pass" : "exact pass");
    use_large_mesh_path(large);
    target_->clear(renderer_->style().background);
    ViewOptions options;
    options.show_vertices = true;
    renderer_->draw(camera_, kViewport, options, {});
    int checked = 0;
    for (VertexId v : mesh_.vertices()) {
      if (v.index % 7 != 0) continue;
      const glm::ivec2 p = pixel_of(mesh_.position(v));
      EXPECT_EQ(renderer_->pick(camera_, kViewport, p.x, p.y), ElementRef(v)) << format_id(v);
      ++checked;
    }
    EXPECT_EQ(checked, 241);  // 1681 vertices, every 7th
    EXPECT_EQ(renderer_->stats().last_id_pass_faces_only, large);
  }
}

TEST_F(Picking, LargeMeshPathAgreesWithTheExactPassInsideFaces) {
  // Pixels well inside faces: both passes give the face a ray cast meets.
  int checked = 0;
  for (int y = 20; y < 256; y += 24) {
    for (int x = 20; x < 256; x += 24) {
      use_large_mesh_path(false);
      const ElementRef exact = draw_and_pick(x, y);
      if (exact.kind != ElementKind::Face) continue;  // background, or near an edge or vertex
      use_large_mesh_path(true);
      EXPECT_EQ(draw_and_pick(x, y), exact) << "pixel " << x << "," << y;
      ++checked;
    }
  }
  EXPECT_GE(checked, 30);  // 38 of the 100 pixels: the others are background or near an edge
}

TEST_F(Picking, ABrokenLargeMeshKeepsTheExactPass) {
  // A face that cannot be walked: its edges may be drawn with no face around them, so only the exact pass
  // finds them.
  use_large_mesh_path(true);
  mesh_.set_next(HalfedgeId(2), HalfedgeId(1));
  renderer_->update(mesh_);
  ASSERT_GT(renderer_->stats().skipped_faces, 0u);
  EXPECT_TRUE(draw_and_pick(128, 128).valid());
  EXPECT_FALSE(renderer_->stats().last_id_pass_faces_only);
}

TEST_F(Picking, BackgroundAndOutsidePixelsPickNothing) {
  EXPECT_FALSE(draw_and_pick(2, 2).valid());
  EXPECT_FALSE(draw_and_pick(253, 3).valid());
  EXPECT_FALSE(renderer_->pick(camera_, kViewport, -1, 10).valid());
  EXPECT_FALSE(renderer_->pick(camera_, kViewport, 10, 256).valid());
}

TEST_F(Picking, HoveringOverAStillViewReusesTheIdBuffer) {
  draw_and_pick(128, 128);
  const uint64_t passes = renderer_->stats().id_passes;
  renderer_->pick(camera_, kViewport, 100, 100);
  renderer_->pick(camera_, kViewport, 140, 90);
  EXPECT_EQ(renderer_->stats().id_passes, passes);
  camera_.orbit(5, 0);
  renderer_->pick(camera_, kViewport, 128, 128);
  EXPECT_EQ(renderer_->stats().id_passes, passes + 1);
}

TEST_F(Picking, UpdateUploadsOncePerVersion) {
  // SetUp already updated once.
  EXPECT_EQ(renderer_->stats().uploads, 1u);
  renderer_->update(mesh_);
  renderer_->update(mesh_);
  EXPECT_EQ(renderer_->stats().uploads, 1u);
  // Drawing with changing highlights touches no geometry.
  Highlights highlights;
  highlights.selected = EdgeId(3);
  renderer_->draw(camera_, kViewport, {}, highlights);
  highlights.hovered = VertexId(5);
  renderer_->draw(camera_, kViewport, {}, highlights);
  const std::vector<ElementRef> changed = {ElementRef(FaceId::face(1)), ElementRef(HalfedgeId(4))};
  highlights.changed = changed;
  renderer_->draw(camera_, kViewport, {}, highlights);
  renderer_->draw(camera_, kViewport, {}, highlights);
  EXPECT_EQ(renderer_->stats().uploads, 1u);
  // Moving a vertex is a new version: one more upload, and the picture follows.
  mesh_.set_position(VertexId(5), {0.9, -0.9, 0.9});
  renderer_->update(mesh_);
  renderer_->update(mesh_);
  EXPECT_EQ(renderer_->stats().uploads, 2u);
  const glm::ivec2 p = pixel_of(mesh_.position(VertexId(5)));
  EXPECT_EQ(draw_and_pick(p.x, p.y), ElementRef(VertexId(5)));
}

TEST_F(Picking, AMeshObjectGivenAnotherMeshIsUploadedAgain) {
  EXPECT_EQ(renderer_->stats().uploads, 1u);
  // Different counts: noticed even if the versions happened to agree.
  mesh_ = build_halfedge_mesh(make_cube_quads());
  renderer_->update(mesh_);
  EXPECT_EQ(renderer_->stats().uploads, 2u);
  EXPECT_EQ(renderer_->stats().edges, 12u);
  // Same counts and the same version but other positions: the owner bumps the version (as undo does),
  HalfedgeMesh other = build_halfedge_mesh(make_cube_quads());
  other.set_position(VertexId(0), {-2.0, -2.0, -2.0});
  const uint64_t seen = mesh_.version();
  mesh_ = other;
  mesh_.bump_version_above(seen);
  renderer_->update(mesh_);
  EXPECT_EQ(renderer_->stats().uploads, 3u);
  EXPECT_TRUE(testing::near(renderer_->bounds().min, {-2.0, -2.0, -2.0}, 0.0));
  // or tells the renderer.
  renderer_->invalidate();
  renderer_->update(mesh_);
  EXPECT_EQ(renderer_->stats().uploads, 4u);
  renderer_->update(mesh_);
  EXPECT_EQ(renderer_->stats().uploads, 4u);
}

TEST_F(Picking, HighlightsColourTheirElements) {
  ViewOptions options;
  options.wireframe = false;
  const ElementRef front = cast(mesh_, camera_, 128, 128);
  target_->clear(renderer_->style().background);
  renderer_->draw(camera_, kViewport, options, {});
  const auto plain = target_->read_rgba();
  Highlights highlights;
  highlights.selected = front;
  target_->clear(renderer_->style().background);
  renderer_->draw(camera_, kViewport, options, highlights);
  const auto selected = target_->read_rgba();
  const size_t centre = (128 * 256 + 128) * 4;
  // The selected face turns towards the selection's yellow: more red and green than blue now.
  EXPECT_LT(plain[centre + 0], plain[centre + 2]);
  EXPECT_GT(selected[centre + 0], selected[centre + 2]);
  EXPECT_GT(selected[centre + 1], selected[centre + 2]);
}

TEST_F(Picking, ABrokenMeshIsDrawnAsFarAsItCanBeWalked) {
  mesh_.set_next(HalfedgeId(2), HalfedgeId(1));       // f0's cycle becomes a rho
  mesh_.set_next(HalfedgeId(5), HalfedgeId(999999));  // f1's leaves the arrays
  renderer_->update(mesh_);
  EXPECT_EQ(renderer_->stats().skipped_faces, 2u);
  EXPECT_EQ(renderer_->stats().triangles, 10u);
  ViewOptions options;
  options.show_halfedges = true;
  options.show_vertices = true;
  target_->clear(renderer_->style().background);
  renderer_->draw(camera_, kViewport, options, {});
  const Image image{256, 256, target_->read_rgba()};
  size_t lit = 0;
  for (size_t i = 0; i < image.rgba.size(); i += 4) lit += image.rgba[i + 2] > 80 ? 1 : 0;
  EXPECT_GT(lit, 5000u);  // most of the cube is still there
  EXPECT_TRUE(renderer_->pick(camera_, kViewport, 128, 128).valid());
}

TEST_F(Picking, OverlaysDrawTheirOwnColours) {
  const ShaderLibrary shaders;
  OverlayRenderer overlay_renderer(shaders);
  Overlay overlay;
  overlay.on_top = true;
  overlay.lines.push_back({{{-0.5, -0.5, 0.0}, {0.5, -0.5, 0.0}}, glm::vec4(1, 0, 0, 1), 6.0f, false});
  overlay.points.push_back({{0.0, -0.5, 0.3}, glm::vec4(0, 1, 0, 1), 12.0f});
  target_->clear(renderer_->style().background);
  renderer_->draw(camera_, kViewport, {}, {});
  overlay_renderer.draw(camera_, kViewport, overlay);
  const auto pixels = target_->read_rgba();
  auto at = [&](const glm::dvec3& p) {
    const glm::ivec2 q = pixel_of(p);
    const size_t i = (size_t(q.y) * 256 + size_t(q.x)) * 4;
    return glm::ivec3(pixels[i], pixels[i + 1], pixels[i + 2]);
  };
  EXPECT_EQ(at({0.2, -0.5, 0.0}), glm::ivec3(255, 0, 0));
  // The point's centre is green (its rim is darkened).
  EXPECT_EQ(at({0.0, -0.5, 0.3}), glm::ivec3(0, 255, 0));
}

}  // namespace
}  // namespace meshedit
