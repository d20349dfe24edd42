// draw_lesson_plot (see lesson_plot_view.h).
#include "ui/lesson_plot_view.h"

#include <algorithm>
#include <string>
#include <vector>

#include <imgui.h>

#include "core/value_format.h"
#include "ui/flow_layout.h"
#include "ui/lesson_question_view.h"
#include "ui/theme.h"

namespace meshedit {
namespace {

std::string number_text(double value) { return format_rounded(value, 3); }

// Maps plot coordinates to the screen rectangle [min, max] (y up).
struct PlotFrame {
  ImVec2 min, max;
  glm::dvec2 x_range, y_range;

  ImVec2 to_screen(double x, double y) const {
    const double sx = (x - x_range[0]) / (x_range[1] - x_range[0]);
    const double sy = std::clamp((y - y_range[0]) / (y_range[1] - y_range[0]), 0.0, 1.0);
    return ImVec2(min.x + float(sx) * (max.x - min.x), max.y - float(sy) * (max.y - min.y));
  }
};

}  // namespace

void draw_lesson_plot(const LessonRunner& runner, const LessonPlot& plot) {
  const Palette& palette = ui_palette();
  const Theme theme = ui_theme();
  if (!plot.title.empty()) ImGui::TextUnformatted(lesson_text(runner, plot.title).c_str());
  const float line = ImGui::GetTextLineHeight();
  const float width = std::max(ImGui::GetContentRegionAvail().x, line * 6.0f);
  const float height = std::clamp(width * 0.55f, line * 5.0f, line * 12.0f);
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::Dummy(ImVec2(width, height));

  // A tenth of the range above and below, so the curves do not run along the frame.
  const double pad = 0.1 * (plot.y_range[1] - plot.y_range[0]);
  const std::string y_top = number_text(plot.y_range[1]), y_bottom = number_text(plot.y_range[0]);
  const float left = std::max(ImGui::CalcTextSize(y_top.c_str()).x, ImGui::CalcTextSize(y_bottom.c_str()).x) + 6.0f;
  PlotFrame frame{ImVec2(origin.x + left, origin.y + 2.0f), ImVec2(origin.x + width - 2.0f, origin.y + height - line),
                  plot.x_range, glm::dvec2(plot.y_range[0] - pad, plot.y_range[1] + pad)};
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(frame.min, frame.max, im_colour_u32(palette.neutrals.canvas));
  const ImU32 grid = im_colour_u32(palette.swatches.grey, 0.6f);
  for (const double y : {plot.y_range[0], plot.y_range[1]}) {
    draw->AddLine(frame.to_screen(plot.x_range[0], y), frame.to_screen(plot.x_range[1], y), grid);
  }
  draw->AddRect(frame.min, frame.max, im_colour_u32(palette.swatches.grey));
  const ImU32 text = ImGui::GetColorU32(ImGuiCol_Text);
  draw->AddText(ImVec2(origin.x, frame.to_screen(0, plot.y_range[1]).y - line * 0.5f), text, y_top.c_str());
  draw->AddText(ImVec2(origin.x, frame.to_screen(0, plot.y_range[0]).y - line * 0.5f), text, y_bottom.c_str());
  const std::string x_left = number_text(plot.x_range[0]), x_right = number_text(plot.x_range[1]);
  draw->AddText(ImVec2(frame.min.x, frame.max.y), text, x_left.c_str());
  draw->AddText(ImVec2(frame.max.x - ImGui::CalcTextSize(x_right.c_str()).x, frame.max.y), text, x_right.c_str());

  draw->PushClipRect(frame.min, frame.max, true);
  std::vector<ImVec2> points;
  for (const LessonPlotCurve& curve : plot.curves) {
    points.clear();
    for (const glm::dvec2& p : curve.points) points.push_back(frame.to_screen(p.x, p.y));
    draw->AddPolyline(points.data(), int(points.size()), im_colour_u32(swatch_in_theme(curve.colour, theme)), 0, 2.0f);
  }
  const bool marked = plot.marker && *plot.marker >= plot.x_range[0] && *plot.marker <= plot.x_range[1];
  if (marked) {
    const double x = *plot.marker;
    draw->AddLine(frame.to_screen(x, frame.y_range[0]), frame.to_screen(x, frame.y_range[1]),
                  im_colour_u32(palette.swatches.ink), 1.5f);
    for (const LessonPlotCurve& curve : plot.curves) {
      if (const std::optional<double> y = plot_value(curve, x)) {
        draw->AddCircleFilled(frame.to_screen(x, *y), 4.0f, im_colour_u32(swatch_in_theme(curve.colour, theme)));
      }
    }
  }
  draw->PopClipRect();

  // The legend: a swatch and the label of each curve, with its value at the marker.
  if (marked) ImGui::Text("x = %s", number_text(*plot.marker).c_str());
  for (size_t i = 0; i < plot.curves.size(); ++i) {
    const LessonPlotCurve& curve = plot.curves[i];
    std::string entry = lesson_text(runner, curve.label);
    if (marked) {
      if (const std::optional<double> y = plot_value(curve, *plot.marker)) entry += " = " + number_text(*y);
    }
    if (i > 0 || marked) same_line_if_room(("MM" + entry).c_str());  // "MM": about the swatch's width
    const ImVec2 at = ImGui::GetCursorScreenPos();
    draw->AddRectFilled(ImVec2(at.x, at.y + line * 0.2f), ImVec2(at.x + line * 0.6f, at.y + line * 0.8f),
                        im_colour_u32(swatch_in_theme(curve.colour, theme)));
    ImGui::Dummy(ImVec2(line * 0.7f, line));
    ImGui::SameLine(0.0f, 2.0f);
    ImGui::TextUnformatted(entry.c_str());
  }
  if (!plot.error.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, im_colour(palette.error));
    text_wrapped_at_spaces(plot.error);
    ImGui::PopStyleColor();
  }
}

}  // namespace meshedit
