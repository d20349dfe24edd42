// PNG files through stb: a round trip keeps every byte, and failures name the file.
#include <fstream>

#include <gtest/gtest.h>

#include "render/image_file.h"
#include "render/render_error.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

TEST(ImageFile, RoundTripKeepsEveryPixelAndTheRowOrder) {
  const auto path = testing::scratch_dir() / "image.png";
  std::vector<uint8_t> rgba(3 * 2 * 4);
  for (size_t i = 0; i < rgba.size(); ++i) rgba[i] = uint8_t(i * 11);
  write_png(path, 3, 2, rgba);
  const Image image = read_png(path);
  EXPECT_EQ(image.width, 3);
  EXPECT_EQ(image.height, 2);
  EXPECT_EQ(image.rgba, rgba);
}

TEST(ImageFile, FailuresNameTheFile) {
  const auto dir = testing::scratch_dir();
  try {
    write_png(dir / "short.png", 4, 4, std::vector<uint8_t>(10));
    FAIL() << "a buffer of the wrong size was written";
  } catch (const RenderError& e) {
    EXPECT_NE(std::string(e.what()).find("short.png"), std::string::npos) << e.what();
  }
  try {
    write_png(dir / "missing" / "dir.png", 1, 1, std::vector<uint8_t>(4));
    FAIL() << "wrote into a directory that does not exist";
  } catch (const RenderError& e) {
    EXPECT_NE(std::string(e.what()).find("dir.png"), std::string::npos) << e.what();
  }
  try {
    read_png(dir / "none.png");
    FAIL() << "read a file that does not exist";
  } catch (const RenderError& e) {
    EXPECT_NE(std::string(e.what()).find("none.png"), std::string::npos) << e.what();
  }
  std::ofstream(dir / "text.png") << "not a png at all";
  try {
    read_png(dir / "text.png");
    FAIL() << "read text as an image";
  } catch (const RenderError& e) {
    EXPECT_NE(std::string(e.what()).find("text.png"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace meshedit
