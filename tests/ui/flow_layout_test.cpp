// Text wrapped at spaces only (ui/flow_layout.h): a lesson's numbers and a repair's ranges never split where ImGui's
// own wrapping would break them (after a full stop or a comma); every line fits the width unless it is one word; the
// text's own line breaks stay; nothing else changes.
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include <imgui.h>

#include "support/imgui_harness.h"
#include "ui/flow_layout.h"

namespace meshedit {
namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST(FlowLayout, TextWrapsAtSpacesOnlyAndKeepsItsOwnBreaks) {
  ui_testing::ImGuiHarness imgui;
  const std::string text =
      "The core moves v0 to (-0.2778, -0.2778, -0.2778) (blue arrow): 5/9 of its distance "
      "from the centre.\nfaces 2..4 and 10..17 reversed";
  imgui.frame([&] {
    for (const float width : {60.0f, 110.0f, 170.0f, 400.0f}) {
      const std::string wrapped = wrapped_at_spaces(text, width);
      // Only spaces became line breaks: with them put back, the text is what it was.
      std::string back = wrapped;
      std::string original = text;
      std::replace(back.begin(), back.end(), '\n', ' ');
      std::replace(original.begin(), original.end(), '\n', ' ');
      EXPECT_EQ(back, original) << width;
      for (const std::string& line : lines_of(wrapped)) {
        const bool one_word = line.find(' ') == std::string::npos;
        EXPECT_TRUE(one_word || ImGui::CalcTextSize(line.c_str()).x <= width) << width << ": '" << line << "'";
      }
      EXPECT_NE(wrapped.find("-0.2778"), std::string::npos) << wrapped;
      EXPECT_NE(wrapped.find("10..17"), std::string::npos) << wrapped;
      EXPECT_NE(wrapped.find("centre.\nfaces"), std::string::npos) << "the text's own break stays: " << wrapped;
    }
    // A width that ends inside the second number: the whole number goes to the next line.
    const float narrow = ImGui::CalcTextSize("to (-0.2778, -0.").x + 1.0f;
    EXPECT_EQ(wrapped_at_spaces("to (-0.2778, -0.2778)", narrow), "to (-0.2778,\n-0.2778)");
  });
}

}  // namespace
}  // namespace meshedit
