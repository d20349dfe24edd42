// Submission::read: .lua files at the top or in subfolders (top wins), symbolic links and hidden folders
// skipped, the size cap, and a missing folder.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "grade/submission.h"
#include "grade_test_support.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;
using testing::write_text;

TEST(Submission, ReadsLuaFilesAndSaysWhereTheyWere) {
  const fs::path dir = testing::scratch_dir();
  write_text(dir / "sub" / "flip.lua", "-- top");
  write_text(dir / "sub" / "notes.txt", "not Lua");
  write_text(dir / "sub" / "hw4" / "split.lua", "-- nested");
  write_text(dir / "sub" / "hw4" / "flip.lua", "-- shadowed by the top one");
  write_text(dir / "sub" / ".git" / "hooks.lua", "-- hidden folder");
  write_text(dir / "sub" / "__MACOSX" / "upsample.lua", "-- zip junk");
  write_text(dir / "sub" / "a" / "b" / "c" / "d" / "deep.lua", "-- too deep");
  write_text(dir / "sub" / "big.lua", std::string(Submission::kMaxSubmittedFileBytes + 1, '-'));
  write_text(dir / "reference.lua", "-- the instructor's");
  fs::create_symlink(dir / "reference.lua", dir / "sub" / "normals.lua");
  const Submission s = Submission::read(dir / "sub");
  ASSERT_EQ(s.files().size(), 2u);
  EXPECT_EQ(s.files()[0].name, "flip.lua");
  EXPECT_EQ(s.files()[0].relative, "flip.lua");
  EXPECT_EQ(s.files()[0].text, "-- top");
  EXPECT_EQ(s.files()[1].name, "split.lua");
  EXPECT_EQ(s.files()[1].relative, "hw4/split.lua");
  EXPECT_EQ(s.find("split.lua")->text, "-- nested");
  EXPECT_EQ(s.find("normals.lua"), nullptr);
  EXPECT_EQ(s.notes(), (std::vector<std::string>{"normals.lua is a symbolic link: skipped",
                                                 "big.lua is larger than 1024 KB: skipped",
                                                 "split.lua was found in hw4/split.lua"}));
}

TEST(Submission, AMissingFolderIsAGradingError) {
  EXPECT_THROW(Submission::read(testing::scratch_dir() / "absent"), GradeError);
}

}  // namespace
}  // namespace meshedit
