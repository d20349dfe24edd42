// live, plot, arrow, curve_t and curve_points on a LessonRunner with a HeadlessHost: live text follows the selection
// and the curve view's t at each update, a live error shows its line once and stops that block while the step goes on,
// a runaway live block stops at its own budget, arrows reach the host and go with the step, a plot is sampled once with
// its marker following t, and bad arguments are `lesson.lua:N:` errors.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/palette.h"
#include "lesson/headless_host.h"
#include "lesson/lesson_runner.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

using Strings = std::vector<std::string>;
using State = LessonRunner::StepState;

std::filesystem::path write_lesson(const std::string& text) {
  const auto path = testing::scratch_dir() / "lesson.lua";
  std::ofstream(path) << text;
  return path;
}

TEST(LessonDisplays, LiveTextFollowsTheSelectionAndTheCurvesT) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(write_lesson(R"lua(local grid = meshedit.grid(1, 1)
step("Selection", function()
  show(grid)
  say "Pick something."
  live(function() return "selected: " .. tostring(selection()) end)
  wait_for { button = "Continue" }
end)
step("Curve", function()
  show { {0, 0}, {1, 2}, {3, 2}, {4, 0} }
  live(function()
    local p = curve_points()
    return string.format("t = %.2f, %d points, last x = %g", curve_t(), #p, p[#p].x)
  end)
end)
step("No curve", function()
  show(grid)
  live(function() return tostring(curve_t()) .. " " .. tostring(curve_points()) end)
end)
)lua")))
      << runner.error();
  ASSERT_EQ(runner.lives().size(), 1u) << runner.error();
  EXPECT_EQ(runner.lives()[0].text, "selected: nil");  // evaluated when live() ran
  EXPECT_EQ(runner.lives()[0].where, "lesson.lua:5");
  ASSERT_EQ(runner.blocks().size(), 2u);
  EXPECT_EQ(runner.blocks()[1].kind, LessonBlock::Kind::Live);
  host.set_selection(ElementRef(EdgeId(2)));
  EXPECT_EQ(runner.lives()[0].text, "selected: nil");  // not before the next frame
  runner.update(0.016);
  EXPECT_EQ(runner.lives()[0].text, "selected: e2");
  EXPECT_EQ(runner.step_state(), State::Waiting);  // reading the view resumes nothing

  runner.next();  // a finished step's live text follows the view too
  EXPECT_EQ(runner.step_state(), State::Finished) << runner.error();
  EXPECT_EQ(runner.lives().at(0).text, "t = 0.50, 4 points, last x = 4");
  host.set_curve_t(0.25);
  runner.refresh_live();
  EXPECT_EQ(runner.lives()[0].text, "t = 0.25, 4 points, last x = 4");

  runner.next();
  EXPECT_EQ(runner.lives().at(0).text, "nil nil");
}

TEST(LessonDisplays, ALiveErrorShowsItsLineOnceAndStopsOnlyThatBlock) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(write_lesson(R"lua(calls = 0
step("Live errors", function()
  show(meshedit.cube())
  live(function()
    calls = calls + 1
    if selection() then error("nothing may be selected") end
    return "calls " .. calls
  end)
  live(function() say("no") end)
  live(function() return selection() and "something" or "nothing" end)
  wait_for { button = "Continue" }
  say("still running")
end)
)lua")))
      << runner.error();
  ASSERT_EQ(runner.lives().size(), 3u) << runner.error();
  EXPECT_EQ(runner.lives()[0].text, "calls 1");
  EXPECT_EQ(runner.lives()[1].error,
            "lesson.lua:9: say() cannot be used in a live() function or a plot's marker: they only read the view");
  runner.update(0.016);
  EXPECT_EQ(runner.lives()[0].text, "calls 2");
  host.set_selection(ElementRef(VertexId(0)));
  runner.update(0.016);
  EXPECT_EQ(runner.lives()[0].error, "lesson.lua:6: nothing may be selected");
  EXPECT_EQ(runner.lives()[0].text, "calls 2");  // the last value it had
  EXPECT_EQ(runner.lives()[2].text, "something");
  runner.update(0.016);
  runner.update(0.016);
  EXPECT_EQ(runner.lives()[0].error, "lesson.lua:6: nothing may be selected");
  runner.restart_step();  // the error went with the step (and show() cleared the selection): the block runs again
  EXPECT_EQ(runner.lives().at(0).error, "");
  EXPECT_EQ(runner.lives().at(0).text, "calls 4");
  EXPECT_TRUE(runner.deliver(LessonEvent::button("Continue")));
  EXPECT_EQ(runner.said(), Strings{"still running"});
  EXPECT_EQ(runner.error(), "");
}

TEST(LessonDisplays, ARunawayLiveBlockStopsAtItsOwnBudgetAndTheStepGoesOn) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(write_lesson(R"lua(step("Runaway", function()
  live(function()
    if selection() then while true do end end
    return "idle"
  end)
  wait_for { button = "Continue" }
  say("after")
end)
)lua")))
      << runner.error();
  EXPECT_EQ(runner.lives().at(0).text, "idle");
  host.set_selection(ElementRef(VertexId(0)));
  runner.update(0.016);
  const std::string error = runner.lives()[0].error;
  EXPECT_EQ(error.rfind("lesson.lua:3: ", 0), 0u) << error;
  // The live block's own budget: its instructions, or its wall time on a busy machine, whichever ends first.
  EXPECT_TRUE(error.find("instruction budget exceeded (2000000 instructions)") != std::string::npos ||
              error.find("time limit exceeded (0.05 s)") != std::string::npos)
      << error;
  EXPECT_EQ(runner.step_state(), State::Waiting);
  EXPECT_TRUE(runner.deliver(LessonEvent::button("Continue")));  // the step's own budget is whole
  EXPECT_EQ(runner.said(), Strings{"after"});
}

