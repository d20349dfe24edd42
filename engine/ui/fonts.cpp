// The window's fonts (see fonts.h).
#include "ui/fonts.h"

#include <imgui.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <system_error>

#include "core/data_folders.h"
#include "core/file_bytes.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;

// The font file's bytes in memory ImGui owns (the atlas frees them), or null when it cannot be read or is not a
// TrueType file: ImGui asserts on a file it cannot open or parse, so it is only handed one that opened.
ImFont* add_font(ImFontAtlas& atlas, const fs::path& path, float pixels, ImFontConfig config) {
  const FileBytes file = read_file_bytes(path);
  const std::string& bytes = file.bytes;
  const bool truetype =
      bytes.size() > 12 && (bytes.compare(0, 4, std::string("\0\1\0\0", 4)) == 0 || bytes.compare(0, 4, "true") == 0);
  if (!file.ok() || !truetype) return nullptr;
  void* data = ImGui::MemAlloc(bytes.size());
  std::memcpy(data, bytes.data(), bytes.size());
  return atlas.AddFontFromMemoryTTF(data, int(bytes.size()), pixels, &config);
}

}  // namespace

fs::path font_folder() {
  if (const char* dir = std::getenv("MESHEDIT_FONT_DIR"); dir && *dir) return dir;
  for (const fs::path& dir : data_folder_candidates("fonts")) {
    std::error_code ec;
    if (fs::is_regular_file(dir / "DejaVuSans.ttf", ec)) return dir;
  }
  return "/usr/share/fonts/truetype/dejavu";
}

FontsLoaded load_fonts(float font_px, float scale, float raster_scale) {
  ImGuiIO& io = ImGui::GetIO();
  ImFontAtlas& atlas = *io.Fonts;
  atlas.Clear();
  FontsLoaded out;
  const float raster = std::max(1.0f, raster_scale);
  out.pixels = font_px * std::max(0.5f, scale) * raster;
  io.FontGlobalScale = 1.0f / raster;

  const fs::path dir = font_folder();
  const fs::path text = dir / "DejaVuSans.ttf", mono = dir / "DejaVuSansMono.ttf";
  ImFontConfig config;
  config.OversampleH = 2;
  ImFont* text_font = add_font(atlas, text, out.pixels, config);
  if (!text_font) {
    ImFontConfig fallback;
    fallback.SizePixels = out.pixels;  // ImGui's pixel font, scaled: blurry but the size asked for
    atlas.AddFontDefault(&fallback);
    out.warning = "no " + text.string() + " (install fonts-dejavu-core): using ImGui's built-in font";
    return out;
  }
  if (!add_font(atlas, mono, out.pixels, config))
    out.warning = "no " + mono.string() + " (install fonts-dejavu-core): ids use the text font";
  out.real = true;
  return out;
}

ImFont* mono_font() {
  const ImFontAtlas& atlas = *ImGui::GetIO().Fonts;
  if (atlas.Fonts.Size > 1) return atlas.Fonts[1];
  return atlas.Fonts.Size > 0 ? atlas.Fonts[0] : ImGui::GetFont();
}

}  // namespace meshedit
