// lua_bench: what scripts pay for the mesh API (not a test: nothing is asserted). Prints the cost of one
// handle field read and write, of iteration and of v.position beside the interpreter's own costs (an empty
// loop, a plain-table field read, a call to a C function that does nothing, a userdata field read through a C
// __index that does nothing, one through a C __index that only makes a new userdata: what any element value costs
// the interpreter, and a vec3 table made in Lua), then a student-style Lua `upsample` against the core's Loop
// subdivision.
//
//   lua_bench [--mesh FILE] [--upsample FILE.lua] [--reads N] [--reps R]
// Defaults: the course teapot (../shared/data/cs184/dae/teapot.dae, 2464 faces) when present, else a torus of
// 2464 faces; the reference solution tests/exercise/solutions/upsample.lua; 2e6 reads; minimum of 5 runs.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include <lua.hpp>

#include "bench/bench_support.h"
#include "core/loop_subdivision.h"
#include "core/mesh_build.h"
#include "core/primitives.h"
#include "io/mesh_file.h"
#include "script/lua_runtime.h"
#include "script/mesh_bindings.h"
#include "script/script_runtime.h"

namespace {

namespace fs = std::filesystem;
using meshedit::bench::min_ms;

const char* option(int argc, char** argv, const char* name, const char* fallback) {
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::strcmp(argv[i], name) == 0) return argv[i + 1];
  }
  return fallback;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace meshedit;
  const std::string source = MESHEDIT_SOURCE_DIR;
  const fs::path mesh_path = option(argc, argv, "--mesh", (source + "/../shared/data/cs184/dae/teapot.dae").c_str());
  const fs::path upsample_path =
      option(argc, argv, "--upsample", (source + "/tests/exercise/solutions/upsample.lua").c_str());
  const long reads = std::max(1000L, std::strtol(option(argc, argv, "--reads", "2000000"), nullptr, 10));
  const int reps = std::clamp(std::atoi(option(argc, argv, "--reps", "5")), 1, 100);

  PolygonMesh polygons;
  std::string mesh_name;
  try {
    polygons = load_mesh(mesh_path);
    mesh_name = mesh_path.filename().string();
  } catch (const std::exception&) {
    polygons = make_torus_with_faces(2464);
    mesh_name = "torus (" + mesh_path.string() + " is absent)";
  }
  const HalfedgeMesh original = build_halfedge_mesh(polygons);
  std::printf("mesh: %s, %zu vertices, %zu faces; minimum of %d runs, one thread\n", mesh_name.c_str(),
              original.num_vertices(), original.num_faces(), reps);

  LuaLimits limits;
  limits.instructions = uint64_t(1) << 40;
  limits.wall_seconds = 600;
  ScriptRuntime lua(limits);
  auto mesh = std::make_shared<HalfedgeMesh>(original);
  push_mesh(lua.state(), mesh);
  lua_setglobal(lua.state(), "mesh");
  lua_pushinteger(lua.state(), reads);
  lua_setglobal(lua.state(), "N");
  // The interpreter's own floor for a binding: a C function that returns its argument, and a userdata whose
  // __index is a C function that returns the key (no work, no allocation).
  lua_pushcfunction(lua.state(), [](lua_State* L) {
    lua_settop(L, 1);
    return 1;
  });
  lua_setglobal(lua.state(), "c_identity");
  lua_newuserdatauv(lua.state(), 8, 0);
  lua_createtable(lua.state(), 0, 1);
  lua_pushcfunction(lua.state(), [](lua_State* L) {
    lua_settop(L, 2);
    return 1;
  });
  lua_setfield(lua.state(), -2, "__index");
  lua_setmetatable(lua.state(), -2);
  lua_setglobal(lua.state(), "u");
  // The floor for a read that yields an element: an __index that makes a fresh userdata the size of a handle, with
  // one user value (copied from its argument, as a handle's mesh is) and a metatable, and does nothing else.
  lua_newuserdatauv(lua.state(), 16, 1);
  lua_createtable(lua.state(), 0, 1);
  lua_pushvalue(lua.state(), -1);
  lua_pushcclosure(
      lua.state(),
      [](lua_State* L) {
        lua_newuserdatauv(L, 16, 1);
        lua_getiuservalue(L, 1, 1);
        lua_setiuservalue(L, -2, 1);
        lua_pushvalue(L, lua_upvalueindex(1));
        lua_setmetatable(L, -2);
        return 1;
      },
      1);
  lua_setfield(lua.state(), -2, "__index");
  lua_setmetatable(lua.state(), -2);
  lua_setglobal(lua.state(), "w");

  // Each loop body does one operation N times; the empty loop is subtracted to leave the operation's cost.
  auto per_op_ns = [&](const char* body) {
    const std::string code =
        "local h = mesh:halfedge(0) local v = mesh:vertex(0) local t = {next = 1} "
        "local f, u, w, mt = c_identity, u, w, {} local n = h.next local x for i = 1, N do " +
        std::string(body) + " end";
    return min_ms(
               reps, [] {}, [&] { lua.run_string(code, "bench.lua"); }) *
           1e6 / double(reads);
  };
  const double empty = per_op_ns("");
  std::printf("%-36s %8.1f ns\n", "empty Lua loop iteration", empty);
  const double table_read = per_op_ns("x = t.next") - empty;
  const double c_call = per_op_ns("x = f(h)") - empty;
  std::printf("%-36s %8.1f ns\n", "plain table field read (t.next)", table_read);
  std::printf("%-36s %8.1f ns\n", "C function call (f(h))", c_call);
  std::printf("%-36s %8.1f ns\n", "empty C __index (u.next)", per_op_ns("x = u.next") - empty);
  const double new_userdata = per_op_ns("x = w.next") - empty;
  std::printf("%-36s %8.1f ns\n", "C __index making a userdata (w.next)", new_userdata);
  const double handle_read = per_op_ns("x = h.next") - empty;
  std::printf("%-36s %8.1f ns  (%.1fx a table read plus a C call; the binding's own share %.1f ns)\n",
              "handle field read (h.next)", handle_read, handle_read / (table_read + c_call),
              handle_read - new_userdata);
  std::printf("%-36s %8.1f ns\n", "handle field write (h.next = n)", per_op_ns("h.next = n") - empty);
  const double position_read = per_op_ns("x = v.position") - empty;
  const double lua_vec3 = per_op_ns("x = setmetatable({x = 1.5, y = 2.5, z = i}, mt)") - empty;
  std::printf("%-36s %8.1f ns\n", "{x, y, z} with a metatable, in Lua", lua_vec3);
  std::printf("%-36s %8.1f ns  (%.2fx making the same vec3 in Lua)\n", "position read (v.position)", position_read,
              position_read / lua_vec3);
  std::printf("%-36s %8.1f ns\n", "method call (v:degree())", per_op_ns("x = v:degree()") - empty);
  const double iterate =
      min_ms(
          reps, [] {}, [&] { lua.run_string("for i = 1, 10 do for h in mesh:halfedges() do end end", "bench.lua"); }) *
      1e6 / (10.0 * double(mesh->num_halfedges()));
  std::printf("%-36s %8.1f ns per halfedge\n", "iteration (mesh:halfedges())", iterate);

  HalfedgeMesh work;
  const double core_ms = min_ms(
      reps, [&] { work = original; }, [&] { loop_subdivide(work, LoopWeights::Course); });
  std::printf("%-36s %8.2f ms  (%zu faces)\n", "core loop_subdivide (C++)", core_ms, work.num_faces());

  if (!fs::exists(upsample_path)) {
    std::printf("%-36s skipped: %s is absent\n", "Lua upsample", upsample_path.string().c_str());
    return 0;
  }
  try {
    lua.run_file(upsample_path);
    const double lua_ms = min_ms(
        reps, [&] { *mesh = original; }, [&] { lua.run_string("upsample(mesh)", "bench.lua"); });
    std::printf("%-36s %8.2f ms  (%zu faces, %.1fx the core)\n", "Lua upsample (student style)", lua_ms,
                mesh->num_faces(), lua_ms / core_ms);
  } catch (const std::exception& e) {
    std::printf("%-36s failed: %s\n", "Lua upsample", e.what());
    return 1;
  }
  return 0;
}
