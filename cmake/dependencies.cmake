# The third-party libraries every module links, under one set of names for both builds:
#   meshedit::glm meshedit::tinyxml2 meshedit::tinygltf meshedit::json meshedit::lua meshedit::stb
#   meshedit::imgui meshedit::imgui_backends meshedit::glfw meshedit::gl, and meshedit::egl (native only).
# Natively they are Debian's packages (find_package / pkg-config). In an emscripten build (web.cmake) they are the
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
  find_package(tinyxml2 REQUIRED)
  find_package(TinyGLTF REQUIRED)
  add_library(meshedit::tinyxml2 ALIAS tinyxml2::tinyxml2)
  add_library(meshedit::tinygltf ALIAS TinyGLTF::TinyGLTF)
endif()
if("script" IN_LIST MESHEDIT_MODULES)
  pkg_check_modules(LUA REQUIRED IMPORTED_TARGET lua5.4-c++)
  add_library(meshedit::lua ALIAS PkgConfig::LUA)
endif()
if("grade" IN_LIST MESHEDIT_MODULES OR "app" IN_LIST MESHEDIT_MODULES)
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
if("ui" IN_LIST MESHEDIT_MODULES)
  pkg_check_modules(IMGUI REQUIRED IMPORTED_TARGET imgui)
  add_library(meshedit::imgui ALIAS PkgConfig::IMGUI)
endif()
if(NOT "app" IN_LIST MESHEDIT_MODULES)
  return()
endif()
find_package(glfw3 REQUIRED)
add_library(meshedit::glfw ALIAS glfw)

# Dear ImGui's GLFW and OpenGL3 backends, compiled from the sources Debian's libimgui-dev ships.
set(IMGUI_BACKENDS_DIR /usr/share/doc/libimgui-dev/examples/backends CACHE PATH "ImGui backend sources")
add_library(imgui_backends STATIC ${IMGUI_BACKENDS_DIR}/imgui_impl_glfw.cpp ${IMGUI_BACKENDS_DIR}/imgui_impl_opengl3.cpp)
target_include_directories(imgui_backends SYSTEM PUBLIC /usr/include/imgui/backends)
target_link_libraries(imgui_backends PUBLIC PkgConfig::IMGUI glfw ${CMAKE_DL_LIBS})
# ImGui 1.86's GL loader fills 54 function pointers through an array declared with 53 (GL3WProcs::ptr): the union
# has room for all 54, so no memory is overrun, but the index is out of bounds for the array and UBSan stops there.
# The bug is in the header Debian ships, not ours: a sanitizer build does not check array bounds in these two files.
target_compile_options(imgui_backends PRIVATE -fno-sanitize=bounds)
add_library(meshedit::imgui_backends ALIAS imgui_backends)
