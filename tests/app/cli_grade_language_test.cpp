// `meshedit grade` writes its feedback in the course's language: the suite's `language` (English by default) or
// --language, which the window's Check my work passes with its own. English is word for word what it was; a language
// it does not know is refused with its name.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "app/cli_test_support.h"
#include "io/file_access.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;
using testing::CommandRun;

CommandRun meshedit(const std::vector<std::string>& args) { return testing::run_meshedit(args, "cli-grade-language"); }

// The output of the first test the submission fails, from results.json.
std::string first_failure(const fs::path& results) {
  const nlohmann::json json = nlohmann::json::parse(read_file(results));
  for (const auto& test : json["tests"]) {
    if (test["score"].get<double>() < test["max_score"].get<double>()) return test["output"].get<std::string>();
  }
  return "";
}

TEST(CliGradeLanguage, TheFeedbackIsInTheSuitesLanguageOrTheOneAskedFor) {
  const fs::path dir = testing::scratch_dir();
  const fs::path source = testing::source_dir();
  fs::create_directories(dir / "submission");
  fs::copy_file(source / "tests/grading/students/flip_breaks_face_cycle.lua", dir / "submission/flip.lua",
                fs::copy_options::overwrite_existing);
  const std::string suite = (source / "tests/grading/suites/flip.lua").string();
  const auto grade = [&](const std::string& suite_file, const std::vector<std::string>& more, const char* name) {
    std::vector<std::string> args = {"grade",
                                     "--suite",
                                     suite_file,
                                     "--submission",
                                     (dir / "submission").string(),
                                     "--results",
                                     (dir / name).string()};
    args.insert(args.end(), more.begin(), more.end());
    const CommandRun run = meshedit(args);
    EXPECT_EQ(run.status, 0) << run.err;
    return first_failure(dir / name);
  };
  const std::string english = grade(suite, {}, "en.json");
  EXPECT_NE(english.find("**Failed:**"), std::string::npos) << english;
  EXPECT_NE(english.find("`h5.next` is still `h3` after your flip\\_edge, as before the call"), std::string::npos)
      << english;

  const std::string chinese = grade(suite, {"--language", "zh"}, "zh.json");
  EXPECT_NE(chinese.find("**未通过：**"), std::string::npos) << chinese;
  EXPECT_NE(chinese.find("调用你的 flip\\_edge 之后，`h5.next` 仍是 `h3`"), std::string::npos) << chinese;

  // suite{ language = "zh" } in the course's suite file: the same words without --language; --language en wins.
  const fs::path zh_suite = dir / "flip.lua";
  std::ofstream(zh_suite) << "suite { language = \"zh\" }\n" << read_file(suite);
  EXPECT_EQ(grade(zh_suite.string(), {}, "suite_zh.json"), chinese);
  EXPECT_EQ(grade(zh_suite.string(), {"--language", "en"}, "suite_en.json"), english);
}

TEST(CliGradeLanguage, ALanguageItDoesNotKnowIsRefusedWithItsName) {
  const fs::path dir = testing::scratch_dir();
  const fs::path suite = dir / "fr.lua";
  std::ofstream(suite) << "suite { language = \"fr\" }\ntest { name = \"t\", run = function() end }\n";
  fs::create_directories(dir / "empty");
  const CommandRun bad_suite = meshedit({"grade", "--suite", suite.string(), "--submission", (dir / "empty").string()});
  EXPECT_NE(bad_suite.status, 0);
  EXPECT_NE(bad_suite.err.find("fr.lua:1: field 'language' must be en or zh"), std::string::npos) << bad_suite.err;
  const CommandRun bad_option =
      meshedit({"grade", "--suite", suite.string(), "--submission", (dir / "empty").string(), "--language", "fr"});
  EXPECT_EQ(bad_option.status, 2);
  EXPECT_NE(bad_option.err.find("--language fr: the feedback is written in en or zh"), std::string::npos)
      << bad_option.err;
}

}  // namespace
}  // namespace meshedit
