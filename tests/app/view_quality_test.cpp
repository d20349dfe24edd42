// ViewQuality (app/view_quality.h): which frames the governor hears, the starting guess by size, starting over on
// another document or a 2x size change, the user's wireframe choice, and the status bar's note. No GL.
#include <gtest/gtest.h>

#include <string>

#include "app/view_quality.h"

namespace meshedit {
namespace {

RenderStats closed_mesh(size_t triangles) {
  RenderStats stats;
  stats.triangles = triangles;
  stats.framebuffer_samples = 4;
  return stats;
}

// One window frame that draws the mesh, as EditorApp does it: the last frame's time, the mesh, the options drawn.
struct View {
  ViewQuality quality;
  ViewOptions options;  // the app's (W writes here)
  RenderStyle style;
  uint64_t generation = 1;
  RenderStats stats = closed_mesh(50000);

  ViewOptions frame(float last_frame_ms) {
    quality.frame_started(last_frame_ms);
    quality.follow_mesh(generation, stats.triangles, style, options);
    return quality.options_to_draw(options, stats);
  }
  // `count` frames, each told that the last one took `ms`; the options the last one drew with.
  ViewOptions frames(float ms, int count) {
    ViewOptions drawn;
    for (int i = 0; i < count; ++i) drawn = frame(ms);
    return drawn;
  }
};

TEST(ViewQuality, SlowFramesDropMultisamplingThenTheWireframeAndTheNoteSaysSo) {
  View view;
  ViewOptions drawn = view.frame(0.0f);
  EXPECT_TRUE(drawn.multisampling);
  EXPECT_TRUE(drawn.wireframe);
  EXPECT_TRUE(drawn.back_sides);
  EXPECT_EQ(view.quality.note(), "");

  drawn = view.frames(62.0f, 4);  // the first frame (the upload) is not counted, then three slow ones
  EXPECT_FALSE(drawn.multisampling);
  EXPECT_TRUE(drawn.wireframe);
  EXPECT_EQ(view.quality.note(), "frame 62 ms: multisampling off");

  drawn = view.frames(62.0f, 3);
  EXPECT_FALSE(drawn.wireframe);
  EXPECT_FALSE(view.options.wireframe);  // written into the app's options: W turns it back on
  EXPECT_EQ(view.quality.note(), "frame 62 ms: multisampling and wireframe off (W shows it)");

  drawn = view.frames(62.0f, 3);
  EXPECT_FALSE(drawn.back_sides);
  EXPECT_EQ(view.quality.note(), "frame 62 ms: multisampling, back sides and wireframe off (W shows it)");
  // Back sides and multisampling are dropped from the copy drawn only.
  EXPECT_TRUE(view.options.multisampling);
  EXPECT_TRUE(view.options.back_sides);
}

TEST(ViewQuality, HeldAtFullQualitySlowFramesAndALargeMeshDropNothingUntilLetGo) {
  View view;
  view.frame(0.0f);
  view.frames(62.0f, 7);
  ASSERT_FALSE(view.options.wireframe);  // dropped before the hold
  view.quality.hold_full(true, view.options);
  EXPECT_TRUE(view.options.wireframe);  // taken back at once
  EXPECT_EQ(view.quality.note(), "");
  ViewOptions drawn = view.frames(62.0f, 10);
  EXPECT_TRUE(drawn.multisampling);
  EXPECT_TRUE(drawn.wireframe);
  EXPECT_TRUE(drawn.back_sides);

  view.stats = closed_mesh(5000000);  // a mesh that would start cheap
  drawn = view.frames(62.0f, 3);
  EXPECT_TRUE(drawn.multisampling);
  EXPECT_TRUE(drawn.wireframe);
  EXPECT_EQ(view.quality.note(), "");

  view.quality.hold_full(false, view.options);
  drawn = view.frames(62.0f, 4);  // heard again: three slow frames drop a step
  EXPECT_FALSE(drawn.multisampling);
  EXPECT_EQ(view.quality.note(), "frame 62 ms: multisampling off");
}

TEST(ViewQuality, OnlyFramesThatDrewTheMeshAreHeard) {
  View view;
  view.frame(0.0f);
  // The curve or patch view: frame_started each frame, no mesh drawn. Their times are not the mesh's.
  for (int i = 0; i < 20; ++i) view.quality.frame_started(500.0f);
  EXPECT_EQ(view.quality.governor().level(), 0);
  // Back in the mesh view, the first frame's time is that of a curve frame: not counted either.
  const ViewOptions drawn = view.frames(10.0f, 20);
  EXPECT_TRUE(drawn.multisampling);
  EXPECT_EQ(view.quality.governor().level(), 0);
}

TEST(ViewQuality, ALargeMeshStartsCheapAndAnotherDocumentStartsOver) {
  View view;
  view.stats = closed_mesh(1000000);
  ViewOptions drawn = view.frame(0.0f);
  EXPECT_FALSE(drawn.multisampling);
  EXPECT_FALSE(drawn.wireframe);
  EXPECT_FALSE(drawn.back_sides);
  EXPECT_EQ(view.quality.note(), "large mesh: multisampling, back sides and wireframe off (W shows it)");
  // Slow, but nothing more to drop: it stays.
  drawn = view.frames(130.0f, 30);
  EXPECT_EQ(view.quality.governor().level(), kQualitySteps);

  // Another document, small: full quality from the start.
  ++view.generation;
  view.stats = closed_mesh(12);
  drawn = view.frame(130.0f);
  EXPECT_TRUE(drawn.multisampling);
  EXPECT_TRUE(drawn.wireframe);
  EXPECT_TRUE(view.options.wireframe);
  EXPECT_EQ(view.quality.note(), "");
}

TEST(ViewQuality, TheUsersWireframeWinsUntilAnotherDocument) {
  View view;
  view.frames(62.0f, 8);  // nothing to hear in the first frame, the upload's frame ignored, 3 frames per step
  ASSERT_FALSE(view.options.wireframe);
  view.options.wireframe = true;  // W
  ViewOptions drawn = view.frame(62.0f);
  EXPECT_TRUE(drawn.wireframe);
  EXPECT_TRUE(view.quality.wireframe_is_users());
  EXPECT_EQ(view.quality.note(), "frame 62 ms: multisampling off");
  // Still slow: the back sides go, the wireframe stays the user's.
  drawn = view.frames(62.0f, 3);
  EXPECT_TRUE(drawn.wireframe);
  EXPECT_FALSE(drawn.back_sides);
  EXPECT_EQ(view.quality.note(), "frame 62 ms: multisampling and back sides off");
  // Fast again: everything else comes back; the wireframe is still what the user said, off now.
  view.options.wireframe = false;  // W again
  drawn = view.frames(4.0f, 20);
  EXPECT_TRUE(drawn.multisampling);
  EXPECT_TRUE(drawn.back_sides);
  EXPECT_FALSE(drawn.wireframe);

  // A subdivision (4x the triangles) starts the governor over but keeps the user's choice.
  view.stats = closed_mesh(200000);
  drawn = view.frame(300.0f);
  EXPECT_FALSE(drawn.wireframe);
  EXPECT_TRUE(view.quality.wireframe_is_users());
  EXPECT_EQ(view.quality.governor().level(), kQualitySteps);
  EXPECT_EQ(view.quality.note(), "large mesh: multisampling and back sides off");

  // Another document forgets it.
  ++view.generation;
  view.stats = closed_mesh(100);
  drawn = view.frame(10.0f);
  EXPECT_FALSE(view.quality.wireframe_is_users());
  EXPECT_TRUE(drawn.wireframe);
}

TEST(ViewQuality, AnOpenMeshKeepsItsBackSidesAndNoSamplesMeansNoMultisamplingStep) {
  View view;
  view.stats.boundary_edges = 40;
  view.stats.framebuffer_samples = 0;
  ViewOptions drawn = view.frames(80.0f, 30);
  EXPECT_FALSE(drawn.wireframe);
  EXPECT_TRUE(drawn.back_sides);
  EXPECT_EQ(view.quality.note(), "frame 80 ms: wireframe off (W shows it)");
}

}  // namespace
}  // namespace meshedit
