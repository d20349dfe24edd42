// Where the program's own files are found: beside the binary, in the installed layout, then in the source tree.
#include "core/data_folders.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <system_error>
#include <vector>

#include "support/test_support.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;
using testing::source_dir;

TEST(DataFolders, CandidatesAreBesideTheBinaryThenInstalledThenTheSourceTree) {
  const fs::path program = program_folder();
  ASSERT_FALSE(program.empty());  // Linux knows it
  std::error_code ec;
  EXPECT_TRUE(fs::is_regular_file(program / "core_tests", ec)) << program;
  const std::vector<fs::path> expected = {program / "scripts/student",
                                          program.parent_path() / "share/meshedit/scripts/student",
                                          source_dir() / "scripts/student"};
  EXPECT_EQ(data_folder_candidates("scripts/student"), expected);
}

TEST(DataFolders, TheBuildTreeFindsTheSourceTreesFolders) {
  EXPECT_EQ(data_folder("lessons"), source_dir() / "lessons");
  EXPECT_EQ(data_folder("shaders"), source_dir() / "shaders");
}

TEST(DataFolders, AFolderNowhereIsTheSourceTreesName) {
  EXPECT_EQ(data_folder("no_such_folder"), source_dir() / "no_such_folder");
}

}  // namespace
}  // namespace meshedit
