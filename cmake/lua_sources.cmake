# Lua 5.4 compiled here from its sources, as C++ so an error unwinds C++ frames (script/lua_runtime.h), for the web
# build (web.cmake) and natively when no C++ build of Lua is installed (lua.cmake).
#
# meshedit_lua_cxx_linkage_header(TARGET): gives TARGET's users a lua.hpp that includes Lua's headers without
#   extern "C", for a Lua compiled as C++ with C++ linkage (the engine includes <lua.hpp>, whose upstream text wraps
#   the headers in extern "C" for a Lua compiled as C).
# meshedit_lua_from_sources(DIR): the library meshedit_lua from DIR, a folder holding lapi.c, lua.h and the rest (a
#   checkout of github.com/lua/lua, or a lua.org release's src/), and the alias meshedit::lua.

function(meshedit_lua_cxx_linkage_header target)
  set(dir "${PROJECT_BINARY_DIR}/lua_cxx_linkage")
  # file(CONFIGURE) writes it only when its text changes, so a new configure recompiles nothing.
  file(CONFIGURE OUTPUT "${dir}/lua.hpp" CONTENT "// Lua 5.4 compiled as C++: its headers without extern \"C\".
#include \"lua.h\"
#include \"lualib.h\"
#include \"lauxlib.h\"
")
  target_include_directories(${target} SYSTEM BEFORE INTERFACE "${dir}")
endfunction()

function(meshedit_lua_from_sources dir)
  if(NOT EXISTS "${dir}/lapi.c" OR NOT EXISTS "${dir}/lua.h")
    message(FATAL_ERROR "${dir} holds no Lua sources (lapi.c, lua.h): it should be a checkout of github.com/lua/lua "
                        "or the src/ folder of a lua.org 5.4 release")
  endif()
  # The 32 library files (not the lua/luac programs, onelua.c or the test library).
  set(lua_files lapi lauxlib lbaselib lcode lcorolib lctype ldblib ldebug ldo ldump lfunc lgc linit liolib llex
      lmathlib lmem loadlib lobject lopcodes loslib lparser lstate lstring lstrlib ltable ltablib ltm lundump
      lutf8lib lvm lzio)
  list(TRANSFORM lua_files PREPEND "${dir}/")
  list(TRANSFORM lua_files APPEND ".c")
  add_library(meshedit_lua STATIC ${lua_files})
  set_source_files_properties(${lua_files} PROPERTIES LANGUAGE CXX)
  if(MSVC)
    target_compile_options(meshedit_lua PRIVATE /TP /w)
  else()
    target_compile_options(meshedit_lua PRIVATE -x c++ -w)
  endif()
  # As Debian builds it (and the upstream release makefile): with Lua 5.3's compatibility functions (math.pow...).
  target_compile_definitions(meshedit_lua PUBLIC LUA_COMPAT_5_3)
  target_include_directories(meshedit_lua SYSTEM PUBLIC "${dir}")
  meshedit_lua_cxx_linkage_header(meshedit_lua)
  add_library(meshedit::lua ALIAS meshedit_lua)
endfunction()
