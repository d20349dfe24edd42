// The bug report's text, written and read (see bug_report.h): a Lua chunk returning one table, read in a runtime whose
// chunk sees no global at all, its fields read raw.
#include "document/bug_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <lua.hpp>
#include <string>
#include <utility>

#include "core/app_version.h"
#include "core/file_bytes.h"
#include "core/value_format.h"
#include "script/lua_runtime.h"

namespace meshedit {
namespace {

constexpr char kFormat[] = "meshedit bug report";
constexpr size_t kMaxReportBytes = size_t(512) << 20;  // a report holds a mesh: as big as a mesh file may be

// `text` between long brackets of the lowest level it does not close; a newline first, which Lua drops, so a text
// that starts with one keeps it.
std::string long_bracketed(const std::string& text) {
  std::string level;
  while (text.find("]" + level + "]") != std::string::npos) level += '=';
  return "[" + level + "[\n" + text + "]" + level + "]";
}

// A Lua string literal of `text`: every byte kept, control bytes and quotes escaped.
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (c == '\n') {
      out += "\\n";
    } else if (byte < 0x20 || byte == 0x7f) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\%03u", static_cast<unsigned>(byte));
      out += escaped;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

void field(std::string& out, const char* indent, const char* name, const std::string& value) {
  if (!value.empty()) out += std::string(indent) + name + " = " + quoted(value) + ",\n";
}

std::string format_operation(const BugReportOperation& op) {
  std::string out =
      "  -- the last run of the student's function on a mesh, and the mesh it was given\n  operation = {\n";
  field(out, "    ", "exercise", op.exercise);
  field(out, "    ", "label", op.label);
  field(out, "    ", "element", op.element);
  field(out, "    ", "verdict", op.verdict);
  out += std::string("    result_shown = ") + (op.result_shown ? "true" : "false") + ",\n";
  out += "    input = " + long_bracketed(op.input) + ",\n  },\n";
  return out;
}

std::string format_camera(const BugReportCamera& camera) {
  std::string out = std::string("  camera = { up = \"") + camera.up + "\", yaw = ";
  append_number(out, camera.yaw);
  out += ", pitch = ";
  append_number(out, camera.pitch);
  out += ", distance = ";
  append_number(out, camera.distance);
  out += ", target = { ";
  for (int i = 0; i < 3; ++i) {
    if (i > 0) out += ", ";
    append_number(out, camera.target[i]);
  }
  return out + " } },\n";
}

// ---- reading ----

// The table at the top of the stack, read raw.
class TableReader {
 public:
  TableReader(lua_State* L, std::string where) : L_(L), where_(std::move(where)) {}

  std::string text(const char* key) const {
    std::string value;
    with_field(key, [&](int type) {
      if (type != LUA_TSTRING) refuse(key, "text");
      size_t size = 0;
      const char* chars = lua_tolstring(L_, -1, &size);
      value.assign(chars, size);
    });
    return value;
  }
  long long integer(const char* key, long long fallback) const {
    long long value = fallback;
    with_field(key, [&](int) {
      if (!lua_isinteger(L_, -1)) refuse(key, "a whole number");
      value = lua_tointeger(L_, -1);
    });
    return value;
  }
  bool boolean(const char* key) const {
    bool value = false;
    with_field(key, [&](int type) {
      if (type != LUA_TBOOLEAN) refuse(key, "true or false");
      value = lua_toboolean(L_, -1) != 0;
    });
    return value;
  }
  double number(const char* key, double fallback) const {
    double value = fallback;
    with_field(key, [&](int type) {
      if (type != LUA_TNUMBER || !std::isfinite(lua_tonumber(L_, -1))) refuse(key, "a finite number");
      value = lua_tonumber(L_, -1);
    });
    return value;
  }
  // Pushes the field `key` when it is a table (true), nothing when it is absent (false).
  bool push_table(const char* key) const {
    lua_pushstring(L_, key);
    const int type = lua_rawget(L_, -2);
    if (type == LUA_TTABLE) return true;
    lua_pop(L_, 1);
    if (type != LUA_TNIL) refuse(key, "a table");
    return false;
  }
  [[noreturn]] void refuse(const std::string& key, const char* wanted) const {
    throw ReportError(where_ + key + " should be " + wanted);
  }
  const std::string& where() const { return where_; }

