// Which document changes the window plays and for how long (app/edit_animator.h), without a window: a flip, split or
// collapse by the key actions plays forward for a quarter second, its undo backward, any other change stops it, and
// nothing plays while the animator is off, not even later.
#include <gtest/gtest.h>

#include <limits>
#include <variant>

#include "app/edit_animator.h"
#include "core/mesh_build.h"
#include "document/document_actions.h"

namespace meshedit {
namespace {

constexpr double kFrame = 0.016;

// The flip lesson's diamond: e0 runs from a = v0 (-1, 0, 0) to b = v1 (1, 0, 0); c = v2 (0, 1, 0), d = v3 (0, -1, 0).
MeshDocument diamond_document() {
  PolygonMesh p;
  p.positions = {{-1, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
  p.add_face({0, 1, 2});
  p.add_face({1, 0, 3});
  return make_document(build_halfedge_mesh(p));
}

class EditAnimatorTest : public ::testing::Test {
 protected:
  void SetUp() override {
    animator_.set_enabled(true);
    animator_.follow(doc_);  // the first look only notes the document's state
  }
  // Frames of kFrame until the animation stops; how many it played (capped).
  int frames_until_stopped() {
    int frames = 0;
    while (animator_.playing() && frames < 1000) {
      animator_.advance(kFrame);
      animator_.follow(doc_);
      ++frames;
    }
    return frames;
  }

  MeshDocument doc_ = diamond_document();
  Selection selection_{ElementRef(EdgeId(0)), {}};
  EditAnimator animator_;
};

TEST_F(EditAnimatorTest, AFlipPlaysForwardForAQuarterSecondFromItsCorners) {
  EXPECT_FALSE(animator_.playing());
  ASSERT_TRUE(flip_selected(doc_, selection_).ok);
  animator_.follow(doc_);
  ASSERT_TRUE(animator_.playing());
  EXPECT_EQ(animator_.time(), 0.0);
  const EditAnimation& animation = *animator_.animation();
  EXPECT_EQ(animation.direction, PlayDirection::Forward);
  const FlipMotion& flip = std::get<FlipMotion>(animation.motion);
  EXPECT_EQ(flip.a, glm::dvec3(-1, 0, 0));
  EXPECT_EQ(flip.b, glm::dvec3(1, 0, 0));
  EXPECT_EQ(flip.c, glm::dvec3(0, 1, 0));
  EXPECT_EQ(flip.d, glm::dvec3(0, -1, 0));
  // The overlay at the start is the edge where it was, a-b.
  const Overlay start = animator_.overlay({});
  ASSERT_EQ(start.lines.size(), 1u);
  EXPECT_EQ(start.lines[0].points[0], glm::dvec3(-1, 0, 0));
  EXPECT_EQ(start.lines[0].points[1], glm::dvec3(1, 0, 0));
  for (const double step : {0.05, 0.05, 0.025}) animator_.advance(step);  // half of the quarter second
  EXPECT_NEAR(animator_.time(), 0.5, 1e-12);
  EXPECT_NEAR(animator_.overlay({}).lines[0].points[0].x, -0.5, 1e-12);
  // The rest: 0.125 s more in frames of 16 ms is 8 frames.
  EXPECT_EQ(frames_until_stopped(), 8);
  EXPECT_TRUE(animator_.overlay({}).lines.empty());
  // Seen once: following again does not replay it.
  animator_.follow(doc_);
  EXPECT_FALSE(animator_.playing());
}

TEST_F(EditAnimatorTest, AWholePlayLastsAQuarterSecondOfFrames) {
  ASSERT_TRUE(flip_selected(doc_, selection_).ok);
  animator_.follow(doc_);
  const int frames = frames_until_stopped();
  EXPECT_EQ(frames, 16);  // 15 frames of 16 ms are 0.24 s, 16 are 0.256 s
}

TEST_F(EditAnimatorTest, AnUndoPlaysBackwardAndARedoForward) {
  ASSERT_TRUE(split_selected(doc_, selection_).ok);
  animator_.follow(doc_);
  ASSERT_TRUE(animator_.playing());
  EXPECT_EQ(animator_.animation()->direction, PlayDirection::Forward);
  EXPECT_EQ(std::get<SplitMotion>(animator_.animation()->motion).m, glm::dvec3(0, 0, 0));
  ASSERT_TRUE(undo_edit(doc_, selection_));
  animator_.follow(doc_);
  ASSERT_TRUE(animator_.playing());
  EXPECT_EQ(animator_.time(), 0.0);  // the undo starts its own play
  EXPECT_EQ(animator_.animation()->direction, PlayDirection::Backward);
  const SplitMotion& split = std::get<SplitMotion>(animator_.animation()->motion);
  EXPECT_EQ(split.m, glm::dvec3(0, 0, 0));
  EXPECT_EQ(split.new_edge_ends.size(), 2u);
  // Backward at the start shows the split's result: the new vertex full size at m.
  const Overlay start = animator_.overlay({});
  ASSERT_EQ(start.points.size(), 1u);
  EXPECT_EQ(start.points[0].position, glm::dvec3(0, 0, 0));
  EXPECT_EQ(start.points[0].size, EditAnimationLook{}.point_size);
  ASSERT_TRUE(redo_edit(doc_, selection_));
  animator_.follow(doc_);
  ASSERT_TRUE(animator_.playing());
  EXPECT_EQ(animator_.animation()->direction, PlayDirection::Forward);
}

TEST_F(EditAnimatorTest, AnotherChangeStopsThePlay) {
  ASSERT_TRUE(flip_selected(doc_, selection_).ok);
  animator_.follow(doc_);
  ASSERT_TRUE(animator_.playing());
  ASSERT_TRUE(loop_subdivide_all(doc_, selection_).ok);
  animator_.follow(doc_);
  EXPECT_FALSE(animator_.playing());
  ASSERT_TRUE(undo_edit(doc_, selection_));
  animator_.follow(doc_);
  EXPECT_FALSE(animator_.playing());  // "undo Loop subdivision" is no flip
  // Replacing the mesh (opening a file) stops it too.
  selection_.selected = EdgeId(0);
  ASSERT_TRUE(flip_selected(doc_, selection_).ok);
  animator_.follow(doc_);
  ASSERT_TRUE(animator_.playing());
  replace_mesh(doc_, diamond_document().mesh, "");
  animator_.follow(doc_);
  EXPECT_FALSE(animator_.playing());
}

TEST_F(EditAnimatorTest, NothingPlaysWhileOffNorLater) {
  animator_.set_enabled(false);
  ASSERT_TRUE(flip_selected(doc_, selection_).ok);
  animator_.follow(doc_);
  EXPECT_FALSE(animator_.playing());
  animator_.set_enabled(true);
  animator_.follow(doc_);
  EXPECT_FALSE(animator_.playing());  // the flip made while off is not played now
  // Turning it off stops a play.
  ASSERT_TRUE(flip_selected(doc_, selection_).ok);
  animator_.follow(doc_);
  ASSERT_TRUE(animator_.playing());
  animator_.set_enabled(false);
  EXPECT_FALSE(animator_.playing());
  EXPECT_TRUE(animator_.overlay({}).lines.empty());
}

TEST_F(EditAnimatorTest, ASlowFrameMovesItOnlyOneStep) {
  ASSERT_TRUE(flip_selected(doc_, selection_).ok);
  animator_.follow(doc_);
  ASSERT_TRUE(animator_.playing());
  animator_.advance(3.0);  // a stall of three seconds
  EXPECT_TRUE(animator_.playing());
  EXPECT_NEAR(animator_.time(), EditAnimator::kMaxStepSeconds / kEditAnimationSeconds, 1e-12);
  animator_.advance(std::numeric_limits<double>::quiet_NaN());
  animator_.advance(-1.0);
  EXPECT_NEAR(animator_.time(), EditAnimator::kMaxStepSeconds / kEditAnimationSeconds, 1e-12);
}

}  // namespace
}  // namespace meshedit
