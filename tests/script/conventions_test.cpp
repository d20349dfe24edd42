// What the templates, lessons and docs say about walks and names, held to what the mesh does. The facts are
// measured on real meshes by Lua scripts run through the built binary (`meshedit run`,
// tests/script/conventions/*.lua); the tests then look for the sentence that states each fact in every file that
// states it. A file that says the opposite, or a core that starts turning the other way, fails here. Skips when
// the binary has not been built (this binary links the script module only; build the `meshedit` target first).
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <regex>
#include <sstream>
#include <string>

#include "support/test_support.h"

namespace meshedit {
namespace {

// "key: value" lines the script printed, by key; a failed expectation when it did not run cleanly.
std::map<std::string, std::string> run_facts(const std::string& script) {
  const auto dir = testing::scratch_dir();
  const auto out = dir / "stdout.txt", err = dir / "stderr.txt";
  const std::string command = "'" + std::string(MESHEDIT_BINARY) + "' run '" +
                              (testing::source_dir() / "tests/script/conventions" / script).string() + "' >'" +
                              out.string() + "' 2>'" + err.string() + "'";
  const int raw = std::system(command.c_str());
  EXPECT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) == 0) << script << ": " << testing::read_text(err);
  std::map<std::string, std::string> facts;
  std::istringstream lines(testing::read_text(out));
  for (std::string line; std::getline(lines, line);) {
    const size_t colon = line.find(": ");
    if (colon != std::string::npos) facts[line.substr(0, colon)] = line.substr(colon + 2);
  }
  return facts;
}

using testing::words_of;

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::string opposite(const std::string& sense) { return sense == "clockwise" ? "counter-clockwise" : "clockwise"; }

TEST(Conventions, EveryFileThatStatesTheVertexWalkGivesTheDirectionTheMeshTurns) {
  if (!std::filesystem::exists(MESHEDIT_BINARY)) GTEST_SKIP() << "meshedit not built";
  const auto facts = run_facts("walk_directions.lua");
  const std::string sense = facts.count("vertex walk") ? facts.at("vertex walk") : "";
  ASSERT_TRUE(sense == "clockwise" || sense == "counter-clockwise") << sense;
  for (const char* file :
       {"engine/core/halfedge_mesh.h", "scripts/api/README.md", "scripts/api/meshedit.lua",
        "scripts/student/normals.lua", "scripts/student/upsample.lua", "lessons/3_halfedge_walks.lua"}) {
    const std::string words = words_of(file);
    EXPECT_TRUE(contains(words, "turns " + sense + " around")) << file << " does not say h.twin.next turns " << sense;
    EXPECT_FALSE(contains(words, "turns " + opposite(sense) + " around")) << file;
  }
}

TEST(Conventions, EveryFileThatStatesTheFaceWalkGivesTheDirectionTheMeshTurns) {
  if (!std::filesystem::exists(MESHEDIT_BINARY)) GTEST_SKIP() << "meshedit not built";
  const auto facts = run_facts("walk_directions.lua");
  const std::string sense = facts.count("face walk") ? facts.at("face walk") : "";
  ASSERT_TRUE(sense == "clockwise" || sense == "counter-clockwise") << sense;
  const std::map<std::string, std::string> sentences{
      {"engine/core/halfedge_mesh.h", "`next` goes " + sense + " around a face"},
      {"scripts/api/README.md", "`h.next` goes " + sense + " around a face"},
      {"scripts/student/normals.lua", "each face's own next goes " + sense},
      {"lessons/3_halfedge_walks.lua", "the following halfedge around the same face, " + sense + "."},
  };
  for (const auto& [file, sentence] : sentences) EXPECT_TRUE(contains(words_of(file), sentence)) << file;
}

TEST(Conventions, TheUpsampleTemplateListsTheHalfedgesAroundASplitVertexInWalkOrder) {
  if (!std::filesystem::exists(MESHEDIT_BINARY)) GTEST_SKIP() << "meshedit not built";
  const auto facts = run_facts("walk_directions.lua");
  ASSERT_EQ(facts.count("split interior"), 1u);
  ASSERT_EQ(facts.count("split boundary"), 1u);
  EXPECT_EQ(facts.at("split interior"), "a, c, b, d");  // mesh_ops.h: m.halfedge = n1 (m->a), then n2, h0, n4
  EXPECT_EQ(facts.at("split boundary"), "a, c, b");
  const std::string words = words_of("scripts/student/upsample.lua");
  EXPECT_TRUE(contains(words, "for an interior edge: to " + facts.at("split interior") + ";"));
  EXPECT_TRUE(contains(words, "on a boundary edge three: to " + facts.at("split boundary") + ")"));
}

TEST(Conventions, TheFlipTemplateAndLessonMapTheCoursesLettersToOurs) {
  if (!std::filesystem::exists(MESHEDIT_BINARY)) GTEST_SKIP() << "meshedit not built";
  const auto facts = run_facts("course_flip_letters.lua");
  ASSERT_EQ(facts.count("ours for course a b c d"), 1u);
  ASSERT_EQ(facts.count("course after"), 1u);
  // The handout's flip turns (a, b, c), (c, b, d) into (a, d, c), (a, b, d); ours gives those two (f0 first).
  EXPECT_EQ(facts.at("course after"), "(a, b, d), (a, d, c)");
  const std::string ours = facts.at("ours for course a b c d");
  EXPECT_EQ(ours, "c a b d");

  // flip.lua's table: a "course a b c d" row, then an "ours" row under it.
  const std::string flip = testing::read_text(testing::source_dir() / "scripts/student/flip.lua");
  std::smatch table;
  ASSERT_TRUE(std::regex_search(
      flip, table, std::regex(R"(-- +course +a +b +c +d [^\n]*\n-- +ours +([a-d]) +([a-d]) +([a-d]) +([a-d]) )")))
      << "flip.lua has no course / ours table";
  EXPECT_EQ(table[1].str() + " " + table[2].str() + " " + table[3].str() + " " + table[4].str(), ours);

  // Lesson 4's list: "course a, b, c, d = our c, a, b, d".
  std::string listed;
  for (char letter : ours) listed += letter == ' ' ? std::string(", ") : std::string(1, letter);
  EXPECT_TRUE(contains(words_of("lessons/4_edge_flip.lua"), "- course a, b, c, d = our " + listed + " -")) << listed;
}

}  // namespace
}  // namespace meshedit
