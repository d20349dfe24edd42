// The one palette of the app: every colour that means something (the selection, the hovered element, the last edit,
// boundary edges, faces and their back sides, de Casteljau levels and the final point, the student's result against the
// reference, error / warning / ok text, lesson highlights) is named here once, for each theme.
//
// It sits in core, though core draws nothing, because both render (the mesh view's RenderStyle) and ui (the panels,
// the curve and patch views) read it and ui may not include render; script reads it too (a lesson's colour names).
// It is plain RGB in [0, 1] with GLM, which core already uses: no GL, no ImGui.
//
// Invariants:
// - Every role is one of the theme's Okabe-Ito swatches (orange, sky blue, bluish green, yellow, blue, vermillion,
//   reddish purple, grey, ink) or one of its neutrals (backgrounds, faces, wire): make_palette() is the only place a
//   role is given a colour, and it does so the same way for both themes.
// - The dark theme's swatches are Okabe-Ito's own values (ink is near-white). The light theme's are the same hues,
//   darkened so that every one has a WCAG contrast of at least 3 with the light view's background, each to its own
//   lightness so that colours that must be told apart stay apart without hue (ink is near-black).
// - Colours that must be told apart stay at least 20 CIELAB units apart for normal vision and under simulated
//   protanopia, deuteranopia and tritanopia, in both themes: selection, hover, last edit and boundary; mine,
//   reference and wrong; consecutive de Casteljau levels and the final point; error, warning and ok text; faces
//   against their back sides and against the highlights. tests/core/palette_test.cpp measures it.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace meshedit {

enum class Theme { Dark, Light };

// 0xRRGGBB as RGB in [0, 1].
constexpr glm::vec3 rgb_hex(uint32_t rgb) {
  return glm::vec3(float((rgb >> 16) & 255u) / 255.0f, float((rgb >> 8) & 255u) / 255.0f, float(rgb & 255u) / 255.0f);
}
constexpr glm::vec4 with_alpha(glm::vec3 rgb, float alpha) { return glm::vec4(rgb.x, rgb.y, rgb.z, alpha); }

// The Okabe-Ito colours as one theme shows them.
struct Swatches {
  glm::vec3 orange, sky_blue, bluish_green, yellow, blue, vermillion, reddish_purple;
  glm::vec3 grey;  // muted things: other patches' nets, dead rows, hints
  glm::vec3 ink;   // the colour of plain marks: white-ish on dark, black-ish on light
};

// In the order of the fields: orange, sky blue, bluish green, yellow, blue, vermillion, reddish purple, grey, ink.
inline constexpr Swatches kDarkSwatches{rgb_hex(0xE69F00), rgb_hex(0x56B4E9), rgb_hex(0x009E73),
                                        rgb_hex(0xF0E442), rgb_hex(0x0072B2), rgb_hex(0xD55E00),
                                        rgb_hex(0xCC79A7), rgb_hex(0x8C8C8C), rgb_hex(0xF2F2F2)};
// Darker where a colour must stand out more: yellow and sky blue as light as a contrast of 3 allows, vermillion and
// blue much darker, so that yellow and vermillion (close in hue for deuteranopes) differ in lightness.
inline constexpr Swatches kLightSwatches{rgb_hex(0xA8660A), rgb_hex(0x3A8CC0), rgb_hex(0x007A5A),
                                         rgb_hex(0x938A1E), rgb_hex(0x004E7C), rgb_hex(0x8A3A00),
                                         rgb_hex(0xA0507E), rgb_hex(0x6B6B6B), rgb_hex(0x1A1A1A)};

// What is not a swatch: the surfaces things are drawn on.
struct Neutrals {
  glm::vec3 view;       // the 3D views' background
  glm::vec3 panel;      // the panels' background (ImGui windows)
  glm::vec3 canvas;     // the curve view's background
  glm::vec3 face;       // a face's front side
  glm::vec3 back_face;  // its back side (an inside-out face shows)
  glm::vec3 wire;       // the wireframe, over the faces
  glm::vec4 label_box;  // behind an id label's text
};

// Dark: a blue-grey view, grey faces (so every highlight hue shows on them) with brown back sides, a near-black wire.
inline constexpr Neutrals kDarkNeutrals{rgb_hex(0x212429),
                                        rgb_hex(0x17171A),
                                        rgb_hex(0x121218),
                                        rgb_hex(0xA7AEBD),
                                        rgb_hex(0x8C5A48),
                                        rgb_hex(0x101114),
                                        glm::vec4(0.0f, 0.0f, 0.0f, 0.75f)};
// Light: a near-white view and panels, pale blue-grey faces with pale brown back sides, a dark wire, white label boxes.
inline constexpr Neutrals kLightNeutrals{rgb_hex(0xEEF0F2),
                                         rgb_hex(0xF7F7F5),
                                         rgb_hex(0xFAFAF8),
                                         rgb_hex(0xAFC0D8),
                                         rgb_hex(0xD9A58F),
                                         rgb_hex(0x2A2A2E),
                                         glm::vec4(1.0f, 1.0f, 1.0f, 0.92f)};

