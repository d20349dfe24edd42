// A Lua runtime with the global `m` bound to a C++ mesh, for the mesh API tests: run() returns the chunk's
// results as strings, error() the message a failing chunk raises.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <lua.hpp>

#include "core/mesh_build.h"
#include "script/lua_runtime.h"
#include "script/mesh_bindings.h"
#include "script/script_runtime.h"

namespace meshedit::testing {

using Strings = std::vector<std::string>;

struct MeshScript {
  std::shared_ptr<HalfedgeMesh> mesh;
  ScriptRuntime lua;

  explicit MeshScript(const PolygonMesh& polygons)
      : mesh(std::make_shared<HalfedgeMesh>(build_halfedge_mesh(polygons))) {
    push_mesh(lua.state(), mesh);
    lua_setglobal(lua.state(), "m");
  }
  Strings run(const std::string& code, const std::string& chunk = "t.lua") { return lua.run_string(code, chunk); }
  std::string error(const std::string& code, const std::string& chunk = "t.lua") {
    try {
      lua.run_string(code, chunk);
    } catch (const ScriptError& e) {
      return e.what();
    }
    return "(no error)";
  }
};

}  // namespace meshedit::testing
