// Helpers shared by the test binaries: where the course files are, and a skip when they are absent.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include <gtest/gtest.h>
#include <glm/vec3.hpp>

namespace meshedit::testing {

// ../shared/data/cs184 (or $MESHEDIT_SHARED_DATA), if it exists.
std::optional<std::filesystem::path> course_data_dir();

// The project's source tree (for assets/ and tests/ files).
std::filesystem::path source_dir();

// The whole file as bytes; a failed expectation (and "") if it cannot be opened.
std::string read_text(const std::filesystem::path& path);

// The words of a file under source_dir(), its line breaks, comment marks (-- --- //) and runs of spaces each made one
// space, so a sentence or a list reads the same wherever the file wraps it.
std::string words_of(const std::string& relative_path);

// A fresh empty directory under the system temp dir, unique to the running test and process (a second call in the
// same test empties it again).
std::filesystem::path scratch_dir();

// EXPECT_TRUE(near(actual, expected, tol)): every coordinate within tol, printed with 17 digits if not.
::testing::AssertionResult near(const glm::dvec3& actual, const glm::dvec3& expected, double tol);

}  // namespace meshedit::testing

// Binds `dir` to the course data folder, or skips the test when it is absent.
#define MESHEDIT_REQUIRE_COURSE_DATA(dir)                                          \
  const auto dir##_opt = ::meshedit::testing::course_data_dir();                   \
  if (!dir##_opt) GTEST_SKIP() << "course files not found (../shared/data/cs184)"; \
  const std::filesystem::path dir = *dir##_opt
