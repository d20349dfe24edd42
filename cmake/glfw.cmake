# meshedit::glfw natively: GLFW 3.3 or newer. Looked for as GLFW's own CMake package, find_package(glfw3 CONFIG)
# (Debian, Ubuntu, Homebrew and vcpkg all install it), then through pkg-config as glfw3.
find_package(glfw3 3.3 CONFIG QUIET)
if(TARGET glfw)
  add_library(meshedit::glfw ALIAS glfw)
  message(STATUS "GLFW: find_package(glfw3 CONFIG) in ${glfw3_DIR}")
  return()
endif()
pkg_check_modules(MESHEDIT_GLFW QUIET IMPORTED_TARGET glfw3>=3.3)
if(MESHEDIT_GLFW_FOUND)
  add_library(meshedit::glfw ALIAS PkgConfig::MESHEDIT_GLFW)
  message(STATUS "GLFW: pkg-config glfw3 (${MESHEDIT_GLFW_LINK_LIBRARIES})")
  return()
endif()
message(FATAL_ERROR "No GLFW 3.3 or newer. Tried find_package(glfw3 CONFIG) and pkg-config glfw3.\n"
                    "Install it (Debian, Ubuntu: libglfw3-dev; Homebrew: glfw; vcpkg: glfw3), or set glfw3_DIR to the "
                    "folder of its glfw3Config.cmake, or add the folder of its glfw3.pc to PKG_CONFIG_PATH.")
