// writeup.json: the student's choices for their write-up (see writeup_settings.h).
#include "writeup/writeup_settings.h"

#include <cmath>
#include <exception>
#include <set>

#include <nlohmann/json.hpp>

#include "core/file_bytes.h"

namespace meshedit {
namespace {

using nlohmann::json;

constexpr int kMaxLevels = 4;

// A number of the object, or nullopt with a problem when it is there and is not a finite number in [lo, hi].
std::optional<double> number_of(const json& object, const char* key, double lo, double hi, const std::string& name,
                                std::vector<std::string>& problems) {
  if (!object.contains(key)) return std::nullopt;
  const json& value = object.at(key);
  if (!value.is_number() || !std::isfinite(value.get<double>()) || value.get<double>() < lo ||
      value.get<double>() > hi) {
    problems.push_back(name + ": \"" + key + "\" must be a number from " + json(lo).dump() + " to " + json(hi).dump() +
                       ", not " + value.dump() + " (the default is used)");
    return std::nullopt;
  }
  return value.get<double>();
}

std::vector<uint32_t> edges_of(const json& object, const char* key, const std::string& name,
                               std::vector<std::string>& problems) {
  std::vector<uint32_t> edges;
  if (!object.contains(key)) return edges;
  const json& value = object.at(key);
  bool ok = value.is_array() && value.size() <= kMaxWriteupEdges;
  for (size_t i = 0; ok && i < value.size(); ++i) {
    ok = value[i].is_number_unsigned() && value[i].get<uint64_t>() < 1'000'000;
    if (ok) edges.push_back(static_cast<uint32_t>(value[i].get<uint64_t>()));
  }
  if (ok) return edges;
  problems.push_back(name + ": \"" + key + "\" must be a list of at most " + std::to_string(kMaxWriteupEdges) +
                     " edge ids (whole numbers: 12 for e12), not " + value.dump() + " (the default is used)");
  return {};
}

// `path` as writeup.json names it: relative to the folder when it is inside it, else whole.
std::string name_in(const std::filesystem::path& path, const std::filesystem::path& folder) {
  const std::filesystem::path relative = path.lexically_relative(folder);
  const bool inside = !relative.empty() && *relative.begin() != "..";
  return (inside ? relative : path).generic_string();
}

}  // namespace

WriteupSettings parse_writeup_settings(const std::string& text, const std::string& name,
                                       const std::filesystem::path& folder) {
  WriteupSettings settings;
  json root;
  try {
    root = json::parse(text);
  } catch (const json::parse_error& e) {
    settings.problems.push_back(name + ": not JSON (" + e.what() + "); the defaults are used");
    return settings;
  }
  if (!root.is_object()) {
    settings.problems.push_back(name + ": must be a JSON object {...}; the defaults are used");
    return settings;
  }
  static const std::set<std::string> kKeys = {"curve", "t",          "other_t",     "camera",
                                              "mesh",  "flip_edges", "split_edges", "levels"};
  for (const auto& [key, value] : root.items()) {
    if (!kKeys.contains(key)) settings.problems.push_back(name + ": unknown key \"" + key + "\" (left alone)");
  }
  std::vector<std::string>& problems = settings.problems;
  if (root.contains("curve")) {
    if (root["curve"].is_string() && !root["curve"].get<std::string>().empty()) {
      settings.curve = folder / root["curve"].get<std::string>();
    } else {
      problems.push_back(name + ": \"curve\" must be the name of a .bzc file (the default curve is used)");
    }
  }
  if (root.contains("mesh")) {
    if (root["mesh"].is_string() && !root["mesh"].get<std::string>().empty()) {
      settings.mesh = folder / root["mesh"].get<std::string>();
    } else {
      problems.push_back(name + ": \"mesh\" must be the name of a mesh file (the grid is used)");
    }
  }
  settings.t = number_of(root, "t", 0.0, 1.0, name, problems).value_or(settings.t);
  settings.other_t = number_of(root, "other_t", 0.0, 1.0, name, problems).value_or(settings.other_t);
  if (root.contains("camera")) {
    const json& camera = root["camera"];
    if (camera.is_object()) {
      settings.camera.yaw = number_of(camera, "yaw", -360.0, 360.0, name, problems).value_or(settings.camera.yaw);
      settings.camera.pitch = number_of(camera, "pitch", -89.0, 89.0, name, problems).value_or(settings.camera.pitch);
      settings.camera.zoom = number_of(camera, "zoom", -20.0, 20.0, name, problems).value_or(settings.camera.zoom);
    } else {
      problems.push_back(name + ": \"camera\" must be an object {\"yaw\": ..., \"pitch\": ..., \"zoom\": ...}");
    }
  }
  settings.flip_edges = edges_of(root, "flip_edges", name, problems);
  settings.split_edges = edges_of(root, "split_edges", name, problems);
  if (const auto levels = number_of(root, "levels", 1, kMaxLevels, name, problems)) {
    if (*levels == std::floor(*levels)) {
      settings.levels = static_cast<int>(*levels);
    } else {
      problems.push_back(name + ": \"levels\" must be a whole number (the default is used)");
    }
  }
  return settings;
}

WriteupSettings read_writeup_settings(const std::filesystem::path& folder) {
  const std::filesystem::path file = folder / kWriteupSettingsFile;
  std::error_code error;
  if (!std::filesystem::exists(file, error)) return WriteupSettings{};
  const FileBytes text = read_file_bytes(file, size_t(1) << 20);
  if (!text.ok()) {
    WriteupSettings settings;
    settings.problems.push_back(std::string(kWriteupSettingsFile) + ": " + text.error + "; the defaults are used");
    return settings;
  }
  return parse_writeup_settings(text.bytes, kWriteupSettingsFile, folder);
}

std::string format_writeup_settings(const WriteupSettings& settings, const std::filesystem::path& folder) {
  json root = json::object();
  if (settings.curve) root["curve"] = name_in(*settings.curve, folder);
  root["t"] = settings.t;
  root["other_t"] = settings.other_t;
  root["camera"] = {{"yaw", settings.camera.yaw}, {"pitch", settings.camera.pitch}, {"zoom", settings.camera.zoom}};
  if (settings.mesh) root["mesh"] = name_in(*settings.mesh, folder);
  if (!settings.flip_edges.empty()) root["flip_edges"] = settings.flip_edges;
  if (!settings.split_edges.empty()) root["split_edges"] = settings.split_edges;
  root["levels"] = settings.levels;
  return root.dump(2) + "\n";
}

}  // namespace meshedit
