// Configure-time check (cmake/lua.cmake): exits 0 when the Lua it is linked with is 5.4 and a Lua error unwinds the
// C++ frames it passes (a destructor runs), as it does when Lua is compiled as C++; a Lua compiled as C jumps over
// them with longjmp, and the destructor never runs.
#include <lua.hpp>

#if LUA_VERSION_NUM != 504
#error "not Lua 5.4"
#endif

namespace {

bool unwound = false;

struct Mark {
  Mark() = default;
  Mark(const Mark&) = delete;
  Mark& operator=(const Mark&) = delete;
  ~Mark() { unwound = true; }
};

int raise_error(lua_State* L) {
  const Mark mark;
  lua_pushliteral(L, "an error");
  return lua_error(L);
}

}  // namespace

int main() {
  lua_State* L = luaL_newstate();
  if (L == nullptr) return 2;
  lua_pushcfunction(L, raise_error);
  const int status = lua_pcall(L, 0, 0, 0);
  lua_close(L);
  return status == LUA_ERRRUN && unwound ? 0 : 1;
}
