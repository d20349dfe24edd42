// mesh:triangulate(), meshedit.repair() and meshedit.load(path, {repair = true}) from Lua.
#include <gtest/gtest.h>

#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <lua.hpp>

#include "core/mesh_build.h"
#include "core/primitives.h"
#include "script/lua_runtime.h"
#include "script/mesh_bindings.h"
#include "script/script_runtime.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

using Strings = std::vector<std::string>;

TEST(TriangulateBinding, QuadCubeBecomesTrianglesThatSubdivide) {
  auto mesh = std::make_shared<HalfedgeMesh>(build_halfedge_mesh(make_cube_quads()));
  ScriptRuntime lua;
  push_mesh(lua.state(), mesh);
  lua_setglobal(lua.state(), "m");
  const Strings refused = lua.run_string("return m:loop_subdivide()", "t.lua");
  ASSERT_EQ(refused.size(), 2u);
  EXPECT_NE(refused[1].find("mesh:triangulate()"), std::string::npos) << refused[1];
  EXPECT_EQ(
      lua.run_string("local n = m:triangulate() return n, m:num_faces(), (m:validate()), m:triangulate()", "t.lua"),
      (Strings{"6", "12", "true", "0"}));
  EXPECT_EQ(mesh->num_faces(), 12u);
  EXPECT_EQ(to_polygon_mesh(*mesh).positions, make_cube_quads().positions);
  EXPECT_EQ(lua.run_string("return m:loop_subdivide(), m:num_faces()", "t.lua"), (Strings{"true", "48"}));
  // The triangulation is one undo point.
  EXPECT_EQ(lua.run_string("m:undo() m:undo() return m:num_faces()", "t.lua"), Strings{"6"});
}

TEST(RepairBinding, RepairsTablesAndReportsWithTheirNumbers) {
  ScriptRuntime lua;
  const Strings r = lua.run_string(
      "local positions = {{0,0,0}, {1,0,0}, {1,1,0}, {-1,0,0}, {-1,-1,0}}\n"
      "local ok, err = pcall(meshedit.from_polygons, positions, {{1,2,3}, {1,4,5}})\n"
      "local m, report = meshedit.repair(positions, {{1,2,3}, {1,4,5}})\n"
      "local f1 = m:face(1)\n"
      "return ok, m:num_vertices(), (m:validate()), report.summary, #report.changes, report.changes[1],\n"
      "  tostring(f1.halfedge.vertex), tostring(f1.halfedge.vertex.position)",
      "t.lua");
  EXPECT_EQ(r, (Strings{"false", "6", "true", "repaired: 1 bow-tie vertex split", "1",
                        "vertex 0 was a bow-tie: split into 0 and new vertex 5 (face 1 moved)", "v5", "(0, 0, 0)"}));
}

TEST(RepairBinding, LoadWithTheRepairOption) {
  const std::filesystem::path dir = testing::scratch_dir();
  const std::string path = (dir / "fin.obj").string();
  std::ofstream(path) << "v 0 0 0\nv 1 0 0\nv 0.5 1 0\nv 0.5 -1 0\nv 0.5 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n";
  ScriptRuntime lua;
  const Strings r = lua.run_string("local ok = pcall(meshedit.load, '" + path +
                                       "')\n"
                                       "local m, report = meshedit.load('" +
                                       path +
                                       "', {repair = true})\n"
                                       "return ok, m:num_faces(), m:num_vertices(), report.changes[1]",
                                   "t.lua");
  EXPECT_EQ(r, (Strings{"false", "3", "7",
                        "the edge between vertex 0 and vertex 1 had faces 0..2: face 2 detached "
                        "(its corners there are now new vertices 5 and 6)"}));
}

}  // namespace
}  // namespace meshedit
