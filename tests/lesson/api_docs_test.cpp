// Keeps the LuaLS ---@meta files in scripts/api/ true: every function and field they document for the
// `meshedit` module, meshes, element handles, vec3, curves and patches must exist on real values, and every
// function of the real module table and every mesh method must be documented. The lesson globals documented in
// lesson.lua must be exactly the functions a lesson's runtime adds to a plain one (read from a running lesson); grading
// globals are only checked against the names listed here (copied from expectations.cpp and suite.cpp), since they
// live in a suite's own state.
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <lua.hpp>

#include "lesson/headless_host.h"
#include "lesson/lesson_runner.h"
#include "script/lua_runtime.h"
#include "script/mesh_bindings.h"
#include "script/script_runtime.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

struct Documented {
  std::map<std::string, std::set<std::string>> functions;  // class -> `function Class:name` / `Class.name`
  std::map<std::string, std::set<std::string>> fields;     // class -> `---@field name`
};

Documented parse_meta(const std::filesystem::path& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in) << "cannot open " << path;
  const std::regex function_line(R"(^function ([A-Za-z_][A-Za-z0-9_]*)[:.]([A-Za-z_][A-Za-z0-9_]*)\()");
  const std::regex class_line(R"(^---@class ([A-Za-z_][A-Za-z0-9_]*))");
  const std::regex field_line(R"(^---@field ([A-Za-z_][A-Za-z0-9_]*)\??\s)");
  Documented doc;
  std::string current_class, line;
  std::smatch match;
  while (std::getline(in, line)) {
    if (std::regex_search(line, match, function_line)) doc.functions[match[1]].insert(match[2]);
    else if (std::regex_search(line, match, class_line)) current_class = match[1];
    else if (std::regex_search(line, match, field_line)) doc.fields[current_class].insert(match[1]);
    else if (line.rfind("---", 0) != 0) current_class.clear();  // a field list ends at the first non-annotation
  }
  return doc;
}

// The Lua expression giving a real value of each documented class (`m` is a cube).
const std::map<std::string, std::vector<std::string>> kSamples = {
    {"Mesh", {"m"}},
    {"Element", {"m:vertex(0)", "m:halfedge(0)", "m:edge(0)", "m:face(0)", "g:boundary(0)"}},
    {"Vertex", {"m:vertex(0)"}},
    {"Halfedge", {"m:halfedge(0)"}},
    {"Edge", {"m:edge(0)"}},
    {"Face", {"m:face(0)"}},
    {"Boundary", {"g:boundary(0)"}},
    {"vec3", {"meshedit.vec3(1, 2, 3)"}},
    {"Curve", {"meshedit.curve({{0, 0, 0}, {1, 1, 0}, {2, 0, 0}})"}},
    {"Patch", {"P"}},
    {"SubdivisionPhases", {"m:subdivision_phases('loop')", "m:subdivision_phases('catmull-clark')"}},
    {"meshedit", {"meshedit"}},
};

class ApiDocs : public ::testing::Test {
 protected:
  void SetUp() override {
    lua.run_string(
        "m = meshedit.cube(); g = meshedit.grid(1, 1)\n"
        "local pts = {} for i = 1, 16 do pts[i] = {i, i % 4, 0} end P = meshedit.patch(pts)",
        "setup.lua");
  }
  // "ok" when `expression[name]` is not nil, else what it is.
  std::string lookup(const std::string& expression, const std::string& name) {
    return lua
        .run_string("local ok, v = pcall(function() return (" + expression + ")['" + name +
                        "'] end) return ok and v ~= nil and 'ok' or tostring(v)",
                    "lookup.lua")
        .at(0);
  }
  ScriptRuntime lua;
  Documented doc = parse_meta(::meshedit::testing::source_dir() / "scripts" / "api" / "meshedit.lua");
};

TEST_F(ApiDocs, TheMetaFileDocumentsEveryClass) {
  for (const char* cls :
       {"Element", "Mesh", "Vertex", "Halfedge", "Face", "Boundary", "vec3", "Curve", "Patch", "meshedit"}) {
    EXPECT_FALSE(doc.functions[cls].empty()) << cls << " has no documented function";
  }
  EXPECT_EQ(doc.fields["Halfedge"], (std::set<std::string>{"next", "twin", "vertex", "edge", "face"}));
  EXPECT_EQ(doc.fields["Element"], (std::set<std::string>{"id", "kind", "mesh"}));
}

TEST_F(ApiDocs, EveryDocumentedFunctionExists) {
  for (const auto& [cls, names] : doc.functions) {
    auto sample = kSamples.find(cls);
    ASSERT_NE(sample, kSamples.end()) << "no sample value for documented class " << cls;
    for (const std::string& expression : sample->second) {
      for (const std::string& name : names) {
        EXPECT_EQ(lookup(expression, name), "ok")
            << cls << ":" << name << " is documented but " << expression << "." << name << " is missing";
      }
    }
  }
}

TEST_F(ApiDocs, EveryDocumentedFieldExists) {
  for (const char* cls : {"Element", "Vertex", "Halfedge", "Edge", "Face", "Boundary", "vec3", "Curve", "Patch"}) {
    ASSERT_FALSE(doc.fields[cls].empty()) << cls;
    for (const std::string& expression : kSamples.at(cls)) {
      for (const std::string& name : doc.fields[cls]) {
        EXPECT_EQ(lookup(expression, name), "ok")
            << cls << "." << name << " is documented but missing on " << expression;
      }
    }
  }
}

