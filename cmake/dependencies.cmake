# The third-party libraries every module links, under one set of names for both builds:
#   meshedit::glm meshedit::tinyxml2 meshedit::tinygltf meshedit::json meshedit::lua meshedit::stb
#   meshedit::imgui meshedit::imgui_backends meshedit::glfw meshedit::gl, and meshedit::egl (native only).
# Natively they are the installed packages (find_package / pkg-config), looked for under the names Debian, Ubuntu,
# Homebrew and vcpkg give them: Lua in lua.cmake, ImGui in imgui.cmake, GLFW in glfw.cmake, each saying at configure
# time what it found, or what it tried and which variable to set. In an emscripten build (web.cmake) they are the
# pinned upstream sources compiled to WebAssembly and the header-only libraries through an include folder of their
# own. A module links the names and never asks which build it is in. Natively only the libraries of the modules in
# MESHEDIT_MODULES are looked for.
if(EMSCRIPTEN)
  include(${CMAKE_CURRENT_LIST_DIR}/web.cmake)
  return()
endif()

find_package(glm REQUIRED)
add_library(meshedit::glm ALIAS glm::glm)
find_package(PkgConfig REQUIRED)
if("io" IN_LIST MESHEDIT_MODULES)
  # Debian 12 ships tinyxml2's CMake package; Ubuntu 22.04 (Gradescope's image) only its pkg-config file.
  find_package(tinyxml2 CONFIG QUIET)
  if(tinyxml2_FOUND)
    add_library(meshedit::tinyxml2 ALIAS tinyxml2::tinyxml2)
  else()
    pkg_check_modules(TINYXML2 REQUIRED IMPORTED_TARGET tinyxml2)
    add_library(meshedit::tinyxml2 ALIAS PkgConfig::TINYXML2)
  endif()
  find_package(TinyGLTF REQUIRED)
  add_library(meshedit::tinygltf ALIAS TinyGLTF::TinyGLTF)
endif()
if("script" IN_LIST MESHEDIT_MODULES)
  include(${CMAKE_CURRENT_LIST_DIR}/lua.cmake)
endif()
if("exercise" IN_LIST MESHEDIT_MODULES)  # the exercises' student calls as bytes, the grader's reports
  find_package(nlohmann_json REQUIRED)
  add_library(meshedit::json ALIAS nlohmann_json::nlohmann_json)
endif()
if("render" IN_LIST MESHEDIT_MODULES)
  pkg_check_modules(EPOXY REQUIRED IMPORTED_TARGET epoxy)
  pkg_check_modules(EGL REQUIRED IMPORTED_TARGET egl)
  pkg_check_modules(STB REQUIRED IMPORTED_TARGET stb)
  add_library(meshedit::gl ALIAS PkgConfig::EPOXY)
  add_library(meshedit::egl ALIAS PkgConfig::EGL)
  add_library(meshedit::stb ALIAS PkgConfig::STB)
endif()
if("app" IN_LIST MESHEDIT_MODULES)
  include(${CMAKE_CURRENT_LIST_DIR}/glfw.cmake)
endif()
if("ui" IN_LIST MESHEDIT_MODULES)
  include(${CMAKE_CURRENT_LIST_DIR}/imgui.cmake)  # and the backends when the app is built
endif()