TEST(LessonDisplays, ArrowsReachTheHostAndGoWithTheStep) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(write_lesson(R"lua(step("Arrows", function()
  arrow({0, 0, 0}, meshedit.vec3(0, 0, 1), "blue")
  arrow({x = 1, y = 2, z = 3}, {1, 2, 4})
end)
step("None", function() end)
step("Bad", function() arrow({0, 0, 0}) end)
step("Bad colour", function() arrow({0, 0, 0}, {1, 1, 1}, "teal") end)
)lua")))
      << runner.error();
  EXPECT_EQ(runner.step_state(), State::Finished) << runner.error();
  EXPECT_EQ(host.calls(),
            (Strings{"clear_annotations", "arrow (0, 0, 0) -> (0, 0, 1) " + colour_hex(kDarkSwatches.blue),
                     "arrow (1, 2, 3) -> (1, 2, 4) " + colour_hex(palette_for(Theme::Dark).lesson_highlight)}));
  ASSERT_EQ(host.arrows().size(), 2u);
  EXPECT_EQ(host.arrows()[1].to, glm::dvec3(1, 2, 4));
  runner.next();
  EXPECT_TRUE(host.arrows().empty());
  runner.next();
  EXPECT_EQ(runner.error(),
            "lesson.lua:6: arrow: the second (where it points) point must be {x, y, z} or a vec3 of "
            "finite numbers, got no value");
  runner.next();
  EXPECT_EQ(runner.error().rfind("lesson.lua:7: unknown colour 'teal'", 0), 0u) << runner.error();
}

