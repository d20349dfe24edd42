// PNG files for screenshots, `meshedit render` and the render tests' references (through stb).
// Images are RGBA8, the top row first. Failures are RenderErrors naming the file.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace meshedit {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> rgba;  // width * height * 4 bytes
};

// The PNG file's bytes of the image (stb's encoder, deterministic: the same pixels give the same bytes). Throws
// RenderError if rgba is not width * height * 4 bytes.
std::string png_bytes(int width, int height, const std::vector<uint8_t>& rgba);
// Throws RenderError if rgba is not width * height * 4 bytes or the file cannot be written.
void write_png(const std::filesystem::path& path, int width, int height, const std::vector<uint8_t>& rgba);
// Reads any PNG as RGBA8; throws RenderError if the file is missing or not a PNG stb can read.
Image read_png(const std::filesystem::path& path);

}  // namespace meshedit
