// `meshedit render` end to end: the real binary, with no X server (DISPLAY unset), writes a PNG of the
// requested size that stb reads back, and refuses bad arguments with the usual exit statuses.
// Needs the `meshedit` target built (it is when the whole project is); skips where EGL is missing.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include <sys/wait.h>

#include <gtest/gtest.h>

#include "gl_test_support.h"
#include "render/image_file.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;

std::string quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

struct CommandResult {
  int status = -1;
  std::string out, err;
};

class RenderCommand : public testing::GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    if (IsSkipped()) return;
    ASSERT_TRUE(fs::exists(MESHEDIT_BINARY)) << MESHEDIT_BINARY << " is missing: build the meshedit target first";
    dir_ = testing::scratch_dir();
  }

  // Runs `meshedit render ARGS` with DISPLAY and WAYLAND_DISPLAY unset: no window system at all.
  CommandResult render(const std::vector<std::string>& args) {
    std::string command = "env -u DISPLAY -u WAYLAND_DISPLAY " + quoted(MESHEDIT_BINARY) + " render";
    for (const auto& a : args) command += " " + quoted(a);
    command += " >" + quoted((dir_ / "stdout").string()) + " 2>" + quoted((dir_ / "stderr").string());
    CommandResult run;
    const int raw = std::system(command.c_str());
    run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    run.out = testing::read_text(dir_ / "stdout");
    run.err = testing::read_text(dir_ / "stderr");
    return run;
  }

  fs::path dir_;
};

TEST_F(RenderCommand, TeapotWithoutADisplayWritesAPngOfTheRequestedSize) {
  const fs::path teapot = testing::source_dir() / "assets" / "teapot.bez";
  const fs::path out = dir_ / "teapot.png";
  const CommandResult run = render({teapot.string(), "--shading", "phong", "--size", "320x200", "-o", out.string()});
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.out.find("320x200"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("16256 triangles"), std::string::npos) << run.out;
  const Image image = read_png(out);
  EXPECT_EQ(image.width, 320);
  EXPECT_EQ(image.height, 200);
  // Not blank: the background in the corner, the teapot's shades in the middle.
  std::set<uint32_t> colours;
  for (size_t i = 0; i < image.rgba.size(); i += 4) {
    colours.insert(uint32_t(image.rgba[i]) << 16 | uint32_t(image.rgba[i + 1]) << 8 | image.rgba[i + 2]);
  }
  EXPECT_GT(colours.size(), 50u);
  const size_t centre = (100 * 320 + 160) * 4;
  EXPECT_GT(image.rgba[centre + 2], image.rgba[0 + 2] + 40) << "the teapot is not in the middle of the picture";
}

TEST_F(RenderCommand, FlatWireframeAndSubdivisionOfAPrimitive) {
  // A .obj written here: a tetrahedron, subdivided twice (4 -> 64 triangles).
  const fs::path tetra = dir_ / "tetra.obj";
  std::ofstream(tetra) << "v 1 1 1\nv -1 -1 1\nv -1 1 -1\nv 1 -1 -1\nf 1 3 2\nf 1 4 3\nf 1 2 4\nf 2 3 4\n";
  const fs::path out = dir_ / "tetra.png";
  const CommandResult run =
      render({tetra.string(), "--wireframe", "--subdivide", "2", "--size", "64x48", "-o", out.string()});
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.out.find("64 triangles"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("wireframe"), std::string::npos) << run.out;
  const Image image = read_png(out);
  EXPECT_EQ(image.width, 64);
  EXPECT_EQ(image.height, 48);
}

TEST_F(RenderCommand, BadArgumentsAreUsageErrorsAndBadFilesErrors) {
  const fs::path teapot = testing::source_dir() / "assets" / "teapot.bez";
  const std::string out = (dir_ / "x.png").string();
  for (const std::vector<std::string>& args : {std::vector<std::string>{teapot.string()},
                                               {teapot.string(), "-o", out, "--size", "0x10"},
                                               {teapot.string(), "-o", out, "--size", "12"},
                                               {teapot.string(), "-o", out, "--shading", "gouraud"},
                                               {teapot.string(), "-o", out, "--up", "x"},
                                               {teapot.string(), "-o", out, "--bogus"},
                                               {"-o", out}}) {
    const CommandResult run = render(args);
    EXPECT_EQ(run.status, 2) << run.err;
    EXPECT_NE(run.err.find("meshedit: "), std::string::npos);
    EXPECT_FALSE(fs::exists(out));
  }
  const CommandResult missing = render({(dir_ / "nowhere.obj").string(), "-o", out});
  EXPECT_EQ(missing.status, 1);
  EXPECT_NE(missing.err.find("nowhere.obj"), std::string::npos) << missing.err;
  const CommandResult curve = render({(testing::source_dir() / "assets" / "curve_cubic.bzc").string(), "-o", out});
  EXPECT_EQ(curve.status, 1);
  EXPECT_FALSE(fs::exists(out));
  const CommandResult unwritable =
      render({teapot.string(), "--size", "8x8", "-o", (dir_ / "no" / "such" / "dir.png").string()});
  EXPECT_EQ(unwritable.status, 1);
  EXPECT_NE(unwritable.err.find("dir.png"), std::string::npos) << unwritable.err;
}

}  // namespace
}  // namespace meshedit
