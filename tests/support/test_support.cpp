// Test helpers (see test_support.h).
#include "support/test_support.h"

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>

namespace meshedit::testing {

std::optional<std::filesystem::path> course_data_dir() {
  std::filesystem::path dir = MESHEDIT_SHARED_DATA;
  if (const char* env = std::getenv("MESHEDIT_SHARED_DATA")) dir = env;
  std::error_code ec;
  if (std::filesystem::is_directory(dir, ec)) return dir;
  return std::nullopt;
}

std::filesystem::path source_dir() { return MESHEDIT_SOURCE_DIR; }

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  EXPECT_TRUE(in.good()) << path;
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::string words_of(const std::string& relative_path) {
  const std::string text = read_text(source_dir() / relative_path);
  static const std::regex breaks(R"(\s*\n\s*(--+|//)?\s*)");
  static const std::regex spaces(R"(\s+)");
  return std::regex_replace(std::regex_replace(text, breaks, " "), spaces, " ");
}

std::filesystem::path scratch_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = info ? std::string(info->test_suite_name()) + "." + info->name() : "meshedit";
  for (char& ch : name) {
    if (ch == '/') ch = '_';
  }
  // The process id keeps two checkouts (or two runs) of the same test from clearing each other's folder.
  auto dir = std::filesystem::temp_directory_path() / "meshedit-tests" / (name + "." + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

::testing::AssertionResult near(const glm::dvec3& actual, const glm::dvec3& expected, double tol) {
  if (std::abs(actual.x - expected.x) <= tol && std::abs(actual.y - expected.y) <= tol &&
      std::abs(actual.z - expected.z) <= tol) {
    return ::testing::AssertionSuccess();
  }
  std::ostringstream out;
  out.precision(17);
  out << "got (" << actual.x << ", " << actual.y << ", " << actual.z << "), expected (" << expected.x << ", "
      << expected.y << ", " << expected.z << "), tolerance " << tol;
  return ::testing::AssertionFailure() << out.str();
}

}  // namespace meshedit::testing
