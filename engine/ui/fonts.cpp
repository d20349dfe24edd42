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
#include "core/text_breaks.h"
#include "core/translation.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;

// The font file's bytes in memory ImGui owns (the atlas frees them), or null when it cannot be read or is not a
// TrueType file: ImGui asserts on a file it cannot open or parse, so it is only handed one that opened.
ImFont* add_font(ImFontAtlas& atlas, const fs::path& path, float pixels, ImFontConfig config) {
  const FileBytes file = read_file_bytes(path);
  const std::string& bytes = file.bytes;
  const bool truetype = bytes.size() > 12 && (bytes.compare(0, 4, std::string("\0\1\0\0", 4)) == 0 ||
                                              bytes.compare(0, 4, "true") == 0 || bytes.compare(0, 4, "ttcf") == 0);
  if (!file.ok() || !truetype) return nullptr;
  void* data = ImGui::MemAlloc(bytes.size());
  std::memcpy(data, bytes.data(), bytes.size());
  return atlas.AddFontFromMemoryTTF(data, int(bytes.size()), pixels, &config);
}

// Wide characters the texts shown needed beyond the shipped ones (fonts_cover), added at the next load.
std::string& extra_wide_text() {
  static std::string text;
  return text;
}

// Every wide character (core/text_breaks.h) of the window's catalog in `language` and of the shipped lessons, with
// CJK punctuation and full-width forms: the glyphs the Chinese font adds to the atlas. Static: ImGui reads the ranges
// when it builds the atlas, after load_fonts returns.
const ImWchar* wide_glyph_ranges(Language language) {
  static ImVector<ImWchar> ranges;
  ImFontGlyphRangesBuilder builder;
  static const ImWchar kPunctuation[] = {0x3000, 0x303F, 0xFF00, 0xFFEF, 0x2010, 0x2027, 0};
  builder.AddRanges(kPunctuation);
  std::string text = catalog_of(language).all_translations() + extra_wide_text();
  std::error_code ec;
  for (fs::directory_iterator it(data_folder("lessons"), ec), end; !ec && it != end; it.increment(ec)) {
    if (it->path().extension() == ".lua") text += read_file_bytes(it->path()).bytes;
  }
  for (size_t i = 0; i < text.size();) {
    size_t n = 1;
    const char32_t c = utf8_at(text, i, &n);
    if (wide_char(c) && c <= 0xFFFF) builder.AddChar(ImWchar(c));
    i += n;
  }
  ranges.clear();
  builder.BuildRanges(&ranges);
  return ranges.Data;
}

// The first of the Chinese font files that exists: beside the DejaVu files (the page's cut-down copy, or an
// installed one), else Debian's fonts-wqy-microhei.
fs::path wide_font_file() {
  std::error_code ec;
  for (const char* name : {"WenQuanYiMicroHei.ttf", "wqy-microhei.ttc"}) {
    if (const fs::path beside = font_folder() / name; fs::is_regular_file(beside, ec)) return beside;
  }
  const char* dir = std::getenv("MESHEDIT_FONT_DIR");
  if (dir && *dir) return font_folder() / "WenQuanYiMicroHei.ttf";  // that folder only (the tests)
  return "/usr/share/fonts/truetype/wqy/wqy-microhei.ttc";
}

// Merges the Chinese glyphs into the last font added; a warning when the font file is missing.
std::string merge_wide_glyphs(ImFontAtlas& atlas, float pixels, const ImWchar* ranges) {
  ImFontConfig config;
  config.MergeMode = true;
  config.OversampleH = 1;
  config.PixelSnapH = true;
  config.GlyphRanges = ranges;
  const fs::path file = wide_font_file();
  if (add_font(atlas, file, pixels, config)) return "";
  return "no " + file.string() + " (install fonts-wqy-microhei): Chinese text cannot be drawn and shows as '?'";
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
  const Language language = text_language();
  const ImWchar* wide = language == Language::English ? nullptr : wide_glyph_ranges(language);
  if (wide) out.warning = merge_wide_glyphs(atlas, out.pixels, wide);
  if (!add_font(atlas, mono, out.pixels, config)) {
    out.warning = "no " + mono.string() + " (install fonts-dejavu-core): ids use the text font";
  } else if (wide && out.warning.empty()) {
    out.warning = merge_wide_glyphs(atlas, out.pixels, wide);
  }
  out.real = true;
  return out;
}

bool fonts_cover(const std::string& text) {
  const ImFontAtlas& atlas = *ImGui::GetIO().Fonts;
  if (atlas.Fonts.Size == 0) return true;
  const ImFont& font = *atlas.Fonts[0];
  bool all = true;
  for (size_t i = 0; i < text.size();) {
    size_t n = 1;
    const char32_t c = utf8_at(text, i, &n);
    if (wide_char(c) && c <= 0xFFFF && !font.FindGlyphNoFallback(ImWchar(c))) {
      extra_wide_text().append(text, i, n);
      all = false;
    }
    i += n;
  }
  return all;
}

ImFont* mono_font() {
  const ImFontAtlas& atlas = *ImGui::GetIO().Fonts;
  if (atlas.Fonts.Size > 1) return atlas.Fonts[1];
  return atlas.Fonts.Size > 0 ? atlas.Fonts[0] : ImGui::GetFont();
}

}  // namespace meshedit
