// PNG reading and writing with stb (see image_file.h). The file itself is read and written here, not
// by stb, so errors can name the path and the reason.
#include "render/image_file.h"

#include <fstream>
#include <string>

#include <stb_image.h>
#include <stb_image_write.h>

#include "core/file_bytes.h"
#include "render/render_error.h"

namespace meshedit {
namespace {

void append_bytes(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<uint8_t>*>(context);
  const auto* bytes = static_cast<const uint8_t*>(data);
  out->insert(out->end(), bytes, bytes + size);
}

}  // namespace

std::string png_bytes(int width, int height, const std::vector<uint8_t>& rgba) {
  if (width < 1 || height < 1 || rgba.size() != size_t(width) * size_t(height) * 4) {
    throw RenderError("the image is not " + std::to_string(width) + "x" + std::to_string(height) + " RGBA pixels");
  }
  std::vector<uint8_t> png;
  if (!stbi_write_png_to_func(append_bytes, &png, width, height, 4, rgba.data(), width * 4) || png.empty()) {
    throw RenderError("PNG encoding failed");
  }
  return std::string(png.begin(), png.end());
}

void write_png(const std::filesystem::path& path, int width, int height, const std::vector<uint8_t>& rgba) {
  std::string png;
  try {
    png = png_bytes(width, height, rgba);
  } catch (const RenderError& e) {
    throw RenderError("cannot write " + path.string() + ": " + e.what());
  }
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(png.data(), std::streamsize(png.size()));
  out.close();
  if (!out) throw RenderError("cannot write " + path.string() + ": the file cannot be created or written");
}

Image read_png(const std::filesystem::path& path) {
  const FileBytes file = read_file_bytes(path);
  if (!file.ok()) throw RenderError("cannot read " + path.string() + ": no such file or not readable");
  int width = 0, height = 0, channels = 0;
  stbi_uc* pixels = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(file.bytes.data()), int(file.bytes.size()),
                                          &width, &height, &channels, 4);
  if (pixels == nullptr) {
    const char* reason = stbi_failure_reason();
    throw RenderError("cannot read " + path.string() + ": " + (reason ? reason : "not an image"));
  }
  Image image;
  image.width = width;
  image.height = height;
  image.rgba.assign(pixels, pixels + size_t(width) * size_t(height) * 4);
  stbi_image_free(pixels);
  return image;
}

}  // namespace meshedit
