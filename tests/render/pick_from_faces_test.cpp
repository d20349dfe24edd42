// pick_from_faces without GL: the face-id window around the cursor is made by exact ray casts through each pixel
// (what a faces-only id pass would hold), on the cube in the default three-quarter view at 256x256.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core/mesh_build.h"
#include "core/primitives.h"
#include "ray_cast.h"
#include "render/mesh_geometry.h"
#include "render/pick_from_faces.h"
#include "render/pick_id.h"

namespace meshedit {
namespace {

constexpr Viewport kViewport{256, 256};

class PickFromFaces : public ::testing::Test {
 protected:
  void SetUp() override {
    mesh_ = build_halfedge_mesh(make_cube());
    camera_.fit(mesh_bounds(mesh_));
  }

  // The window a faces-only pass would read around (x, y): the ray casts' faces.
  struct Window {
    std::vector<uint32_t> ids;
    int left, top, width, height;
  };
  Window window_at(int x, int y) const {
    Window w;
    w.left = std::max(0, x - kVertexPickRadius);
    w.top = std::max(0, y - kVertexPickRadius);
    const int right = std::min(kViewport.width - 1, x + kVertexPickRadius);
    const int bottom = std::min(kViewport.height - 1, y + kVertexPickRadius);
    w.width = right - w.left + 1;
    w.height = bottom - w.top + 1;
    for (int row = w.top; row <= bottom; ++row) {
      for (int column = w.left; column <= right; ++column) {
        w.ids.push_back(encode_pick_id(testing::cast(mesh_, camera_, kViewport, column, row)));
      }
    }
    return w;
  }
  ElementRef pick_in(const Window& w, int x, int y, bool halfedges = false) const {
    return pick_from_faces(mesh_, camera_, kViewport, PickWindow{w.ids, w.width, w.height, w.left, w.top}, x, y,
                           halfedges);
  }
  ElementRef pick(int x, int y, bool halfedges = false) const { return pick_in(window_at(x, y), x, y, halfedges); }

  glm::ivec2 pixel_of(const glm::dvec3& p) const {
    const ScreenPoint s = camera_.project(p, kViewport);
    return {int(std::floor(s.pixel.x)), int(std::floor(s.pixel.y))};
  }

  HalfedgeMesh mesh_;
  OrbitCamera camera_;
};

TEST_F(PickFromFaces, TheNearestCornerWithinReach) {
  // v5 = (+0.5, -0.5, +0.5), the corner nearest the eye.
  const glm::ivec2 p = pixel_of(mesh_.position(VertexId(5)));
  EXPECT_EQ(pick(p.x, p.y), ElementRef(VertexId(5)));
  EXPECT_EQ(pick(p.x + 3, p.y + 3), ElementRef(VertexId(5)));  // 4.9 pixels: within kVertexPickRadius
  EXPECT_NE(pick(p.x + 6, p.y + 6), ElementRef(VertexId(5)));  // 8.5 pixels: not
}

TEST_F(PickFromFaces, AnEdgeNearItsMidpointAndNotAHiddenOne) {
  const EdgeId top_front = testing::edge_between(mesh_, VertexId(4), VertexId(5));
  const glm::ivec2 p = pixel_of((mesh_.position(VertexId(4)) + mesh_.position(VertexId(5))) * 0.5);
  EXPECT_EQ(pick(p.x, p.y), ElementRef(top_front));
  EXPECT_EQ(pick(p.x, p.y + 3), ElementRef(top_front));  // a few pixels below, on the front side
  // v2-v6 lies behind the cube: its image is covered by front faces, whose own elements are all it can give.
  const EdgeId hidden = testing::edge_between(mesh_, VertexId(2), VertexId(6));
  const glm::ivec2 q = pixel_of((mesh_.position(VertexId(2)) + mesh_.position(VertexId(6))) * 0.5);
  EXPECT_NE(pick(q.x, q.y), ElementRef(hidden));
}

TEST_F(PickFromFaces, FacesAwayFromTheirSidesAreTheRayCastsFace) {
  int checked = 0;
  for (int y = 20; y < 256; y += 24) {
    for (int x = 20; x < 256; x += 24) {
      const ElementRef picked = pick(x, y);
      if (picked.kind != ElementKind::Face) continue;  // background, or near a side or corner
      EXPECT_EQ(picked, testing::cast(mesh_, camera_, kViewport, x, y)) << x << "," << y;
      ++checked;
    }
  }
  EXPECT_GE(checked, 30);
  EXPECT_FALSE(pick(2, 2).valid());  // background all around
}

TEST_F(PickFromFaces, ShownArrowsWinOverTheirFaceAndSide) {
  int checked = 0;
  for (HalfedgeId h : mesh_.halfedges()) {
    const auto arrow = halfedge_arrow(mesh_, h);
    ASSERT_TRUE(arrow.has_value());
    const glm::dvec3 middle = (glm::dvec3(arrow->tail) + glm::dvec3(arrow->tip)) * 0.5;
    const glm::ivec2 p = pixel_of(middle);
    // Only where a ray cast sees the arrow's own face is it visible.
    if (testing::cast(mesh_, camera_, kViewport, p.x, p.y) != ElementRef(mesh_.face(h))) continue;
    EXPECT_EQ(pick(p.x, p.y, true), ElementRef(h)) << format_id(h);
    EXPECT_NE(pick(p.x, p.y, false).kind, ElementKind::Halfedge);
    ++checked;
  }
  EXPECT_EQ(checked, 18);  // three sides of two triangles of three halfedges
}

TEST_F(PickFromFaces, ABrokenFaceGivesNoCandidatesAndNoStrayRead) {
  // The window still names f0, but its cycle now leaves the arrays: its corners and sides are not offered, and
  // nothing outside the mesh is read.
  const glm::ivec2 p = pixel_of(mesh_.position(VertexId(5)));
  const Window window = window_at(p.x, p.y);
  EXPECT_EQ(pick_in(window, p.x, p.y), ElementRef(VertexId(5)));
  for (HalfedgeId h : mesh_.halfedges()) mesh_.set_next(h, HalfedgeId(999999));
  const ElementRef after = pick_in(window, p.x, p.y);  // every face broken: only the window's faces are left
  EXPECT_EQ(after.kind, ElementKind::Face) << format_id(after);
}

}  // namespace
}  // namespace meshedit
