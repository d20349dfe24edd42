// A lesson's texts in two languages (lesson/lesson_texts.h): the logic sees the English, the runner keeps the Chinese
// for the panel, and what is wrong with a translation is named with the lesson's line. The shipped lessons the course
// ships (welcome, 1 to 7 and the scan to repair) have a Chinese twin for every text their runs show, each keeping its
// English's code and numbers.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "exercise/exercise_registry.h"
#include "lesson/headless_host.h"
#include "lesson/lesson_headless.h"
#include "lesson/lesson_runner.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

std::filesystem::path write_lesson(const std::string& text, const std::string& name) {
  const auto path = testing::scratch_dir() / name;
  std::ofstream(path) << text;
  return path;
}

TEST(LessonTexts, TheLogicSeesTheEnglishAndThePanelGetsTheChinese) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(write_lesson(R"lua(lesson { title = { en = "Flips", zh = "翻转" } }
step({ en = "Pick", zh = "选择" }, function()
  say { en = "The edge `e2` has 2 faces.", zh = "边 `e2` 有 2 个面。" }
  local got = choose {
    { en = "Which one?", zh = "哪一个？" },
    options = { { en = "the left", zh = "左边的" }, "h4" },
    answer = "h4",
    feedback = { ["the left"] = { en = "No: the left is h1.", zh = "不对：左边的是 h1。" } },
  }
  say("got " .. got)
end)
)lua",
                                       "texts.lua")))
      << runner.error();
  EXPECT_EQ(runner.title(), "Flips");
  EXPECT_EQ(runner.step_titles(), std::vector<std::string>{"Pick"});
  ASSERT_EQ(runner.said().size(), 1u);
  const LessonTexts& texts = runner.texts();
  EXPECT_EQ(texts.in(runner.title(), Language::Chinese), "翻转");
  EXPECT_EQ(texts.in(runner.said()[0], Language::Chinese), "边 `e2` 有 2 个面。");
  EXPECT_EQ(texts.in(runner.said()[0], Language::English), "The edge `e2` has 2 faces.");
  const LessonWait& wait = runner.waiting_for();
  ASSERT_EQ(wait.options, (std::vector<std::string>{"the left", "h4"}));
  EXPECT_EQ(texts.in(wait.question, Language::Chinese), "哪一个？");
  EXPECT_EQ(texts.in(wait.options[0], Language::Chinese), "左边的");
  EXPECT_TRUE(runner.deliver(LessonEvent::choice("the left")));
  EXPECT_EQ(runner.waiting_for().feedback, "No: the left is h1.");
  EXPECT_EQ(texts.in(runner.waiting_for().feedback, Language::Chinese), "不对：左边的是 h1。");
  EXPECT_TRUE(runner.deliver(LessonEvent::choice("h4")));
  EXPECT_EQ(runner.said().back(), "got h4") << "choose returns the English option";
  EXPECT_TRUE(texts.problems().empty());
  ASSERT_EQ(texts.untranslated().size(), 1u);
  EXPECT_NE(texts.untranslated()[0].find("texts.lua:10: \"got h4\""), std::string::npos) << texts.untranslated()[0];
}

TEST(LessonTexts, AnUnknownLanguageAndADroppedCodeSpanAreNamedWithTheLineAndTheEnglishShows) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(write_lesson(R"lua(step("One", function()
  say { en = "Hello there", fr = "Bonjour" }
  for _ = 1, 2 do say { en = "Set `h.next` 3 times.", zh = "设置三次。" } end
end)
)lua",
                                       "bad_texts.lua")))
      << runner.error();
  ASSERT_EQ(runner.error(), "");
  const LessonTexts& texts = runner.texts();
  ASSERT_EQ(texts.problems().size(), 2u) << "each place is named once";
  EXPECT_EQ(texts.problems()[0],
            "bad_texts.lua:2: 'fr' is not a language MeshEdit knows (en, zh): the text is shown in English");
  EXPECT_EQ(texts.problems()[1],
            "bad_texts.lua:3: the zh text drops 3, `h.next` of its English, so the English is shown: \"Set `h.next` 3 "
            "times.\" / \"设置三次。\"");
  EXPECT_EQ(texts.in("Set `h.next` 3 times.", Language::Chinese), "Set `h.next` 3 times.");
}

TEST(LessonTexts, ATextTableWithoutEnglishIsAnErrorAtTheLessonsLine) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(write_lesson("step(\"One\", function()\n  say { zh = \"你好\" }\nend)\n", "no_en.lua")));
  EXPECT_NE(runner.error().find("no_en.lua:2: say: expected text"), std::string::npos) << runner.error();
}

// Each shipped lesson, run headless with its answers (and a wrong answer where the answers give one):
// no text the run shows lacks its Chinese twin, and no twin drops its English's code or numbers.
TEST(LessonTexts, EveryTranslatedLessonHasAChineseTwinForEveryTextItShows) {
  const auto source = testing::source_dir();
  ASSERT_EQ(load_exercise_folder(source / "scripts" / "exercises"), std::vector<std::string>{});  // as the CLI does
  for (const char* stem : {"welcome", "1_de_casteljau", "2_bezier_patches", "3_halfedge_walks", "4_edge_flip",
                           "5_edge_split", "6_loop_subdivision", "7_catmull_clark", "byo_mesh"}) {
    SCOPED_TRACE(stem);
    std::ostringstream out;
    const HeadlessOutcome outcome =
        run_lesson_headless(source / "lessons" / (std::string(stem) + ".lua"),
                            source / "tests" / "lesson" / "lessons" / (std::string(stem) + "_answers.lua"), out,
                            LessonRunner::default_limits(), source / "tests" / "exercise" / "solutions");
    ASSERT_EQ(outcome.failure, "") << out.str();
    for (const std::string& problem : outcome.text_problems) ADD_FAILURE() << problem;
    for (const std::string& text : outcome.untranslated) ADD_FAILURE() << "no zh twin: " << text;
  }
}

}  // namespace
}  // namespace meshedit
