# meshedit::imgui natively: Dear ImGui 1.86 with imgui_stdlib; and, when the app is built, meshedit::imgui_backends:
# its GLFW and OpenGL3 backends. Looked for in this order, the first found winning:
#   1. IMGUI_DIR, when set: a checkout of github.com/ocornut/imgui at v1.86, compiled here with its backends. Homebrew
#      has no ImGui: on macOS, point IMGUI_DIR at a checkout;
#   2. find_package(imgui CONFIG), target imgui::imgui: vcpkg's imgui[glfw-binding,opengl3-binding], which has the
#      backends compiled in;
#   3. pkg-config imgui: Debian's and Ubuntu's libimgui-dev, whose backend sources (IMGUI_BACKENDS_DIR) are compiled
#      here.
include(${CMAKE_CURRENT_LIST_DIR}/imgui_sources.cmake)

set(IMGUI_DIR "" CACHE PATH "A Dear ImGui 1.86 checkout to compile instead of an installed ImGui")
set(IMGUI_BACKENDS_DIR /usr/share/doc/libimgui-dev/examples/backends CACHE PATH
    "The ImGui backend sources of an ImGui found by pkg-config (Debian's libimgui-dev)")
set(meshedit_imgui_backends_wanted OFF)
if("app" IN_LIST MESHEDIT_MODULES)
  set(meshedit_imgui_backends_wanted ON)
endif()

# ImGui 1.86's GL loader fills 54 function pointers through an array declared with 53 (GL3WProcs::ptr): the union
# has room for all 54, so no memory is overrun, but the index is out of bounds for the array and UBSan stops there.
# The bug is in ImGui's header, not ours: a sanitizer build does not check array bounds in the backends it compiles.
function(meshedit_imgui_backends_unchecked)
  if(NOT MSVC)
    target_compile_options(meshedit_imgui_backends PRIVATE -fno-sanitize=bounds)
  endif()
endfunction()

# 1. A checkout
if(IMGUI_DIR)
  meshedit_imgui_from_sources("${IMGUI_DIR}")
  if(meshedit_imgui_backends_wanted)
    meshedit_imgui_backends_from_sources("${IMGUI_DIR}/backends" "${IMGUI_DIR}/backends" meshedit_imgui)
    meshedit_imgui_backends_unchecked()
  endif()
  message(STATUS "ImGui: compiled from ${IMGUI_DIR}")
  return()
endif()

# 2. vcpkg
find_package(imgui CONFIG QUIET)
if(TARGET imgui::imgui)
  add_library(meshedit::imgui ALIAS imgui::imgui)
  if(meshedit_imgui_backends_wanted)
    get_target_property(imgui_includes imgui::imgui INTERFACE_INCLUDE_DIRECTORIES)
    find_file(MESHEDIT_IMGUI_IMPL_GLFW imgui_impl_glfw.h PATHS ${imgui_includes} PATH_SUFFIXES backends NO_DEFAULT_PATH)
    if(NOT MESHEDIT_IMGUI_IMPL_GLFW)
      message(FATAL_ERROR "find_package(imgui CONFIG) found ImGui in ${imgui_DIR} without its GLFW backend: install "
                          "imgui[glfw-binding,opengl3-binding] (vcpkg), or set IMGUI_DIR to a Dear ImGui 1.86 checkout")
    endif()
    add_library(meshedit_imgui_backends INTERFACE)
    target_link_libraries(meshedit_imgui_backends INTERFACE imgui::imgui meshedit::glfw)
    add_library(meshedit::imgui_backends ALIAS meshedit_imgui_backends)
  endif()
  message(STATUS "ImGui: find_package(imgui CONFIG) in ${imgui_DIR}")
  return()
endif()

# 3. pkg-config
pkg_check_modules(MESHEDIT_IMGUI QUIET IMPORTED_TARGET imgui)
if(MESHEDIT_IMGUI_FOUND)
  add_library(meshedit::imgui ALIAS PkgConfig::MESHEDIT_IMGUI)
  if(meshedit_imgui_backends_wanted)
    # The backends' headers sit in backends/ of the include folder (Debian: /usr/include/imgui/backends).
    meshedit_imgui_backends_from_sources("${IMGUI_BACKENDS_DIR}" "${MESHEDIT_IMGUI_INCLUDEDIR}/backends"
                                         PkgConfig::MESHEDIT_IMGUI)
    meshedit_imgui_backends_unchecked()
  endif()
  message(STATUS "ImGui: pkg-config imgui (${MESHEDIT_IMGUI_LINK_LIBRARIES})")
  return()
endif()

message(FATAL_ERROR "No Dear ImGui. Tried find_package(imgui CONFIG) (vcpkg: imgui[glfw-binding,opengl3-binding]) "
                    "and pkg-config imgui (Debian, Ubuntu: libimgui-dev).\n"
                    "Install one, or set IMGUI_DIR to a checkout of https://github.com/ocornut/imgui at v1.86 "
                    "(on macOS: Homebrew has no ImGui).")
