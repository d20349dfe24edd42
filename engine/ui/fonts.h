// The window's type: Debian's DejaVu Sans for text and DejaVu Sans Mono for ids and tables, rasterised at the size
// the student chose times the monitor's content scale, so text is sharp on HiDPI screens. Without the font files
// ImGui's own font is used and the warning says which file was missing. When the window's language is Chinese
// (core/translation.h), the glyphs of WenQuanYi Micro Hei that the language's catalog and the shipped lessons use are
// merged into both fonts, so the atlas holds only the characters the texts need: WenQuanYiMicroHei.ttf (the page's
// cut-down copy) or wqy-microhei.ttc beside the DejaVu files, else Debian's fonts-wqy-microhei (not with
// MESHEDIT_FONT_DIR set: that folder only).
//
// Invariants:
// - load_fonts replaces everything in ImGui's font atlas: the first font is the text font (ImGui's default), the
//   second the monospace one. The caller uploads the atlas again (the window's backend) before the next frame.
// - mono_font() is never null while an ImGui context exists: the text font stands in when there is no second one.
// - The font files are looked up in MESHEDIT_FONT_DIR when it is set (tests point it at a folder without them), else
//   in the first fonts/ folder of core/data_folders.h that holds DejaVuSans.ttf (an install copies them into
//   share/meshedit/fonts), else in Debian's folder for fonts-dejavu-core.
#pragma once

#include <filesystem>
#include <string>

struct ImFont;

namespace meshedit {

struct FontsLoaded {
  bool real = false;    // DejaVu was found and loaded
  float pixels = 0.0f;  // the text font's height in framebuffer pixels
  std::string warning;  // why ImGui's font stands in ("" when real)
};

// Builds the atlas for text of `font_px` at content scale `scale` (pixels = font_px * scale), rasterised at
// `raster_scale` times that and drawn at 1 / raster_scale (for a framebuffer denser than the window's coordinates).
// Needs a current ImGui context, outside a frame.
FontsLoaded load_fonts(float font_px, float scale, float raster_scale = 1.0f);

// Whether the text font draws every wide character of `text` (core/text_breaks.h). When it does not, the missing
// characters are remembered, so that the next load_fonts adds them (a lesson from outside the shipped lessons/
// folder), and false is returned: the caller loads the fonts again.
bool fonts_cover(const std::string& text);

// The monospace font, for ids, pointer tables and code.
ImFont* mono_font();

// The folder load_fonts reads DejaVuSans.ttf and DejaVuSansMono.ttf from (see the invariants above).
std::filesystem::path font_folder();

}  // namespace meshedit