TEST_F(ApiDocs, EveryModuleFunctionIsDocumented) {
  const auto names = lua.run_string(
      "local t = {} for k, v in pairs(meshedit) do if type(v) == 'function' then t[#t + 1] = k end end "
      "table.sort(t) return table.concat(t, ' ')",
      "module.lua");
  std::istringstream words(names.at(0));
  std::string name;
  int count = 0;
  while (words >> name) {
    ++count;
    EXPECT_TRUE(doc.functions["meshedit"].count(name)) << "meshedit." << name << " is not in scripts/api/meshedit.lua";
  }
  EXPECT_EQ(count, int(doc.functions["meshedit"].size()));
}

TEST_F(ApiDocs, EveryMeshMethodIsDocumented) {
  // The methods table is the mesh metatable's __index; read it from C++ (scripts see no metatable).
  lua_State* L = lua.state();
  lua_getglobal(L, "m");
  ASSERT_TRUE(lua_getmetatable(L, -1));
  ASSERT_EQ(lua_getfield(L, -1, "__index"), LUA_TTABLE);
  int count = 0;
  lua_pushnil(L);
  while (lua_next(L, -2)) {
    lua_pop(L, 1);
    if (lua_type(L, -1) != LUA_TSTRING) continue;
    const std::string name = lua_tostring(L, -1);
    ++count;
    EXPECT_TRUE(doc.functions["Mesh"].count(name)) << "mesh:" << name << " is not in scripts/api/meshedit.lua";
  }
  lua_pop(L, 3);
  EXPECT_EQ(count, int(doc.functions["Mesh"].size()));
}

TEST_F(ApiDocs, AnUndocumentedNameIsCaught) {
  // The lookup really fails for a name the API does not have, so the checks above can fail.
  EXPECT_NE(lookup("m", "no_such_method"), "ok");
  EXPECT_NE(lookup("m:halfedge(0)", "no_such_field"), "ok");
  EXPECT_NE(lookup("meshedit.vec3(1, 2, 3)", "no_such_method"), "ok");
}

// The names of the global functions `code` sees, sorted, one string: what the lesson below says and a plain runtime
// returns.
constexpr const char* kGlobalFunctions =
    "local t = {} for k, v in pairs(_G) do if type(v) == 'function' then t[#t + 1] = k end end "
    "table.sort(t) return table.concat(t, ' ')";

std::set<std::string> words(const std::string& text) {
  std::istringstream in(text);
  std::set<std::string> out;
  for (std::string word; in >> word;) out.insert(word);
  return out;
}

TEST(ApiDocsFiles, TheLessonMetaFileDocumentsExactlyTheLessonGlobals) {
  ScriptRuntime plain;
  const std::set<std::string> base = words(plain.run_string(kGlobalFunctions, "plain.lua").at(0));
  const auto lesson = ::meshedit::testing::scratch_dir() / "globals.lua";
  std::ofstream(lesson) << "step('Globals', function() say((function() " << kGlobalFunctions << " end)()) end)\n";
  HeadlessHost host;
  LessonRunner runner(host);
  ASSERT_TRUE(runner.load(lesson)) << runner.error();
  ASSERT_EQ(runner.said().size(), 1u) << runner.error();
  std::set<std::string> lesson_globals;
  for (const std::string& name : words(runner.said()[0])) {
    if (!base.count(name)) lesson_globals.insert(name);
  }
  EXPECT_TRUE(lesson_globals.count("choose") && lesson_globals.count("plot"));  // the set is read, not empty

  const std::string text =
      ::meshedit::testing::read_text(::meshedit::testing::source_dir() / "scripts" / "api" / "lesson.lua");
  const std::regex global_function(R"((^|\n)function ([A-Za-z_][A-Za-z0-9_]*)\()");
  std::set<std::string> documented;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), global_function); it != std::sregex_iterator(); ++it) {
    documented.insert((*it)[2]);
  }
  EXPECT_EQ(documented, lesson_globals);
}

TEST(ApiDocsFiles, LessonAndGradingMetaFilesNameTheRealGlobals) {
  const auto dir = ::meshedit::testing::source_dir() / "scripts" / "api";
  Documented lesson = parse_meta(dir / "lesson.lua");
  const std::string text = ::meshedit::testing::read_text(dir / "lesson.lua");
  for (const char* name :
       {"lesson", "step",   "say",          "wait_for",  "animate",      "show",     "highlight", "label",
        "clear",  "camera", "current_mesh", "selection", "lesson_file",  "choose",   "pick",      "answer",
        "live",   "plot",   "arrow",        "curve_t",   "curve_points", "your_turn"}) {
    EXPECT_NE(text.find(std::string("\nfunction ") + name + "("), std::string::npos) << name;
  }
  Documented grading = parse_meta(dir / "grading.lua");
  EXPECT_EQ(grading.functions["Expect"],
            (std::set<std::string>{"truthy", "falsy", "is_nil", "equal", "near", "valid", "mesh_equal", "same_pointers",
                                   "counts", "pass", "fail", "score", "exercise"}));
  EXPECT_EQ(grading.functions["Student"], (std::set<std::string>{"has", "call", "output"}));
}

}  // namespace
}  // namespace meshedit
