// The cube rendered offscreen (EGL, 256x256) against reference pictures, with a tolerance.
//
// The references in tests/render/references/ were made by this renderer and looked at by a person:
// the unit cube in the default Z-up three-quarter view, filling about 70% of the frame on the dark
// background, its front (-y), right (+x) and top (+z) sides in three shades of blue (flat); the same
// with a soft highlight and shading that runs across the sides (Phong from the area-weighted vertex
// normals, which on a cube lean towards the corners); and flat with every edge drawn in near-black,
// the triangles' diagonals included (wireframe).
// To regenerate them after an intended change of the look, run
//     MESHEDIT_UPDATE_REFERENCES=1 build/tests/render_tests --gtest_filter='CubeImage.*'
// then LOOK at each PNG before committing it.
#include <cstdlib>
#include <set>

#include <gtest/gtest.h>

#include "core/mesh_build.h"
#include "core/primitives.h"
#include "gl_test_support.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

// Mean absolute difference per channel (0-255) must stay below this; and few pixels may differ a lot.
constexpr double kMeanTolerance = 1.5;
constexpr double kStrongDifferenceFraction = 0.005;  // of pixels differing by more than 64 in a channel
constexpr size_t kMinDistinctColours = 6;

struct Difference {
  double mean = 0.0;
  double strong_fraction = 0.0;
};

Difference compare(const Image& a, const Image& b) {
  Difference out;
  size_t strong = 0;
  double sum = 0.0;
  for (size_t i = 0; i < a.rgba.size(); i += 4) {
    bool big = false;
    for (size_t c = 0; c < 4; ++c) {
      const int delta = std::abs(int(a.rgba[i + c]) - int(b.rgba[i + c]));
      sum += delta;
      big = big || delta > 64;
    }
    strong += big ? 1 : 0;
  }
  out.mean = sum / double(a.rgba.size());
  out.strong_fraction = double(strong) / double(a.rgba.size() / 4);
  return out;
}

size_t distinct_colours(const Image& image) {
  std::set<uint32_t> colours;
  for (size_t i = 0; i < image.rgba.size(); i += 4) {
    colours.insert(uint32_t(image.rgba[i]) << 16 | uint32_t(image.rgba[i + 1]) << 8 | image.rgba[i + 2]);
  }
  return colours.size();
}

class CubeImage : public testing::GlTest {
 protected:
  Image render_cube(const ViewOptions& options) {
    const ShaderLibrary shaders;
    MeshRenderer renderer(shaders);
    const HalfedgeMesh mesh = build_halfedge_mesh(make_cube());
    renderer.update(mesh);
    OrbitCamera camera;
    camera.fit(renderer.bounds());
    return render(renderer, mesh, camera, options, {});
  }

  void expect_matches_reference(const Image& image, const std::string& name) {
    const auto path = testing::source_dir() / "tests" / "render" / "references" / (name + ".png");
    ASSERT_GE(distinct_colours(image), kMinDistinctColours) << "the rendered image is (nearly) blank";
    if (std::getenv("MESHEDIT_UPDATE_REFERENCES") != nullptr) {
      write_png(path, image.width, image.height, image.rgba);
      GTEST_SKIP() << "wrote " << path << "; look at it before committing";
    }
    const Image reference = read_png(path);
    ASSERT_EQ(reference.width, image.width);
    ASSERT_EQ(reference.height, image.height);
    const Difference diff = compare(image, reference);
    EXPECT_LT(diff.mean, kMeanTolerance) << name;
    EXPECT_LT(diff.strong_fraction, kStrongDifferenceFraction) << name;
  }
};

TEST_F(CubeImage, Flat) {
  ViewOptions options;
  options.wireframe = false;
  expect_matches_reference(render_cube(options), "cube_flat");
}

TEST_F(CubeImage, Phong) {
  ViewOptions options;
  options.wireframe = false;
  options.smooth_shading = true;
  expect_matches_reference(render_cube(options), "cube_phong");
}

TEST_F(CubeImage, Wireframe) {
  ViewOptions options;
  options.wireframe = true;
  expect_matches_reference(render_cube(options), "cube_wireframe");
}

TEST_F(CubeImage, TheComparisonTellsTheViewsApart) {
  ViewOptions flat;
  flat.wireframe = false;
  ViewOptions phong = flat;
  phong.smooth_shading = true;
  ViewOptions wire = flat;
  wire.wireframe = true;
  const Image a = render_cube(flat), b = render_cube(phong), c = render_cube(wire);
  for (const auto& [x, y] : {std::pair{&a, &b}, std::pair{&a, &c}, std::pair{&b, &c}}) {
    const Difference diff = compare(*x, *y);
    EXPECT_TRUE(diff.mean >= kMeanTolerance || diff.strong_fraction >= kStrongDifferenceFraction);
  }
  // And the same view twice is the same picture.
  const Difference same = compare(a, render_cube(flat));
  EXPECT_EQ(same.mean, 0.0);
}

}  // namespace
}  // namespace meshedit
