// The window's lasting settings (see settings.h). One table lists every key with how it is read and written.
#include "document/settings.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <functional>
#include <limits>
#include <optional>
#include <sstream>

#include "core/translation.h"
#include "io/file_access.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;

std::string trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return {};
  const auto last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

// Parses a whole number or a decimal; false when `text` is not entirely one, or not within [low, high].
bool parse_in_range(const std::string& text, double low, double high, double& out) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value)) return false;
  if (value < low || value > high) return false;
  out = value;
  return true;
}

std::string number(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

// One setting: its key, how its value is read (false: not a valid value) and how it is written.
struct Key {
  const char* name;
  const char* expected;  // what the warning says a valid value is
  std::function<bool(Settings&, const std::string&)> read;
  std::function<std::string(const Settings&)> write;
};

Key number_key(const char* name, const char* expected, double low, double high,
               const std::function<void(Settings&, double)>& set, const std::function<double(const Settings&)>& get) {
  return {name, expected,
          [=](Settings& s, const std::string& text) {
            double value = 0.0;
            if (!parse_in_range(text, low, high, value)) return false;
            set(s, value);
            return true;
          },
          [=](const Settings& s) { return number(get(s)); }};
}

Key flag_key(const char* name, bool LayoutPrefs::*field) {
  return {name, "true or false",
          [=](Settings& s, const std::string& text) {
            if (text != "true" && text != "false") return false;
            s.layout.*field = text == "true";
            return true;
          },
          [=](const Settings& s) { return std::string(s.layout.*field ? "true" : "false"); }};
}

Key ems_key(const char* name, float LayoutPrefs::*field, float low) {
  return number_key(
      name, "a width in font sizes", low, kMaxPanelEms, [=](Settings& s, double v) { s.layout.*field = float(v); },
      [=](const Settings& s) { return double(s.layout.*field); });
}

const std::vector<Key>& keys() {
  static const std::vector<Key> kTable = {
      number_key(
          "window_width", "a width in pixels", Settings::kMinWindowWidth, Settings::kMaxWindowSide,
          [](Settings& s, double v) { s.window_width = int(v); },
          [](const Settings& s) { return double(s.window_width); }),
      number_key(
          "window_height", "a height in pixels", Settings::kMinWindowHeight, Settings::kMaxWindowSide,
          [](Settings& s, double v) { s.window_height = int(v); },
          [](const Settings& s) { return double(s.window_height); }),
      number_key(
          "font_px", "a text size in pixels", Settings::kMinFontPx, Settings::kMaxFontPx,
          [](Settings& s, double v) { s.font_px = float(v); }, [](const Settings& s) { return double(s.font_px); }),
      {"theme", "dark or light",
       [](Settings& s, const std::string& text) {
         if (text != "dark" && text != "light") return false;
         s.theme = text == "light" ? Theme::Light : Theme::Dark;
         return true;
       },
       [](const Settings& s) { return std::string(s.theme == Theme::Light ? "light" : "dark"); }},
      {"language", "en or zh (or nothing: the system's)",
       [](Settings& s, const std::string& text) {
         if (text.empty()) return true;  // not chosen yet: the window follows the system's locale
         const std::optional<Language> language = language_by_code(text);
         if (!language || text != language_code(*language)) return false;
         s.language = text;
         return true;
       },
       [](const Settings& s) { return s.language; }},
      ems_key("left_column_ems", &LayoutPrefs::left_ems, WindowLayout::kMinColumnEms),
      ems_key("right_column_ems", &LayoutPrefs::right_ems, WindowLayout::kMinColumnEms),
      ems_key("console_ems", &LayoutPrefs::console_ems, WindowLayout::kMinConsoleEms),
      flag_key("left_column_open", &LayoutPrefs::left_open),
      flag_key("right_column_open", &LayoutPrefs::right_open),
      {"animate_edits", "true or false",
       [](Settings& s, const std::string& text) {
         if (text != "true" && text != "false") return false;
         s.animate_edits = text == "true";
         return true;
       },
       [](const Settings& s) { return std::string(s.animate_edits ? "true" : "false"); }},
      number_key(
          "student_code_seconds", "a number of seconds", Settings::kMinStudentCodeSeconds,
          Settings::kMaxStudentCodeSeconds, [](Settings& s, double v) { s.student_code_seconds = v; },
          [](const Settings& s) { return s.student_code_seconds; }),
  };
  return kTable;
}

}  // namespace

LuaLimits window_student_limits(double seconds) {
  LuaLimits limits;
  limits.instructions = std::numeric_limits<uint64_t>::max();
  limits.wall_seconds = seconds;
  return limits;
}

fs::path settings_path() {
  if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg) return fs::path(xdg) / "meshedit" / "settings.ini";
  if (const char* home = std::getenv("HOME"); home && *home) {
    return fs::path(home) / ".config" / "meshedit" / "settings.ini";
  }
  return {};
}

Settings parse_settings(const std::string& text, const std::string& name, std::vector<std::string>& warnings) {
  Settings settings;
  std::istringstream lines(text);
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    const std::string where = name + ":" + std::to_string(number) + ": ";
    line = trim(line);
    if (line.empty() || line[0] == '#') continue;
    const auto equals = line.find('=');
    if (equals == std::string::npos) {
      warnings.push_back(where + "not a 'key = value' line");
      continue;
    }
    const std::string key = trim(line.substr(0, equals)), value = trim(line.substr(equals + 1));
    const auto& table = keys();
    const auto found = std::find_if(table.begin(), table.end(), [&](const Key& k) { return key == k.name; });
    if (found == table.end()) {
      warnings.push_back(where + "unknown setting '" + key + "'");
    } else if (!found->read(settings, value)) {
      warnings.push_back(where + key + " must be " + found->expected + ", not '" + value + "'; kept the default");
    }
  }
  return settings;
}

Settings read_settings(const fs::path& path, std::vector<std::string>& warnings) {
  std::error_code ec;
  if (path.empty() || !fs::exists(path, ec)) return Settings{};
  try {
    return parse_settings(read_file(path), path.string(), warnings);
  } catch (const std::exception& e) {
    warnings.push_back(e.what());
    return Settings{};
  }
}

std::string format_settings(const Settings& settings) {
  std::string text = "# MeshEdit's window settings, written when the window closes.\n";
  for (const Key& key : keys()) text += std::string(key.name) + " = " + key.write(settings) + "\n";
  return text;
}

std::string write_settings(const fs::path& path, const Settings& settings) {
  try {
    std::error_code ec;
    fs::create_directories(path.parent_path(), ec);
    if (ec) return path.parent_path().string() + ": " + ec.message();
    write_file(path, format_settings(settings));
    return {};
  } catch (const std::exception& e) {
    return e.what();
  }
}

float stepped_font_px(float font_px, int steps) {
  const float base = std::isfinite(font_px) ? font_px : Settings::kDefaultFontPx;
  return std::clamp(std::round(base) + float(steps), Settings::kMinFontPx, Settings::kMaxFontPx);
}

}  // namespace meshedit
