// The grader's pictures of a failed test (app/failure_pictures.h) show the element the student's function was given:
// the camera turns towards an element on the far side of the three-quarter view. Drawn by the built `meshedit grade`
// with EGL; skipped where no picture can be drawn.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "app/cli_test_support.h"
#include "core/palette.h"
#include "render/image_file.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;

// Pixels of the selection's colour (within a little of it) in the first third of the picture: the input's panel.
int selected_pixels_in_input(const Image& image) {
  const glm::vec3 selected = palette_for(Theme::Dark).selected * 255.0f;
  int count = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width / 3; ++x) {
      const uint8_t* p = &image.rgba[(size_t(y) * image.width + x) * 4];
      const bool near =
          std::abs(p[0] - selected.r) < 40 && std::abs(p[1] - selected.g) < 40 && std::abs(p[2] - selected.b) < 40;
      count += near ? 1 : 0;
    }
  }
  return count;
}

TEST(FailurePictures, AnEdgeOnTheFarSideOfTheThreeQuarterViewIsInSight) {
  // A flip that forgets the faces fails 4.2 first on e0 of the cube, the edge under its far bottom corner in the
  // three-quarter view, and 4.1 on e2 of two triangles in the plane, which that view sees from above.
  const fs::path dir = testing::scratch_dir();
  const fs::path grading = testing::source_dir() / "tests" / "grading";
  fs::create_directories(dir / "bob");
  fs::copy_file(grading / "students" / "flip_forgets_faces.lua", dir / "bob" / "flip.lua");
  const testing::CommandRun run =
      testing::run_meshedit({"grade", "--suite", (grading / "suites" / "flip.lua").string(), "--submission",
                             (dir / "bob").string(), "--results", (dir / "results.json").string()},
                            "failure-pictures");
  ASSERT_EQ(run.status, 0) << run.err;
  if (run.err.find("no pictures") != std::string::npos) GTEST_SKIP() << run.err;
  for (const char* test : {"test-4.1.png", "test-4.2.png"}) {
    SCOPED_TRACE(test);
    const Image picture = read_png(dir / "pictures" / test);
    ASSERT_GT(picture.width, 0);
    // The highlighted edge is a line across the panel, hundreds of pixels, not the few of its end points.
    EXPECT_GT(selected_pixels_in_input(picture), 300);
  }
}

}  // namespace
}  // namespace meshedit