inline constexpr size_t kLevelColours = 3;  // de Casteljau levels 1, 2, 3, 4... take these in turn
inline constexpr float kGhostAlpha = 0.6f;  // the reference's level, drawn under yours in the curve view

struct Palette {
  Swatches swatches;
  Neutrals neutrals;

  // The mesh view.
  glm::vec3 selected, hovered, changed, boundary;  // changed: by the last edit
  glm::vec3 vertex, arrow;

  // Labels over the mesh view: an id label's text by its element's kind, a lesson's label, and their boxes.
  glm::vec3 vertex_label, edge_label, halfedge_label, face_label, lesson_label;
  glm::vec4 lesson_label_box;

  // What a lesson's highlight() draws when it names no colour.
  glm::vec3 lesson_highlight;

  // De Casteljau: level 0 is the control polygon, then levels 1.. take `levels` in turn; the final point C(t) (and
  // a patch's P(u, v)); the curve itself (and the point being dragged); the two halves of a split.
  glm::vec3 control;
  std::array<glm::vec3, kLevelColours> levels;
  glm::vec3 final_point, curve, split_left, split_right;

  // The patch view's probe: other patches' nets, the probed one's, its rows at u, the points on them, the column
  // through those points and its levels at v.
  glm::vec3 net, probed_net, row_curve, row_points, column_polygon;
  std::array<glm::vec3, 2> column_levels;

  // The student's code against the reference: yours where it agrees, the reference's (ghosted), yours where not.
  glm::vec3 mine, reference, wrong;

  // Panel text and marks.
  glm::vec3 error, warning, ok, link, dead, console_input;
  glm::vec3 emphasis;        // text to read first: a lesson's hint, the step a replay is at
  glm::vec4 changed_cell;    // behind a pointer-table cell the last edit changed
  glm::vec4 differing_cell;  // behind an exercise's cell where yours and the reference's differ
};

// Gives every role its colour from the theme's swatches and neutrals (the only place roles are chosen).
inline Palette make_palette(const Swatches& s, const Neutrals& n) {
  Palette p;
  p.swatches = s;
  p.neutrals = n;

  p.selected = s.yellow;
  p.hovered = s.sky_blue;
  p.changed = s.vermillion;
  p.boundary = s.blue;
  p.vertex = s.ink;
  p.arrow = s.ink;

  p.vertex_label = s.yellow;
  p.edge_label = s.ink;
  p.halfedge_label = s.reddish_purple;
  p.face_label = s.sky_blue;
  p.lesson_label = s.orange;
  p.lesson_label_box = glm::vec4(glm::vec3(n.label_box), std::min(1.0f, n.label_box.a + 0.25f));

  p.lesson_highlight = p.changed;

  p.control = s.ink;
  p.levels = {s.sky_blue, s.yellow, s.blue};
  p.final_point = s.vermillion;
  p.curve = s.bluish_green;
  p.split_left = s.orange;
  p.split_right = s.blue;

  p.net = s.grey;
  p.probed_net = s.ink;
  p.row_curve = s.orange;
  p.row_points = s.yellow;
  p.column_polygon = s.sky_blue;
  p.column_levels = {s.blue, s.reddish_purple};

  p.mine = s.bluish_green;
  p.reference = s.ink;
  p.wrong = s.vermillion;

  p.error = s.vermillion;
  p.warning = s.yellow;
  p.ok = s.bluish_green;
  p.link = s.sky_blue;
  p.dead = s.grey;
  p.emphasis = s.orange;
  p.console_input = s.sky_blue;
  p.changed_cell = with_alpha(p.changed, 0.45f);
  p.differing_cell = with_alpha(p.wrong, 0.45f);
  return p;
}

inline const Palette& palette_for(Theme theme) {
  static const Palette kDark = make_palette(kDarkSwatches, kDarkNeutrals);
  static const Palette kLight = make_palette(kLightSwatches, kLightNeutrals);
  return theme == Theme::Light ? kLight : kDark;
}

// The colour of level k of de Casteljau's pyramid (k = 0: the control polygon).
inline glm::vec3 level_colour(const Palette& palette, int k) {
  if (k <= 0) return palette.control;
  return palette.levels[static_cast<size_t>(k - 1) % kLevelColours];
}

// A colour given as one of the dark theme's swatches, shown in `theme`: the theme's swatch of the same name (a
// lesson's "yellow" is the light theme's darker yellow there). Any other colour is returned as it is.
inline glm::vec3 swatch_in_theme(glm::vec3 dark_swatch, Theme theme) {
  const Swatches& from = kDarkSwatches;
  const Swatches& to = palette_for(theme).swatches;
  const glm::vec3 Swatches::*names[] = {&Swatches::orange,         &Swatches::sky_blue, &Swatches::bluish_green,
                                        &Swatches::yellow,         &Swatches::blue,     &Swatches::vermillion,
                                        &Swatches::reddish_purple, &Swatches::grey,     &Swatches::ink};
  for (const auto name : names) {
    if (from.*name == dark_swatch) return to.*name;
  }
  return dark_swatch;
}

}  // namespace meshedit
