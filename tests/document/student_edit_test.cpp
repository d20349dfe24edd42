// StudentEdit (document/student_edit.h): the editor's text of a student file, its lines replaced, saved whole, read
// again when the file changes on disk unless the text has unsaved changes; and the line a Lua error names.
#include "document/student_edit.h"

#include <gtest/gtest.h>

#include <fstream>

#include "support/test_support.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;

TEST(StudentEdit, ReplacesALineSavesAndFollowsTheFileWhileClean) {
  const fs::path file = testing::scratch_dir() / "flip.lua";
  std::ofstream(file) << "function flip_edge(mesh, e)\n  return nil\nend\n";
  StudentEdit edit;
  edit.follow(file);
  EXPECT_EQ(edit.text(), "function flip_edge(mesh, e)\n  return nil\nend\n");
  EXPECT_FALSE(edit.set_line(0, "x"));
  EXPECT_FALSE(edit.set_line(6, "x"));  // past one beyond the last line
  ASSERT_TRUE(edit.set_line(2, "  return e"));
  EXPECT_TRUE(edit.dirty());
  // Unsaved text is not replaced by the file.
  std::ofstream(file) << "-- changed elsewhere\n";
  edit.follow(file);
  EXPECT_EQ(edit.text(), "function flip_edge(mesh, e)\n  return e\nend\n");
  ASSERT_TRUE(edit.save());
  EXPECT_FALSE(edit.dirty());
  std::ifstream in(file);
  const std::string saved((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(saved, edit.text());
  // Clean: a change on disk shows.
  std::ofstream(file) << "-- changed elsewhere, longer\n";
  edit.follow(file);
  EXPECT_EQ(edit.text(), "-- changed elsewhere, longer\n");
  ASSERT_TRUE(edit.set_line(2, "return {}"));  // one beyond the last line adds one
  EXPECT_EQ(edit.text(), "-- changed elsewhere, longer\nreturn {}");
}

TEST(StudentEdit, ReadsALineAsTheEditorNumbersThem) {
  const fs::path file = testing::scratch_dir() / "split.lua";
  std::ofstream(file) << "local a = 1\n\nreturn a\n";
  StudentEdit edit;
  edit.follow(file);
  EXPECT_EQ(edit.line(0), std::nullopt);
  EXPECT_EQ(edit.line(1), "local a = 1");
  EXPECT_EQ(edit.line(2), "");
  EXPECT_EQ(edit.line(3), "return a");
  EXPECT_EQ(edit.line(4), "");  // after the last newline: the empty line the editor shows
  EXPECT_EQ(edit.line(5), std::nullopt);
  ASSERT_TRUE(edit.set_line(5, "-- added"));
  EXPECT_EQ(edit.line(5), "-- added");
  EXPECT_EQ(edit.text(), "local a = 1\n\nreturn a\n\n-- added");
}

TEST(StudentEdit, ADraftTakenBackIsUnsavedTextAndEveryChangeIsCounted) {
  const fs::path file = testing::scratch_dir() / "flip.lua";
  std::ofstream(file) << "return nil\n";
  StudentEdit edit;
  edit.follow(file);
  const uint64_t read = edit.changes();
  EXPECT_GT(read, 0u);
  EXPECT_FALSE(edit.take_draft("return nil\n"));  // the text already shown: nothing to take
  EXPECT_FALSE(edit.dirty());
  EXPECT_EQ(edit.changes(), read);
  ASSERT_TRUE(edit.take_draft("return e\n"));
  EXPECT_TRUE(edit.dirty());
  EXPECT_EQ(edit.text(), "return e\n");
  EXPECT_EQ(edit.changes(), read + 1);
  ASSERT_TRUE(edit.set_line(1, "return {}"));
  EXPECT_EQ(edit.changes(), read + 2);
  ASSERT_TRUE(edit.save());
  EXPECT_EQ(edit.changes(), read + 2);  // saving changes the file, not the text
  edit.reread();
  EXPECT_EQ(edit.changes(), read + 3);
}

TEST(StudentEdit, AMissingFileShowsEmptyWithItsErrorAndSaveSaysWhyNot) {
  const fs::path dir = testing::scratch_dir();
  StudentEdit edit;
  edit.follow(dir / "missing.lua");
  EXPECT_EQ(edit.text(), "");
  EXPECT_NE(edit.read_error().find("missing.lua"), std::string::npos) << edit.read_error();
  StudentEdit nowhere;
  nowhere.follow(dir / "no such folder" / "flip.lua");
  const Check saved = nowhere.save();
  EXPECT_FALSE(saved);
  EXPECT_NE(saved.reason.find("flip.lua"), std::string::npos) << saved.reason;
}

TEST(StudentEdit, TheLineAnErrorNamesInTheFile) {
  EXPECT_EQ(error_line_in("flip.lua:67: 'end' expected near 'nil'", "flip.lua"), 67u);
  EXPECT_EQ(error_line_in("[string \"flip.lua\"]:3: unexpected symbol", "flip.lua"), 3u);
  EXPECT_EQ(error_line_in("/tmp/x/flip.lua:12: attempt to index a nil value", "flip.lua"), 12u);
  EXPECT_EQ(error_line_in("split.lua:4: oops", "flip.lua"), std::nullopt);
  EXPECT_EQ(error_line_in("flip.lua: cannot open", "flip.lua"), std::nullopt);
  EXPECT_EQ(error_line_in("flip.lua:0: nothing", "flip.lua"), std::nullopt);
  EXPECT_EQ(error_line_in("memory ran out", "flip.lua"), std::nullopt);
  EXPECT_EQ(error_line_in("flip.lua:99999999999999999999: huge", "flip.lua").has_value(), true);
  EXPECT_EQ(error_line_in("anything", ""), std::nullopt);
}

}  // namespace
}  // namespace meshedit
