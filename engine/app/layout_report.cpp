// The window's layout as JSON (see layout_report.h).
#include "app/layout_report.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <nlohmann/json.hpp>

#include "app/editor_app.h"

namespace meshedit {
namespace {

using nlohmann::json;

json rect(float x, float y, float w, float h) { return json::array({x, y, w, h}); }
json rect(const ScreenRect& r) { return rect(r.x, r.y, r.width, r.height); }

// "Lessons###left column" -> "left column"; "##left splitter" -> "left splitter".
std::string window_name(const char* name) {
  std::string text = name;
  if (const auto id = text.find("###"); id != std::string::npos) return text.substr(id + 3);
  if (text.rfind("##", 0) == 0) return text.substr(2);
  return text;
}

}  // namespace

std::string layout_json(const EditorApp& app) {
  const ImGuiIO& io = ImGui::GetIO();
  json out;
  out["display"] = json::array({io.DisplaySize.x, io.DisplaySize.y});
  out["font_px"] = app.panels().font_pixels();
  out["theme"] = app.settings().theme == Theme::Light ? "light" : "dark";
  out["mode"] = app.mode() == ViewMode::Mesh ? "mesh" : app.mode() == ViewMode::Curve ? "curve" : "patches";
  out["view"] = rect(app.panels().layout().view);

  json panels = json::array(), splitters = json::array();
  for (const ImGuiWindow* window : ImGui::GetCurrentContext()->Windows) {
    const bool drawn = window->Active && !window->Hidden;  // between frames: drawn in the last one
    if (!drawn || (window->Flags & ImGuiWindowFlags_ChildWindow) || (window->Flags & ImGuiWindowFlags_Tooltip)) {
      continue;
    }
    const std::string name = window_name(window->Name);
    if (name == "curve view" || name == "Debug##Default") continue;  // the view itself; ImGui's implicit window
    json entry = {{"name", name}, {"rect", rect(window->Pos.x, window->Pos.y, window->Size.x, window->Size.y)}};
    (name.find("splitter") != std::string::npos ? splitters : panels).push_back(std::move(entry));
  }
  out["panels"] = std::move(panels);
  out["splitters"] = std::move(splitters);

  json lesson = json::object();
  for (const auto& [key, item] :
       {std::pair{"text", "lesson-text"}, std::pair{"back", "lesson-back"}, std::pair{"next", "lesson-next"}}) {
    if (const UiProbe::Item* found = app.panels().probe().find(item)) {
      lesson[key] = rect(found->min.x, found->min.y, found->max.x - found->min.x, found->max.y - found->min.y);
    }
  }
  out["lesson"] = std::move(lesson);
  json drawn = json::array();
  for (const PlacedLabel& label : app.view().last_labels().placed) {
    drawn.push_back({{"text", label.text},
                     {"element", format_id(label.element)},
                     {"source", label.source == LabelSource::Lesson ? "lesson" : "id"},
                     {"rect", rect(float(label.rect.min.x), float(label.rect.min.y), float(label.rect.width()),
                                   float(label.rect.height()))}});
  }
  out["labels"] = {{"drawn", std::move(drawn)}, {"dropped", app.view().last_labels().dropped}};
  return out.dump(2) + "\n";
}

}  // namespace meshedit
