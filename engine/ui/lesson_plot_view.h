// A lesson's plot{} (lesson/lesson_blocks.h) drawn into the lesson panel with ImGui's draw list: its title, a framed
// area with the curves as polylines in their colours (each named swatch in the theme's shade), the marker as a
// vertical line with a dot where it meets each curve, the ranges at the corners, and a legend giving each curve's value
// at the marker.
//
// Invariants: it draws only what the plot holds (sampled once by the runner), so a frame costs no Lua call; points
// outside the y range are clipped to the frame; a marker outside the x range (or none) draws no line; a plot whose
// marker failed shows the marker's error under it in the palette's error colour.
#pragma once

#include "lesson/lesson_blocks.h"
#include "lesson/lesson_runner.h"

namespace meshedit {

// Draws `plot` at the cursor, as wide as the content region; needs a current ImGui window.
void draw_lesson_plot(const LessonRunner& runner, const LessonPlot& plot);

}  // namespace meshedit
