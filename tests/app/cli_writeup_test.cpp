// `meshedit writeup` as a student runs it: on the solutions every figure is ok and the pages are written (index.html
// with its pictures inside, writeup.md with figures/ beside it), the same bytes on a second run; a wrong flip_edge
// fails its figures in the grader's words and the pages are still written; a missing folder and bad arguments are
// refused with the usage's statuses.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "app/cli_test_support.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

using testing::run_meshedit;
namespace fs = std::filesystem;

fs::path solutions() { return testing::source_dir() / "tests" / "exercise" / "solutions"; }

TEST(CliWriteup, TheSolutionsGiveEveryFigureOkAndTheSameBytesTwice) {
  const fs::path dir = testing::scratch_dir();
  const auto first =
      run_meshedit({"writeup", "--submission", solutions().string(), "-o", (dir / "one").string()}, "writeup-one");
  ASSERT_EQ(first.status, 0) << first.out << first.err;
  for (const char* number : {"1.1", "1.2", "2.1", "3.1", "4.1", "5.1", "5.2", "5.3", "6.1", "6.2", "6.3", "6.4"}) {
    EXPECT_NE(first.out.find(std::string(number) + " ok\n"), std::string::npos) << number << "\n" << first.out;
  }
  EXPECT_NE(first.out.find("0 figures have problems"), std::string::npos) << first.out;
  const auto second =
      run_meshedit({"writeup", "--submission", solutions().string(), "-o", (dir / "two").string()}, "writeup-two");
  ASSERT_EQ(second.status, 0) << second.err;
  const std::string page = testing::read_text(dir / "one" / "index.html");
  EXPECT_NE(page.find("src=\"data:image/png;base64,"), std::string::npos);
  EXPECT_EQ(page, testing::read_text(dir / "two" / "index.html"));
  size_t pictures = 0;
  for (const auto& entry : fs::directory_iterator(dir / "one" / "figures")) {
    const std::string png = testing::read_text(entry.path());
    EXPECT_GT(png.size(), 1000u) << entry.path();
    EXPECT_EQ(png.substr(1, 3), "PNG");
    EXPECT_EQ(png, testing::read_text(dir / "two" / "figures" / entry.path().filename())) << entry.path();
    ++pictures;
  }
  EXPECT_GE(pictures, 24u);
  const std::string markdown = testing::read_text(dir / "one" / "writeup.md");
  EXPECT_NE(markdown.find("](figures/4.1-a.png)"), std::string::npos);
}

TEST(CliWriteup, AWrongFlipFailsItsFiguresInTheGradersWordsAndThePagesAreStillWritten) {
  const fs::path dir = testing::scratch_dir();
  const fs::path folder = dir / "student";
  fs::create_directories(folder);
  for (const auto& entry : fs::directory_iterator(solutions()))
    fs::copy_file(entry.path(), folder / entry.path().filename());
  fs::copy_file(testing::source_dir() / "tests" / "grading" / "students" / "flip_forgets_faces.lua",
                folder / "flip.lua", fs::copy_options::overwrite_existing);
  const auto run =
      run_meshedit({"writeup", "--submission", folder.string(), "-o", (dir / "out").string()}, "writeup-wrong-flip");
  EXPECT_EQ(run.status, 1) << run.out << run.err;
  EXPECT_NE(run.out.find("4.1 problem: flipping e"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("after your flip_edge the mesh is not valid"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("3.1 ok\n"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("6.1 ok\n"), std::string::npos) << run.out;
  EXPECT_TRUE(fs::is_regular_file(dir / "out" / "index.html"));
  EXPECT_NE(testing::read_text(dir / "out" / "index.html").find("after your flip_edge the mesh is not valid"),
            std::string::npos);
}

TEST(CliWriteup, AMissingFolderAndBadArgumentsAreRefused) {
  const fs::path dir = testing::scratch_dir();
  const auto missing = run_meshedit(
      {"writeup", "--submission", (dir / "nowhere").string(), "-o", (dir / "out").string()}, "writeup-gone");
  EXPECT_EQ(missing.status, 1);
  EXPECT_NE(missing.err.find("nowhere"), std::string::npos) << missing.err;
  const auto no_output = run_meshedit({"writeup", "--submission", solutions().string()}, "writeup-no-output");
  EXPECT_EQ(no_output.status, 2);
  EXPECT_NE(no_output.err.find("writeup needs -o OUT"), std::string::npos) << no_output.err;
}

}  // namespace
}  // namespace meshedit
