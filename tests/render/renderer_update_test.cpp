// MeshRenderer::update on the GPU: edits described by a MeshChange are patched in place (the buffers read back
// equal a full build of the new state, byte for byte, after every step of a run of flips, splits, collapses, undos
// and redos, with the arrows shown); a flip on a big mesh sends a few kilobytes; an idle frame and a camera orbit
// upload nothing, rebuild nothing and redraw no id buffer.
#include <algorithm>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "core/history.h"
#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/primitives.h"
#include "gl_test_support.h"
#include "quad_torus.h"
#include "update_test_support.h"

namespace meshedit {
namespace {

using testing::changed_elements;
using testing::GlTest;
using testing::same_bytes;

// Updates `renderer` from `before` to `mesh` with a change description, as the app does.
void update_with_change(MeshRenderer& renderer, const HalfedgeMesh& before, const HalfedgeMesh& mesh) {
  const std::vector<ElementRef> elements = changed_elements(before, mesh);
  MeshRenderer::MeshChange change;
  change.before = &before;
  change.elements = elements;
  change.version_before = before.version();
  change.version_after = mesh.version();
  renderer.update(mesh, &change);
}

void expect_buffers_equal_full_build(const MeshRenderer& renderer, const HalfedgeMesh& mesh, bool arrows) {
  SlotGeometry gpu;
  std::vector<EdgeSegment> gpu_arrows;
  renderer.read_gpu_buffers(gpu, gpu_arrows);
  const SlotGeometry full = build_slot_geometry(mesh);
  testing::expect_same_slots(gpu, full);
  if (arrows) {
    EXPECT_TRUE(same_bytes(gpu_arrows, build_slot_arrows(mesh)));
  }
}

class RendererUpdate : public GlTest {
 protected:
  static constexpr Viewport kViewport{160, 120};
};

TEST_F(RendererUpdate, EditsUndoAndRedoArePatchedAndEqualAFullBuild) {
  MeshRenderer renderer{ShaderLibrary()};
  HalfedgeMesh mesh = build_halfedge_mesh(make_grid(10, 8));
  renderer.update(mesh);
  OrbitCamera camera;
  camera.fit(renderer.bounds());
  ViewOptions options;
  options.show_halfedges = true;  // the arrows are patched too
  RenderTarget target(kViewport.width, kViewport.height, 0);
  renderer.draw(camera, kViewport, options, {});
  History history(64);
  std::mt19937 rng(7);
  int outgrown = 0;
  for (int step = 0; step < 150; ++step) {
    const HalfedgeMesh before = mesh;
    const EdgeId e(uint32_t(rng() % mesh.edge_capacity()));
    switch (rng() % 6) {
      case 0:
      case 1:
        if (flip(mesh, e)) history.record("flip", before);
        break;
      case 2:
        if (split(mesh, e)) history.record("split", before);
        break;
      case 3:
        if (collapse(mesh, e)) history.record("collapse", before);
        break;
      case 4: history.undo(mesh); break;
      default: history.redo(mesh); break;
    }
    if (mesh.version() == before.version()) continue;
    const RenderStats was = renderer.stats();
    update_with_change(renderer, before, mesh);
    renderer.draw(camera, kViewport, options, {});
    SCOPED_TRACE("step " + std::to_string(step));
    if (renderer.stats().uploads != was.uploads) {
      // Splits use up the room kept at the end now and then (an eighth of the mesh): then it is a rebuild.
      EXPECT_EQ(renderer.stats().last_rebuild_reason, "the mesh outgrew its buffers");
      ++outgrown;
    } else {
      EXPECT_EQ(renderer.stats().patches, was.patches + 1);
    }
    expect_buffers_equal_full_build(renderer, mesh, true);
    if (HasFailure()) return;
  }
  EXPECT_LE(outgrown, 3);
  EXPECT_GT(renderer.stats().patches, 80u);
}

TEST_F(RendererUpdate, MovedVerticesOfQuadsArePatchedTheirPackedTrianglesToo) {
  MeshRenderer renderer{ShaderLibrary()};
  HalfedgeMesh mesh = build_halfedge_mesh(quad_torus(12, 8));
  renderer.update(mesh);
  std::mt19937 rng(3);
  for (int step = 0; step < 30; ++step) {
    const HalfedgeMesh before = mesh;
    const VertexId v(uint32_t(rng() % mesh.vertex_capacity()));
    mesh.set_position(v, mesh.position(v) * 1.1);
    update_with_change(renderer, before, mesh);
  }
  EXPECT_EQ(renderer.stats().uploads, 1u);
  EXPECT_EQ(renderer.stats().patches, 30u);
  expect_buffers_equal_full_build(renderer, mesh, false);
}

TEST_F(RendererUpdate, AFlipOnABigMeshSendsBytesForTheEditNotTheMesh) {
  MeshRenderer renderer{ShaderLibrary()};
  HalfedgeMesh mesh = build_halfedge_mesh(make_torus_with_faces(200000));
  renderer.update(mesh);
  const size_t full_bytes = renderer.stats().last_update_bytes;
  EXPECT_GT(full_bytes, 10000000u);
  for (uint32_t e : {100u, 150000u, 299000u}) {
    const HalfedgeMesh before = mesh;
    ASSERT_TRUE(flip(mesh, EdgeId(e)));
    update_with_change(renderer, before, mesh);
    EXPECT_EQ(renderer.stats().uploads, 1u);
    EXPECT_LT(renderer.stats().last_update_bytes, 4096u);
    EXPECT_LT(renderer.stats().last_update_slots, 40u);
  }
  const HalfedgeMesh before = mesh;
  ASSERT_TRUE(split(mesh, EdgeId(5000)));  // new elements go into the room kept at the end
  update_with_change(renderer, before, mesh);
  EXPECT_EQ(renderer.stats().uploads, 1u);
  EXPECT_LT(renderer.stats().last_update_bytes, 4096u);
  expect_buffers_equal_full_build(renderer, mesh, false);
}

TEST_F(RendererUpdate, WithoutAChangeOrFromAnotherStateItRebuilds) {
  MeshRenderer renderer{ShaderLibrary()};
  HalfedgeMesh mesh = build_halfedge_mesh(make_torus(8, 6));
  renderer.update(mesh);
  HalfedgeMesh before = mesh;
  ASSERT_TRUE(flip(mesh, EdgeId(3)));
  renderer.update(mesh);  // no description
  EXPECT_EQ(renderer.stats().uploads, 2u);
  EXPECT_EQ(renderer.stats().last_rebuild_reason, "no change description");
  before = mesh;
  ASSERT_TRUE(flip(mesh, EdgeId(4)));
  const HalfedgeMesh middle = mesh;
  ASSERT_TRUE(flip(mesh, EdgeId(5)));
  update_with_change(renderer, middle, mesh);  // describes a step from a state the renderer never showed
  EXPECT_EQ(renderer.stats().uploads, 3u);
  EXPECT_EQ(renderer.stats().patches, 0u);
  expect_buffers_equal_full_build(renderer, mesh, false);
}

// A mesh past the buffer cap is refused before the slot build (no upload is counted), with a message that gives the
// texels needed and allowed; the old picture is not drawn for it and nothing is picked; a mesh that fits is drawn
// again.
TEST_F(RendererUpdate, AMeshTooLargeToDrawIsRefusedAndNothingIsDrawn) {
  MeshRenderer renderer{ShaderLibrary()};
  const HalfedgeMesh small = build_halfedge_mesh(make_torus(8, 6));  // 288 halfedge slots
  renderer.update(small);
  OrbitCamera camera;
  camera.fit(renderer.bounds());
  const HalfedgeMesh big = build_halfedge_mesh(make_torus(30, 20));  // 3600 halfedge slots
  renderer.style().max_buffer_texels = 2000;
  try {
    renderer.update(big);
    ADD_FAILURE() << "no refusal";
  } catch (const RenderError& e) {
    EXPECT_NE(std::string(e.what()).find("too large to draw"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("allows 2000"), std::string::npos) << e.what();
  }
  EXPECT_EQ(renderer.stats().refusals, 1u);
  EXPECT_EQ(renderer.stats().uploads, 1u);
  RenderTarget target(kViewport.width, kViewport.height, 0);
  target.clear(renderer.style().background);
  renderer.draw(camera, kViewport, {}, {});
  const std::vector<uint8_t> pixels = target.read_rgba();
  const auto background = [&](size_t i) { return pixels[i] == uint8_t(renderer.style().background.r * 255.0f + 0.5f); };
  for (size_t i = 0; i < pixels.size(); i += 4 * 37) EXPECT_TRUE(background(i)) << "pixel " << i / 4;
  EXPECT_FALSE(renderer.pick(camera, kViewport, 80, 60).valid());

  renderer.update(small);
  EXPECT_EQ(renderer.stats().uploads, 2u);
  expect_buffers_equal_full_build(renderer, small, false);
}

TEST_F(RendererUpdate, IdleFramesAndOrbitsDoNoPerElementWork) {
  MeshRenderer renderer{ShaderLibrary()};
  HalfedgeMesh mesh = build_halfedge_mesh(make_torus_with_faces(20000));
  renderer.update(mesh);
  OrbitCamera camera;
  camera.fit(renderer.bounds());
  const std::vector<ElementRef> changed = {ElementRef(FaceId::face(1)), ElementRef(EdgeId(4))};
  Highlights highlights;
  highlights.changed = changed;
  highlights.changed_key = 42;
  RenderTarget target(kViewport.width, kViewport.height, 0);
  renderer.draw(camera, kViewport, {}, highlights);
  renderer.pick(camera, kViewport, 80, 60);
  EXPECT_TRUE(renderer.pick_is_cheap(camera, kViewport));
  const RenderStats settled = renderer.stats();
  const size_t sent = settled.last_update_bytes;
  for (int frame = 0; frame < 20; ++frame) {
    camera.orbit(4.0, 1.0);  // a drag: the app neither picks nor hovers meanwhile
    renderer.update(mesh);
    renderer.draw(camera, kViewport, {}, highlights);
  }
  for (int frame = 0; frame < 20; ++frame) {  // idle
    renderer.update(mesh);
    renderer.draw(camera, kViewport, {}, highlights);
  }
  const RenderStats& now = renderer.stats();
  EXPECT_EQ(now.uploads, settled.uploads);
  EXPECT_EQ(now.patches, settled.patches);
  EXPECT_EQ(now.highlight_uploads, settled.highlight_uploads);
  EXPECT_EQ(now.arrow_uploads, settled.arrow_uploads);
  EXPECT_EQ(now.id_passes, settled.id_passes);
  EXPECT_EQ(now.last_update_bytes, sent);
  // The camera moved: the next pick would redraw the id buffer, and says so beforehand.
  EXPECT_FALSE(renderer.pick_is_cheap(camera, kViewport));
  renderer.pick(camera, kViewport, 80, 60);
  EXPECT_EQ(renderer.stats().id_passes, settled.id_passes + 1);
  EXPECT_TRUE(renderer.pick_is_cheap(camera, kViewport));
}

}  // namespace
}  // namespace meshedit
