# meshedit::lua natively: Lua 5.4 compiled as C++, so a Lua error unwinds C++ frames (script/lua_runtime.h). Looked
# for in this order, the first that works winning:
#   1. MESHEDIT_LUA_SOURCE_DIR, when set: those sources compiled here as C++ (lua_sources.cmake);
#   2. vcpkg's lua[cpp]: find_package(unofficial-lua CONFIG), target unofficial::lua::lua-cpp (C++ linkage);
#   3. pkg-config, the names of a C++ build: lua5.4-c++ (Debian, Ubuntu), lua-5.4-c++, lua54-c++, lua-c++, its functions
#      with C names (Debian 12, Ubuntu 22.04) or, failing that, with C++ names (Ubuntu 24.04);
#   4. pkg-config, the names of Lua built as C: lua5.4, lua-5.4, lua54, lua (Homebrew, vcpkg's plain lua);
#   5. CMake's FindLua module.
# A library from 2-5 is used only when a small program linked with it (lua_unwinds.cpp) shows that it is Lua 5.4 and
# that its errors run C++ destructors. Builds of Lua as C (Homebrew's, most distributions' plain liblua) do not, and
# are passed over: then MESHEDIT_LUA_SOURCE_DIR is the way, e.g. the src/ folder of a lua.org 5.4 release.
include(${CMAKE_CURRENT_LIST_DIR}/lua_sources.cmake)

set(MESHEDIT_LUA_SOURCE_DIR "" CACHE PATH "Lua 5.4 sources to compile as C++ instead of an installed Lua")
if(MESHEDIT_LUA_SOURCE_DIR)
  meshedit_lua_from_sources("${MESHEDIT_LUA_SOURCE_DIR}")
  message(STATUS "Lua: compiled as C++ from ${MESHEDIT_LUA_SOURCE_DIR}")
  return()
endif()

set(meshedit_lua_tried "")

# meshedit_lua_try(NAME TARGET): uses TARGET as meshedit::lua when lua_unwinds.cpp links and runs with it.
function(meshedit_lua_try name target)
  string(MAKE_C_IDENTIFIER "${name}" id)
  set(result MESHEDIT_LUA_UNWINDS_${id})
  if(NOT DEFINED ${result})
    try_run(run_result compile_result "${PROJECT_BINARY_DIR}/lua_unwinds/${id}"
            "${CMAKE_CURRENT_FUNCTION_LIST_DIR}/lua_unwinds.cpp"
            LINK_LIBRARIES ${target})
    if(compile_result AND run_result EQUAL 0)
      set(${result} ON CACHE INTERNAL "")
    else()
      set(${result} OFF CACHE INTERNAL "")
    endif()
  endif()
  if(${result})
    add_library(meshedit::lua ALIAS ${target})
    message(STATUS "Lua: ${name}")
  else()
    set(why "found, but not Lua 5.4 built as C++ (cmake/lua_unwinds.cpp)")
    set(meshedit_lua_tried "${meshedit_lua_tried}\n  ${name}: ${why}" PARENT_SCOPE)
  endif()
endfunction()

# 2. vcpkg
find_package(unofficial-lua CONFIG QUIET)
if(TARGET unofficial::lua::lua-cpp)
  add_library(meshedit_lua_vcpkg INTERFACE IMPORTED)
  target_link_libraries(meshedit_lua_vcpkg INTERFACE unofficial::lua::lua-cpp)
  meshedit_lua_cxx_linkage_header(meshedit_lua_vcpkg)
  meshedit_lua_try("vcpkg's unofficial::lua::lua-cpp" meshedit_lua_vcpkg)
elseif(TARGET unofficial::lua::lua)
  set(meshedit_lua_tried "${meshedit_lua_tried}\n  vcpkg's unofficial-lua: no lua-cpp (install lua[cpp])")
else()
  set(meshedit_lua_tried "${meshedit_lua_tried}\n  find_package(unofficial-lua CONFIG) (vcpkg's lua[cpp]): not found")
endif()

# 3 and 4. pkg-config
foreach(names IN ITEMS "lua5.4-c++;lua-5.4-c++;lua54-c++;lua-c++" "lua5.4;lua-5.4;lua54;lua")
  if(TARGET meshedit::lua)
    break()
  endif()
  string(MAKE_C_IDENTIFIER "MESHEDIT_PC_${names}" prefix)
  pkg_search_module(${prefix} QUIET IMPORTED_TARGET ${names})
  if(${prefix}_FOUND)
    meshedit_lua_try("pkg-config ${${prefix}_MODULE_NAME} (${${prefix}_LINK_LIBRARIES})" PkgConfig::${prefix})
    if(NOT TARGET meshedit::lua AND names MATCHES "c\\+\\+")
      # Debian 12 builds its liblua5.4-c++ with C names; Ubuntu 24.04 with C++ names, for headers without extern "C".
      add_library(${prefix}_cxx_names INTERFACE IMPORTED)
      target_link_libraries(${prefix}_cxx_names INTERFACE PkgConfig::${prefix})
      meshedit_lua_cxx_linkage_header(${prefix}_cxx_names)
      meshedit_lua_try("pkg-config ${${prefix}_MODULE_NAME} with C++ names (${${prefix}_LINK_LIBRARIES})"
                       ${prefix}_cxx_names)
    endif()
  else()
    string(REPLACE ";" ", " shown "${names}")
    set(meshedit_lua_tried "${meshedit_lua_tried}\n  pkg-config ${shown}: not found")
  endif()
endforeach()

# 5. FindLua
if(NOT TARGET meshedit::lua)
  find_package(Lua 5.4 QUIET)
  if(LUA_FOUND)
    add_library(meshedit_lua_module INTERFACE IMPORTED)
    target_include_directories(meshedit_lua_module SYSTEM INTERFACE ${LUA_INCLUDE_DIR})
    target_link_libraries(meshedit_lua_module INTERFACE ${LUA_LIBRARIES})
    meshedit_lua_try("FindLua (${LUA_LIBRARIES})" meshedit_lua_module)
  else()
    set(meshedit_lua_tried "${meshedit_lua_tried}\n  find_package(Lua 5.4) (CMake's FindLua): not found")
  endif()
endif()

if(NOT TARGET meshedit::lua)
  message(FATAL_ERROR "No Lua 5.4 built as C++ (an error must unwind C++ frames). Tried:${meshedit_lua_tried}\n"
                      "Install one (Debian, Ubuntu: liblua5.4-dev; vcpkg: lua[cpp]), or set MESHEDIT_LUA_SOURCE_DIR "
                      "to Lua 5.4's sources (the src/ folder of a lua.org release, or a checkout of github.com/lua/lua) "
                      "to compile them as C++ here (Homebrew's lua is built as C).")
endif()
