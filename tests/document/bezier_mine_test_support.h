// What the tests of "mine" in the curve and patch views share (document/bezier_mine_test.cpp, and
// ui/bezier_mine_views_test.cpp for the views): the correct solutions, a student file written into a folder as a
// save, a solution with one line changed, the course's cubic and lesson 2's hill.
#pragma once

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/bezier.h"
#include "support/test_support.h"

namespace meshedit::document_testing {

inline std::filesystem::path solutions() { return testing::source_dir() / "tests" / "exercise" / "solutions"; }

// Writes `text` as `name` in `folder`, moving the modification time on so a rewrite is always seen as a save.
inline void write_file(const std::filesystem::path& folder, const std::string& name, const std::string& text) {
  namespace fs = std::filesystem;
  const fs::path path = folder / name;
  const bool existed = fs::exists(path);
  const auto before = existed ? fs::last_write_time(path) : fs::file_time_type{};
  std::ofstream(path, std::ios::binary) << text;
  if (existed) fs::last_write_time(path, before + std::chrono::seconds(2));
}

// The solution with `from` replaced by `to`.
inline std::string solution_with(const std::string& file, const std::string& from, const std::string& to) {
  std::string text = testing::read_text(solutions() / file);
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

inline const std::string kStepLine = "    result[i] = (1 - t) * points[i] + t * points[i + 1]\n";

// The course's curve1.bzc cubic; at t = 0.5 level 1 is (0.25, 0.475) (0.55, 0.675) (0.85, 0.6).
inline const std::vector<glm::dvec2> kCubic = {{0.2, 0.35}, {0.3, 0.6}, {0.8, 0.75}, {0.9, 0.45}};

// Lesson 2's hill: row r at y = r, column c at x = c, the middle four raised to z = 2.
inline BezierPatch hill() {
  BezierPatch patch;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) {
      patch.at(r, c) = glm::dvec3(c, r, (r == 1 || r == 2) && (c == 1 || c == 2) ? 2.0 : 0.0);
    }
  }
  return patch;
}

}  // namespace meshedit::document_testing
