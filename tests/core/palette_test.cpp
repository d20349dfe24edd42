// The palette (core/palette.h) keeps apart what must be told apart, for normal vision and the three common
// dichromacies, in both themes, and its light theme reads on its light background. The colour science it is measured
// with (colour_vision.h) is checked first against known values, so a broken measure cannot pass a bad palette.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "core/colour_vision.h"
#include "core/palette.h"

namespace meshedit {
namespace {

using testing::composite;
using testing::contrast_ratio;
using testing::delta_e;
using testing::kVisions;
using testing::Vision;

constexpr double kMinDeltaE = 20.0;       // CIELAB units between colours that must be told apart
constexpr double kMinLineContrast = 3.0;  // WCAG, for lines, marks, labels and large text

struct Named {
  const char* name;
  glm::vec3 rgb;
};
using Pairs = std::vector<std::pair<Named, Named>>;

Pairs all_pairs(const std::vector<Named>& colours) {
  Pairs pairs;
  for (size_t i = 0; i < colours.size(); ++i) {
    for (size_t j = i + 1; j < colours.size(); ++j) pairs.push_back({colours[i], colours[j]});
  }
  return pairs;
}

const char* theme_name(Theme theme) { return theme == Theme::Light ? "light" : "dark"; }

// Fails for each pair closer than kMinDeltaE under some vision; returns the smallest distance for each vision.
std::vector<double> expect_apart(const Pairs& pairs, Theme theme, const std::string& group) {
  std::vector<double> smallest;
  for (Vision vision : kVisions) {
    double least = 1e9;
    for (const auto& [a, b] : pairs) {
      const double d = delta_e(a.rgb, b.rgb, vision);
      least = std::min(least, d);
      EXPECT_GE(d, kMinDeltaE) << theme_name(theme) << " theme, " << group << ": " << a.name << " and " << b.name
                               << " under " << testing::vision_name(vision);
    }
    smallest.push_back(least);
    std::printf("  %-5s %-34s %-14s smallest dE %.1f\n", theme_name(theme), group.c_str(), testing::vision_name(vision),
                least);
  }
  return smallest;
}

// ---- the measure ----------------------------------------------------------------------------------

TEST(ColourVision, KnownValues) {
  const glm::vec3 white(1.0f), black(0.0f);
  EXPECT_NEAR(testing::relative_luminance(white), 1.0, 1e-4);
  EXPECT_NEAR(contrast_ratio(white, black), 21.0, 1e-3);
  const glm::dvec3 lab_white = testing::lab_from_linear(testing::linear_rgb(white));
  EXPECT_NEAR(lab_white.x, 100.0, 0.01);
  EXPECT_NEAR(lab_white.y, 0.0, 0.05);
  EXPECT_NEAR(lab_white.z, 0.0, 0.05);
  // sRGB red is L* 53.2, a* 80.1, b* 67.2.
  const glm::dvec3 lab_red = testing::lab_from_linear(testing::linear_rgb({1.0f, 0.0f, 0.0f}));
  EXPECT_NEAR(lab_red.x, 53.24, 0.05);
  EXPECT_NEAR(lab_red.y, 80.09, 0.1);
  EXPECT_NEAR(lab_red.z, 67.20, 0.1);
  // Machado's matrices keep greys grey (each row sums to 1).
  for (Vision vision : kVisions) EXPECT_LT(delta_e({0.5f, 0.5f, 0.5f}, {0.5f, 0.5f, 0.5f}, vision), 1e-9);
  for (Vision vision : kVisions) {
    const glm::dvec3 grey = testing::simulate_linear({0.2, 0.2, 0.2}, vision);
    EXPECT_NEAR(grey.r, 0.2, 1e-5);
    EXPECT_NEAR(grey.g, 0.2, 1e-5);
    EXPECT_NEAR(grey.b, 0.2, 1e-5);
  }
}

TEST(ColourVision, RedAndGreenCollapseForProtanopesAndDeuteranopesOnly) {
  // An orange-red and an olive green: far apart for normal vision and tritanopes, close for the other two.
  const glm::vec3 red(1.0f, 0.4f, 0.1f), green(0.6f, 0.6f, 0.0f);
  EXPECT_GT(delta_e(red, green, Vision::Normal), 60.0);
  EXPECT_GT(delta_e(red, green, Vision::Tritanopia), 60.0);
  EXPECT_LT(delta_e(red, green, Vision::Protanopia), 10.0);
  EXPECT_LT(delta_e(red, green, Vision::Deuteranopia), 10.0);
  // A pale red and green for "wrong" and "right" text: 104 apart for normal vision, 12 for deuteranopes.
  EXPECT_LT(delta_e({1.0f, 0.45f, 0.4f}, {0.5f, 0.9f, 0.5f}, Vision::Deuteranopia), 15.0);
}

TEST(ColourVision, OkabeItoAloneIsNotEnough) {
  // Why the palette does not pair some Okabe-Ito colours: orange and yellow come within 20 under deuteranopia, sky
  // blue and bluish green under tritanopia.
  EXPECT_LT(delta_e(kDarkSwatches.orange, kDarkSwatches.yellow, Vision::Deuteranopia), kMinDeltaE);
  EXPECT_LT(delta_e(kDarkSwatches.sky_blue, kDarkSwatches.bluish_green, Vision::Tritanopia), kMinDeltaE);
}

// ---- the palette ----------------------------------------------------------------------------------

class PaletteInTheme : public ::testing::TestWithParam<Theme> {
 protected:
  const Palette& p() const { return palette_for(GetParam()); }
};

TEST_P(PaletteInTheme, HighlightsAreApart) {
  const Palette& pal = p();
  expect_apart(
      all_pairs(
          {{"selected", pal.selected}, {"hovered", pal.hovered}, {"changed", pal.changed}, {"boundary", pal.boundary}}),
      GetParam(), "selection/hover/changed/boundary");
}

TEST_P(PaletteInTheme, HighlightsStandOutOnFacesAndWire) {
  const Palette& pal = p();
  Pairs pairs;
  for (const Named& highlight :
       {Named{"selected", pal.selected}, Named{"hovered", pal.hovered}, Named{"changed", pal.changed}}) {
    pairs.push_back({highlight, {"face", pal.neutrals.face}});
  }
  for (const Named& line : {Named{"selected", pal.selected}, Named{"hovered", pal.hovered},
                            Named{"changed", pal.changed}, Named{"boundary", pal.boundary}}) {
    pairs.push_back({line, {"wire", pal.neutrals.wire}});
  }
  pairs.push_back({{"face", pal.neutrals.face}, {"back face", pal.neutrals.back_face}});
  expect_apart(pairs, GetParam(), "highlights/faces/wire");
}

TEST_P(PaletteInTheme, MineReferenceAndWrongAreApart) {
  const Palette& pal = p();
  expect_apart(all_pairs({{"mine", pal.mine}, {"reference", pal.reference}, {"wrong", pal.wrong}}), GetParam(),
               "mine/reference/wrong");
}

TEST_P(PaletteInTheme, DeCasteljauLevelsAreApart) {
  const Palette& pal = p();
  // Each level against the next (the cycle wraps, so level kLevelColours + 1 comes back to level 1's colour), and
  // every level against the final point and against a wrong level of yours (drawn instead of a level's colour).
  Pairs pairs;
  std::vector<std::string> names;
  for (int k = 0; k <= int(kLevelColours) + 1; ++k) names.push_back("level " + std::to_string(k));
  for (int k = 0; k <= int(kLevelColours); ++k) {
    pairs.push_back(
        {{names[size_t(k)].c_str(), level_colour(pal, k)}, {names[size_t(k) + 1].c_str(), level_colour(pal, k + 1)}});
  }
  for (int k = 0; k <= int(kLevelColours); ++k) {
    pairs.push_back({{names[size_t(k)].c_str(), level_colour(pal, k)}, {"final point", pal.final_point}});
    if (k > 0) pairs.push_back({{names[size_t(k)].c_str(), level_colour(pal, k)}, {"wrong", pal.wrong}});
  }
  expect_apart(pairs, GetParam(), "de Casteljau levels");
}

TEST_P(PaletteInTheme, ErrorWarningAndOkTextAreApart) {
  const Palette& pal = p();
  expect_apart(all_pairs({{"error", pal.error}, {"warning", pal.warning}, {"ok", pal.ok}}), GetParam(),
               "error/warning/ok text");
}

TEST_P(PaletteInTheme, LabelsReadOnTheirBoxesOverTheViewAndTheFaces) {
  const Palette& pal = p();
  const std::vector<Named> texts{{"vertex label", pal.vertex_label},
                                 {"edge label", pal.edge_label},
                                 {"halfedge label", pal.halfedge_label},
                                 {"face label", pal.face_label}};
  for (glm::vec3 under : {pal.neutrals.view, pal.neutrals.face, pal.neutrals.back_face}) {
    const glm::vec3 box = composite(glm::vec3(pal.neutrals.label_box), pal.neutrals.label_box.a, under);
    for (const Named& text : texts) {
      EXPECT_GE(contrast_ratio(text.rgb, box), kMinLineContrast) << theme_name(GetParam()) << ": " << text.name;
    }
    const glm::vec3 lesson_box = composite(glm::vec3(pal.lesson_label_box), pal.lesson_label_box.a, under);
    EXPECT_GE(contrast_ratio(pal.lesson_label, lesson_box), kMinLineContrast) << theme_name(GetParam());
  }
}

INSTANTIATE_TEST_SUITE_P(BothThemes, PaletteInTheme, ::testing::Values(Theme::Dark, Theme::Light),
                         [](const ::testing::TestParamInfo<Theme>& param_info) {
                           return std::string(theme_name(param_info.param));
                         });

TEST(LightPalette, LinesAndMarksContrastWithTheLightBackgrounds) {
  const Palette& pal = palette_for(Theme::Light);
  const std::vector<Named> on_view{{"wire", pal.neutrals.wire},
                                   {"boundary", pal.boundary},
                                   {"vertex", pal.vertex},
                                   {"arrow", pal.arrow},
                                   {"selected", pal.selected},
                                   {"hovered", pal.hovered},
                                   {"changed", pal.changed},
                                   {"lesson highlight", pal.lesson_highlight},
                                   {"net", pal.net},
                                   {"probed net", pal.probed_net},
                                   {"row curve", pal.row_curve},
                                   {"row points", pal.row_points},
                                   {"column polygon", pal.column_polygon},
                                   {"column level 1", pal.column_levels[0]},
                                   {"column level 2", pal.column_levels[1]},
                                   {"surface point", pal.final_point}};
  for (const Named& c : on_view) {
    EXPECT_GE(contrast_ratio(c.rgb, pal.neutrals.view), kMinLineContrast) << c.name << " on the view";
  }
  // Every swatch, so that a lesson's named highlight reads too.
  const Swatches& s = pal.swatches;
  for (const Named& c : std::vector<Named>{{"orange", s.orange},
                                           {"sky blue", s.sky_blue},
                                           {"bluish green", s.bluish_green},
                                           {"yellow", s.yellow},
                                           {"blue", s.blue},
                                           {"vermillion", s.vermillion},
                                           {"reddish purple", s.reddish_purple},
                                           {"grey", s.grey},
                                           {"ink", s.ink}}) {
    EXPECT_GE(contrast_ratio(c.rgb, pal.neutrals.view), kMinLineContrast) << c.name << " on the view";
  }
  const glm::vec3 ghosted_reference = composite(pal.reference, kGhostAlpha, pal.neutrals.canvas);
  std::vector<Named> on_canvas{
      {"control", pal.control},       {"final point", pal.final_point},          {"curve", pal.curve},
      {"split left", pal.split_left}, {"split right", pal.split_right},          {"mine", pal.mine},
      {"wrong", pal.wrong},           {"reference (ghosted)", ghosted_reference}};
  for (glm::vec3 level : pal.levels) on_canvas.push_back({"level", level});
  for (const Named& c : on_canvas) {
    EXPECT_GE(contrast_ratio(c.rgb, pal.neutrals.canvas), kMinLineContrast) << c.name << " on the curve view";
  }
  for (const Named& c : std::vector<Named>{{"error", pal.error},
                                           {"warning", pal.warning},
                                           {"ok", pal.ok},
                                           {"link", pal.link},
                                           {"dead", pal.dead},
                                           {"emphasis", pal.emphasis},
                                           {"console input", pal.console_input}}) {
    EXPECT_GE(contrast_ratio(c.rgb, pal.neutrals.panel), kMinLineContrast) << c.name << " on a panel";
  }
}

TEST(LightPalette, TheLightThemeIsLightAndTheDarkDark) {
  EXPECT_GT(testing::relative_luminance(palette_for(Theme::Light).neutrals.view), 0.7);
  EXPECT_GT(testing::relative_luminance(palette_for(Theme::Light).neutrals.panel), 0.7);
  EXPECT_LT(testing::relative_luminance(palette_for(Theme::Dark).neutrals.view), 0.05);
  EXPECT_LT(testing::relative_luminance(palette_for(Theme::Dark).neutrals.panel), 0.05);
}

// ---- naming -----------------------------------------------------------------------------------------

TEST(Palette, DarkSwatchesAreOkabeIto) {
  const auto hex = [](glm::vec3 c) {
    char text[8];
    std::snprintf(text, sizeof text, "#%02X%02X%02X", int(c.r * 255.0f + 0.5f), int(c.g * 255.0f + 0.5f),
                  int(c.b * 255.0f + 0.5f));
    return std::string(text);
  };
  EXPECT_EQ(hex(kDarkSwatches.orange), "#E69F00");
  EXPECT_EQ(hex(kDarkSwatches.sky_blue), "#56B4E9");
  EXPECT_EQ(hex(kDarkSwatches.bluish_green), "#009E73");
  EXPECT_EQ(hex(kDarkSwatches.yellow), "#F0E442");
  EXPECT_EQ(hex(kDarkSwatches.blue), "#0072B2");
  EXPECT_EQ(hex(kDarkSwatches.vermillion), "#D55E00");
  EXPECT_EQ(hex(kDarkSwatches.reddish_purple), "#CC79A7");
}

TEST(Palette, LevelsCycleAfterTheControlPolygon) {
  const Palette& pal = palette_for(Theme::Dark);
  EXPECT_EQ(level_colour(pal, 0), pal.control);
  EXPECT_EQ(level_colour(pal, 1), pal.levels[0]);
  EXPECT_EQ(level_colour(pal, int(kLevelColours)), pal.levels[kLevelColours - 1]);
  EXPECT_EQ(level_colour(pal, int(kLevelColours) + 1), pal.levels[0]);
}

TEST(Palette, ASwatchTakesTheThemesShade) {
  EXPECT_EQ(swatch_in_theme(kDarkSwatches.yellow, Theme::Light), kLightSwatches.yellow);
  EXPECT_EQ(swatch_in_theme(kDarkSwatches.ink, Theme::Light), kLightSwatches.ink);
  EXPECT_EQ(swatch_in_theme(kDarkSwatches.vermillion, Theme::Dark), kDarkSwatches.vermillion);
  const glm::vec3 own(0.2f, 0.3f, 0.4f);  // not a swatch: left as it is
  EXPECT_EQ(swatch_in_theme(own, Theme::Light), own);
}

}  // namespace
}  // namespace meshedit