 private:
  template <typename Read>
  void with_field(const char* key, Read read) const {
    lua_pushstring(L_, key);
    const int type = lua_rawget(L_, -2);
    if (type != LUA_TNIL) read(type);
    lua_pop(L_, 1);
  }

  lua_State* L_;
  std::string where_;  // "report.meshedit: the field " (then the key)
};

const char* const kKnownFields[] = {"format",    "version", "readable_by", "app",    "language",  "lesson", "step",
                                    "mesh_name", "mesh",    "selection",   "camera", "operation", "files"};

std::vector<std::string> unknown_fields(lua_State* L) {
  std::vector<std::string> unknown;
  lua_pushnil(L);
  while (lua_next(L, -2) != 0) {
    if (lua_type(L, -2) == LUA_TSTRING) {
      const std::string key = lua_tostring(L, -2);
      if (std::find(std::begin(kKnownFields), std::end(kKnownFields), key) == std::end(kKnownFields)) {
        unknown.push_back(key);
      }
    }
    lua_pop(L, 1);
  }
  std::sort(unknown.begin(), unknown.end());
  return unknown;
}

void check_version(const TableReader& table, BugReport& report, const std::string& name) {
  if (table.text("format") != kFormat) {
    throw ReportError(name + ": not a MeshEdit bug report (its table has no format = \"" + kFormat + "\")");
  }
  report.version = static_cast<int>(table.integer("version", 0));
  report.readable_by = static_cast<int>(table.integer("readable_by", report.version));
  report.app = table.text("app");
  const std::string saved_by = report.app.empty() ? std::string() : " (saved by " + report.app + ")";
  if (report.version < 1) {
    throw ReportError(name + ": a bug report of version " + std::to_string(report.version) + saved_by +
                      ", which no MeshEdit wrote");
  }
  if (report.readable_by > kBugReportVersion) {
    throw ReportError(name + ": a bug report of version " + std::to_string(report.version) + saved_by +
                      " that needs a newer MeshEdit: this is " + kAppVersion + ", which reads version " +
                      std::to_string(kBugReportVersion));
  }
}

BugReportOperation read_operation(const TableReader& table) {
  BugReportOperation op;
  op.exercise = table.text("exercise");
  op.label = table.text("label");
  op.element = table.text("element");
  op.verdict = table.text("verdict");
  op.result_shown = table.boolean("result_shown");
  op.input = table.text("input");
  if (op.exercise.empty()) table.refuse("exercise", "the name of an exercise's function");
  return op;
}

BugReportCamera read_camera(lua_State* L, const TableReader& table) {
  BugReportCamera camera;
  const std::string up = table.text("up");
  if (up != "y" && up != "z") table.refuse("up", "\"y\" or \"z\"");
  camera.up = up[0];
  camera.yaw = table.number("yaw", 0.0);
  camera.pitch = table.number("pitch", 0.0);
  camera.distance = table.number("distance", 1.0);
  if (table.push_table("target")) {
    for (int i = 0; i < 3; ++i) {
      lua_rawgeti(L, -1, i + 1);
      if (lua_type(L, -1) != LUA_TNUMBER || !std::isfinite(lua_tonumber(L, -1))) {
        table.refuse("target", "three finite numbers");
      }
      camera.target[i] = lua_tonumber(L, -1);
      lua_pop(L, 1);
    }
    lua_pop(L, 1);
  }
  return camera;
}

// A student file's name: "flip.lua", never a folder, nothing hidden.
bool plain_lua_name(const std::string& name) {
  return name.size() > 4 && name.compare(name.size() - 4, 4, ".lua") == 0 && name.front() != '.' &&
         name.find_first_of("/\\:") == std::string::npos && name.find('\0') == std::string::npos;
}

std::vector<StudentSource> read_files(lua_State* L, const std::string& where) {
  std::vector<StudentSource> files;
  lua_pushnil(L);
  while (lua_next(L, -2) != 0) {
    if (lua_type(L, -2) != LUA_TSTRING || lua_type(L, -1) != LUA_TSTRING) {
      lua_pop(L, 2);
      throw ReportError(where + "files should map file names to their texts");
    }
    size_t size = 0;
    const char* text = lua_tolstring(L, -1, &size);
    StudentSource file{lua_tostring(L, -2), std::string(text, size)};
    if (!plain_lua_name(file.name)) {
      lua_pop(L, 2);
      throw ReportError(where + "files holds \"" + file.name + "\", which is not the name of a .lua file");
    }
    files.push_back(std::move(file));
    lua_pop(L, 1);
  }
  std::sort(files.begin(), files.end(), [](const StudentSource& a, const StudentSource& b) { return a.name < b.name; });
  return files;
}

}  // namespace

std::string format_bug_report(const BugReport& report) {
  std::string out =
      "-- A MeshEdit bug report: what a student chose to send. Open it in MeshEdit (meshedit report.meshedit, or\n"
      "-- drop it on the page) to see what the student saw; `meshedit run report.meshedit` runs the last operation\n"
      "-- again with the student's code and prints its diagnosis.\n"
      "return {\n";
  out += std::string("  format = ") + quoted(kFormat) + ",\n";
  out += "  version = " + std::to_string(report.version) + ",\n";
  out += "  readable_by = " + std::to_string(report.readable_by) + ",\n";
  field(out, "  ", "app", report.app);
  field(out, "  ", "language", report.language);
  field(out, "  ", "lesson", report.lesson);
  if (report.step > 0) out += "  step = " + std::to_string(report.step) + ",\n";
  field(out, "  ", "mesh_name", report.mesh_name);
  field(out, "  ", "selection", report.selection);
  if (report.camera) out += format_camera(*report.camera);
  if (report.operation) out += format_operation(*report.operation);
  if (!report.mesh.empty())
    out += "  -- the mesh shown, every id kept\n  mesh = " + long_bracketed(report.mesh) + ",\n";
  if (!report.files.empty()) {
    out += "  -- the code files the student chose to send\n  files = {\n";
    for (const StudentSource& file : report.files) {
      out += "    [" + quoted(file.name) + "] = " + long_bracketed(file.text) + ",\n";
    }
    out += "  },\n";
  }
  return out + "}\n";
}

BugReport parse_bug_report(std::string_view text, const std::string& name) {
  LuaLimits limits;
  limits.instructions = 10'000'000;
  limits.memory_bytes = size_t(1) << 30;
  limits.wall_seconds = 10.0;
  LuaRuntime lua(limits);
  lua_State* L = lua.state();
  BugReport report;
  try {
    lua.load(text, name);
    lua_newtable(L);  // the chunk's _ENV: no global at all
    lua_setupvalue(L, -2, 1);
    if (lua.call(0, 1) != 1 || lua_type(L, -1) != LUA_TTABLE) {
      throw ReportError(name + ": not a MeshEdit bug report (it does not return a table)");
    }
  } catch (const ScriptError& e) {
    throw ReportError(std::string(e.what()) + " (reading it as a MeshEdit bug report)");
  }
  const TableReader table(L, name + ": the field ");
  check_version(table, report, name);
  if (report.version > kBugReportVersion) report.left_out = unknown_fields(L);
  report.language = table.text("language");  // one this reader does not know replays in English
  report.lesson = table.text("lesson");
  const long long step = table.integer("step", 0);
  if (step < 0 || (step > 0 && report.lesson.empty())) table.refuse("step", "a lesson's step, 1 or more");
  report.step = static_cast<size_t>(step);
  report.mesh_name = table.text("mesh_name");
  report.mesh = table.text("mesh");
  report.selection = table.text("selection");
  if (table.push_table("camera")) {
    report.camera = read_camera(L, TableReader(L, name + ": the field camera."));
    lua_pop(L, 1);
  }
  if (table.push_table("operation")) {
    report.operation = read_operation(TableReader(L, name + ": the field operation."));
    lua_pop(L, 1);
  }
  if (table.push_table("files")) {
    report.files = read_files(L, name + ": the field ");
    lua_pop(L, 1);
  }
  return report;
}

BugReport read_bug_report(const std::filesystem::path& path) {
  const std::string name = path.filename().string();
  const FileBytes bytes = read_file_bytes(path, kMaxReportBytes);
  if (!bytes.ok()) throw ReportError(name + ": " + bytes.error);
  return parse_bug_report(bytes.bytes, name);
}

}  // namespace meshedit