TEST(LessonDisplays, APlotIsSampledOnceAndItsMarkerFollowsT) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(write_lesson(R"lua(calls = 0
step("Plot", function()
  show { {0, 0}, {1, 2}, {3, 2}, {4, 0} }
  plot {
    title = "Bernstein weights", x = {0, 1}, samples = 4,
    curves = {
      { label = "B0", fn = function(t) calls = calls + 1 return (1 - t) ^ 3 end, colour = "orange" },
      { fn = function(t) return 3 * t * (1 - t) ^ 2 end },
    },
    marker = function() return curve_t() end,
  }
  say("sampled " .. calls)
end)
)lua")))
      << runner.error();
  ASSERT_EQ(runner.plots().size(), 1u) << runner.error();
  const LessonPlot& plot = runner.plots()[0];
  EXPECT_EQ(plot.title, "Bernstein weights");
  EXPECT_EQ(plot.where, "lesson.lua:4");
  ASSERT_EQ(plot.curves.size(), 2u);
  EXPECT_EQ(plot.curves[0].label, "B0");
  EXPECT_EQ(plot.curves[0].colour, kDarkSwatches.orange);
  EXPECT_EQ(plot.curves[1].label, "curve 2");
  EXPECT_EQ(plot.curves[1].colour, kDarkSwatches.orange);  // the second colour in turn
  ASSERT_EQ(plot.curves[0].points.size(), 5u);
  EXPECT_EQ(plot.curves[0].points[1], glm::dvec2(0.25, 0.421875));
  EXPECT_EQ(plot.curves[1].points[2], glm::dvec2(0.5, 0.375));
  EXPECT_EQ(plot.y_range, glm::dvec2(0.0, 1.0));  // the samples' own range
  EXPECT_EQ(plot_value(plot.curves[1], 0.375), 0.5 * (0.421875 + 0.375));
  EXPECT_EQ(runner.said(), Strings{"sampled 5"});
  ASSERT_TRUE(plot.marker);
  EXPECT_EQ(*plot.marker, 0.5);
  host.set_curve_t(0.75);
  runner.update(0.016);
  EXPECT_EQ(*runner.plots()[0].marker, 0.75);
  EXPECT_EQ(runner.plots()[0].curves[0].points.size(), 5u);
  host.set_curve_t(0.0);
  runner.refresh_live();
  EXPECT_EQ(*runner.plots()[0].marker, 0.0);
  EXPECT_EQ(runner.blocks().at(0).kind, LessonBlock::Kind::Plot);
  EXPECT_EQ(runner.error(), "");
}

TEST(LessonDisplays, BadPlotsNameTheFieldAndTheLine) {
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(write_lesson(R"lua(local ok = { fn = function(t) return t end }
step("1", function() plot { curves = {} } end)
step("2", function() plot { x = {1, 0}, curves = { ok } } end)
step("3", function() plot { curves = { { label = "B9", fn = function(t) return t <= 0.5 and t or nil end } } } end)
step("4", function() plot { curves = { ok }, marker = 3 } end)
step("5", function() plot { curves = { ok }, colour = "red" } end)
step("6", function() plot { curves = { ok }, marker = function() return "left" end } say("goes on") end)
step("7", function() plot { curves = { { fn = ok.fn, width = 2 } } } end)
)lua")))
      << runner.error();
  const Strings expected = {
      "lesson.lua:2: plot: curves must be a list like {{label = \"B0\", fn = function(x) ... end}, ...}",
      "lesson.lua:3: plot: x must be two increasing numbers like {0, 1}",
      "lesson.lua:4: plot: 'B9' gave nil at x = 0.51 (fn must return a number)",
      "lesson.lua:5: plot: marker must be function() return x end, got number",
      "lesson.lua:6: plot: unknown field 'colour' (fields: title, x, y, samples, curves, marker)",
      "",
      "lesson.lua:8: plot: curve 1: unknown field 'width' (fields: label, fn, colour, color)",
  };
  for (size_t i = 0; i < expected.size(); ++i) {
    runner.go_to(i);
    EXPECT_EQ(runner.error(), expected[i]) << "step " << i + 1;
  }
  runner.go_to(5);  // a marker's error stops the marker, not the step
  EXPECT_EQ(runner.step_state(), State::Finished);
  EXPECT_EQ(runner.plots().at(0).error, "lesson.lua:7: plot: the marker must return a number or nil, got string");
  EXPECT_EQ(runner.said(), Strings{"goes on"});
}

}  // namespace
}  // namespace meshedit
