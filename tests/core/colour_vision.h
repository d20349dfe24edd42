// Colour science for the palette's tests: how a colour looks to people with the three common dichromacies, how far
// apart two colours look, and how well text or a line stands out from its background.
//
// - Dichromacy: Machado, Oliveira and Fernandes (2009), "A Physiologically-based Model for Simulation of Color Vision
//   Deficiency", IEEE TVCG 15(6), the matrices for severity 1.0 (protanopia, deuteranopia, tritanopia), applied to
//   linear RGB and clamped to [0, 1].
// - Distance: CIE 1976 ΔE*ab between CIELAB colours (sRGB primaries, D65 white).
// - Contrast: WCAG 2.x contrast ratio from relative luminance, (L1 + 0.05) / (L2 + 0.05).
//
// Inputs are sRGB components in [0, 1] (as the palette stores them).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

namespace meshedit::testing {

enum class Vision { Normal, Protanopia, Deuteranopia, Tritanopia };
inline constexpr std::array<Vision, 4> kVisions{Vision::Normal, Vision::Protanopia, Vision::Deuteranopia,
                                                Vision::Tritanopia};

inline const char* vision_name(Vision v) {
  switch (v) {
    case Vision::Normal: return "normal vision";
    case Vision::Protanopia: return "protanopia";
    case Vision::Deuteranopia: return "deuteranopia";
    case Vision::Tritanopia: return "tritanopia";
  }
  return "?";
}

inline double linear_from_srgb(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

inline glm::dvec3 linear_rgb(glm::vec3 srgb) {
  return {linear_from_srgb(srgb.r), linear_from_srgb(srgb.g), linear_from_srgb(srgb.b)};
}

// Machado et al. 2009, severity 1.0, rows acting on linear (R, G, B).
inline glm::dvec3 simulate_linear(glm::dvec3 rgb, Vision vision) {
  using Rows = std::array<std::array<double, 3>, 3>;
  static constexpr Rows kProtanopia{
      {{0.152286, 1.052583, -0.204868}, {0.114503, 0.786281, 0.099216}, {-0.003882, -0.048116, 1.051998}}};
  static constexpr Rows kDeuteranopia{
      {{0.367322, 0.860646, -0.227968}, {0.280085, 0.672501, 0.047413}, {-0.011820, 0.042940, 0.968881}}};
  static constexpr Rows kTritanopia{
      {{1.255528, -0.076749, -0.178779}, {-0.078411, 0.930809, 0.147602}, {0.004733, 0.691367, 0.303900}}};
  const Rows* m = vision == Vision::Protanopia     ? &kProtanopia
                  : vision == Vision::Deuteranopia ? &kDeuteranopia
                  : vision == Vision::Tritanopia   ? &kTritanopia
                                                   : nullptr;
  if (!m) return rgb;
  glm::dvec3 out;
  for (int i = 0; i < 3; ++i) {
    const auto& row = (*m)[size_t(i)];
    out[i] = std::clamp(row[0] * rgb.r + row[1] * rgb.g + row[2] * rgb.b, 0.0, 1.0);
  }
  return out;
}

// CIELAB (L*, a*, b*) of a linear sRGB colour, D65 white.
inline glm::dvec3 lab_from_linear(glm::dvec3 rgb) {
  const double x = 0.4124 * rgb.r + 0.3576 * rgb.g + 0.1805 * rgb.b;
  const double y = 0.2126 * rgb.r + 0.7152 * rgb.g + 0.0722 * rgb.b;
  const double z = 0.0193 * rgb.r + 0.1192 * rgb.g + 0.9505 * rgb.b;
  auto f = [](double t) { return t > 216.0 / 24389.0 ? std::cbrt(t) : (24389.0 / 27.0 * t + 16.0) / 116.0; };
  const double fx = f(x / 0.95047), fy = f(y), fz = f(z / 1.08883);
  return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

// ΔE*ab between two sRGB colours as a person with `vision` sees them.
inline double delta_e(glm::vec3 a, glm::vec3 b, Vision vision) {
  return glm::distance(lab_from_linear(simulate_linear(linear_rgb(a), vision)),
                       lab_from_linear(simulate_linear(linear_rgb(b), vision)));
}

inline double relative_luminance(glm::vec3 srgb) {
  const glm::dvec3 l = linear_rgb(srgb);
  return 0.2126 * l.r + 0.7152 * l.g + 0.0722 * l.b;
}

// WCAG contrast ratio, from 1 (the same) to 21 (black on white).
inline double contrast_ratio(glm::vec3 a, glm::vec3 b) {
  const double la = relative_luminance(a), lb = relative_luminance(b);
  return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

// `over` with alpha `alpha` painted on `under` (sRGB blending, as ImGui and the GL blend do).
inline glm::vec3 composite(glm::vec3 over, float alpha, glm::vec3 under) {
  return over * alpha + under * (1.0f - alpha);
}

}  // namespace meshedit::testing
