// The languages, templates and PO catalogs of core/translation.h, and the shipped catalogs: each entry's placeholders
// are its English's, and the window's texts come back in English unchanged.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "core/translation.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

// Puts the window back in English with the shipped catalogs, whatever a test chose.
struct WindowLanguageGuard {
  ~WindowLanguageGuard() {
    set_catalog(Language::Chinese, read_catalog(Language::Chinese, testing::source_dir() / "assets/translations"));
    set_text_language(Language::English);
  }
};

TEST(Translation, LanguagesAreFoundByCodeAndByLocale) {
  EXPECT_EQ(language_by_code("zh"), Language::Chinese);
  EXPECT_EQ(language_by_code("zh_CN.UTF-8"), Language::Chinese);
  EXPECT_EQ(language_by_code("zh-Hans"), Language::Chinese);
  EXPECT_EQ(language_by_code("en_GB"), Language::English);
  EXPECT_EQ(language_by_code("fr"), std::nullopt);
  EXPECT_EQ(language_by_code("C"), std::nullopt);
  EXPECT_STREQ(language_name(Language::Chinese), "简体中文");
  EXPECT_STREQ(language_code(Language::Chinese), "zh");
}

TEST(Translation, TemplatesFillNamedPartsInAnyOrder) {
  const MessageParts parts = {{"count", "3"}, {"file", "cube.obj"}};
  EXPECT_EQ(fill_template("{count} faces reversed in {file}", parts), "3 faces reversed in cube.obj");
  EXPECT_EQ(fill_template("{file} 中有 {count} 个面被翻转", parts), "cube.obj 中有 3 个面被翻转");
  EXPECT_EQ(fill_template("{{count}} stays, {missing} shows", parts), "{count} stays, {missing} shows");
  EXPECT_EQ(placeholder_names("{b} and {a} and {a}, {{c}}, {1x}"), (std::vector<std::string>{"a", "b"}));
}

TEST(Translation, PoEntriesAreReadWithContinuationsEscapesAndFuzzyLeftOut) {
  Catalog catalog;
  catalog.read_po_text(
      "msgid \"\"\nmsgstr \"Content-Type: text/plain; charset=UTF-8\\n\"\n\n"
      "#: engine/app/editor_menus.cpp\nmsgid \"Open...\"\nmsgstr \"打开...\"\n\n"
      "msgid \"a \\\"quoted\\\" \"\n\"text\"\nmsgstr \"\"\n\"带“引号”的文字\"\n\n"
      "#, fuzzy\nmsgid \"Save\"\nmsgstr \"保存\"\n\nmsgid \"Not yet\"\nmsgstr \"\"\n",
      "zh/test.po");
  EXPECT_TRUE(catalog.problems().empty()) << catalog.problems().front();
  ASSERT_NE(catalog.find("Open..."), nullptr);
  EXPECT_EQ(*catalog.find("Open..."), "打开...");
  ASSERT_NE(catalog.find("a \"quoted\" text"), nullptr);
  EXPECT_EQ(*catalog.find("a \"quoted\" text"), "带“引号”的文字");
  EXPECT_EQ(catalog.find("Save"), nullptr) << "a fuzzy entry is not a translation yet";
  EXPECT_EQ(catalog.find("Not yet"), nullptr) << "an empty msgstr is not translated";
  EXPECT_EQ(catalog.size(), 2u);
}

TEST(Translation, APlaceholderMismatchIsAnErrorNamingBothTextsAndTheEntryIsLeftOut) {
  Catalog catalog;
  catalog.read_po_text("msgid \"{count} faces in {file}\"\nmsgstr \"{count} 个面\"\n\nmsgid \"x\"\nnot po\n",
                       "zh/app.po");
  ASSERT_EQ(catalog.problems().size(), 2u);
  EXPECT_EQ(catalog.problems()[1], "zh/app.po:5: not a PO line (a keyword and a \"quoted\" text): not po");
  EXPECT_EQ(catalog.problems()[0],
            "zh/app.po:1: the translation \"{count} 个面\" has placeholders {count} where its English \"{count} faces "
            "in {file}\" has {count}, {file}");
  EXPECT_EQ(catalog.find("{count} faces in {file}"), nullptr);
}

TEST(Translation, TheWindowIsEnglishByteForByteAndChineseWhereTheCatalogSays) {
  WindowLanguageGuard guard;
  Catalog catalog;
  catalog.add("Lesson", "课程", "test");
  catalog.add("{count} faces", "{count} 个面", "test");
  set_catalog(Language::Chinese, catalog);
  const char* english = "Lesson";
  set_text_language(Language::English);
  EXPECT_EQ(tr(english), english) << "English is the very pointer the code gave";
  EXPECT_EQ(tr_label(english), english);
  set_text_language(Language::Chinese);
  EXPECT_STREQ(tr(english), "课程");
  EXPECT_STREQ(tr_label("Lesson"), "课程###Lesson") << "the ImGui id stays the English";
  EXPECT_STREQ(tr_label("Lesson##left"), "课程###Lesson##left");
  EXPECT_STREQ(tr("Untranslated"), "Untranslated") << "a text without a translation shows in English";
  EXPECT_EQ(tr_format("{count} faces", {{"count", "12"}}), "12 个面");
  const LocalText both = local_format("{count} faces", {{"count", "12"}});
  EXPECT_EQ(both.english(), "12 faces");
  EXPECT_EQ(both.in(Language::Chinese), "12 个面");
}

TEST(Translation, EveryShippedCatalogReadsWithoutAProblem) {
  const Catalog catalog = read_catalog(Language::Chinese, testing::source_dir() / "assets/translations");
  for (const std::string& problem : catalog.problems()) ADD_FAILURE() << problem;
  EXPECT_GT(catalog.size(), 400u);
  ASSERT_NE(catalog.find("Press {what}"), nullptr) << "the lesson runner's default hints are translated";
}

TEST(Translation, AMissingCatalogFolderIsNamedAndTheWindowStaysEnglish) {
  const Catalog catalog = read_catalog(Language::Chinese, testing::source_dir() / "no such folder");
  ASSERT_EQ(catalog.problems().size(), 1u);
  EXPECT_NE(catalog.problems()[0].find("no translations of 简体中文 in"), std::string::npos) << catalog.problems()[0];
  EXPECT_EQ(catalog.size(), 0u);
}

}  // namespace
}  // namespace meshedit
