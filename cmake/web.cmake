# The third-party libraries of the WebAssembly build (included by dependencies.cmake under emscripten), with the
# names dependencies.cmake lists. The pinned upstream releases (ImGui 1.86, Lua 5.4.6, tinyxml2 9.0.0) come from
# MESHEDIT_VENDOR_DIR when it is set (the archives and their SHA256SUMS, e.g. ../shared/vendor) and are downloaded
# from their upstream tags otherwise; either way the archive must match the hash below, and nothing of them is copied
# into the repository. The header-only libraries (GLM, tinygltf, stb, nlohmann-json) are taken from
# MESHEDIT_HEADER_ONLY_DIR (Debian's /usr/include) through a folder of links to them alone, so no header of this
# machine's C library reaches the WebAssembly build.
include(FetchContent)

set(MESHEDIT_VENDOR_DIR "" CACHE PATH "Folder of the pinned upstream archives (empty: download from upstream)")
set(MESHEDIT_HEADER_ONLY_DIR /usr/include CACHE PATH "Folder holding glm/, nlohmann/, tiny_gltf.h and stb/")

# Every target of the web build: C++ exceptions on (Lua's errors and the engine's both unwind).
add_compile_options(-fexceptions)
add_link_options(-fexceptions)

# meshedit_vendor_source(NAME ARCHIVE UPSTREAM_URL SHA256): FetchContent from the vendor folder or upstream.
function(meshedit_vendor_source name archive upstream hash)
  if(MESHEDIT_VENDOR_DIR)
    set(url "${MESHEDIT_VENDOR_DIR}/${archive}")
    if(NOT EXISTS "${url}")
      message(FATAL_ERROR "MESHEDIT_VENDOR_DIR=${MESHEDIT_VENDOR_DIR} has no ${archive}")
    endif()
  else()
    set(url "${upstream}")
  endif()
  set(timestamp "")
  if(CMAKE_VERSION VERSION_GREATER_EQUAL 3.24)
    set(timestamp DOWNLOAD_EXTRACT_TIMESTAMP TRUE)  # the unpacked files carry the archive's times (3.24's default)
  endif()
  FetchContent_Declare(${name} URL "${url}" URL_HASH SHA256=${hash} ${timestamp})
  FetchContent_GetProperties(${name})
  if(NOT ${name}_POPULATED)
    FetchContent_Populate(${name})
  endif()
  set(${name}_SOURCE_DIR "${${name}_SOURCE_DIR}" PARENT_SCOPE)
endfunction()

meshedit_vendor_source(imgui imgui-1.86.tar.gz https://github.com/ocornut/imgui/archive/refs/tags/v1.86.tar.gz
                       f4cb47d9ffb19b1fcd1a193e5e6c1b0cb13f603498014e33713e3792c1f3c95b)
meshedit_vendor_source(lua lua-5.4.6.tar.gz https://github.com/lua/lua/archive/refs/tags/v5.4.6.tar.gz
                       9a2c76df0d7843eed36a41a364b8c4ac565be0815c863ab7f3c4a51b6dc6ca31)
meshedit_vendor_source(tinyxml2 tinyxml2-9.0.0.tar.gz
                       https://github.com/leethomason/tinyxml2/archive/refs/tags/9.0.0.tar.gz
                       314a5cd2e21f1deef0a2def58ddbd304e4de2038e1d6ca2bdf45e74c24f13719)

# The header-only libraries: links in the build folder, one per library.
set(header_only "${PROJECT_BINARY_DIR}/header_only")
file(MAKE_DIRECTORY "${header_only}")
foreach(entry glm nlohmann tiny_gltf.h stb/stb_image.h stb/stb_image_write.h)
  get_filename_component(link_name "${entry}" NAME)
  if(NOT EXISTS "${MESHEDIT_HEADER_ONLY_DIR}/${entry}")
    message(FATAL_ERROR "MESHEDIT_HEADER_ONLY_DIR=${MESHEDIT_HEADER_ONLY_DIR} has no ${entry}")
  endif()
  file(CREATE_LINK "${MESHEDIT_HEADER_ONLY_DIR}/${entry}" "${header_only}/${link_name}" SYMBOLIC)
endforeach()

add_library(meshedit_header_only INTERFACE)
target_include_directories(meshedit_header_only SYSTEM INTERFACE "${header_only}")
add_library(meshedit::glm ALIAS meshedit_header_only)
add_library(meshedit::json ALIAS meshedit_header_only)

# tinygltf and stb_image(_write): their implementations in one translation unit (Debian ships them compiled).
add_library(meshedit_header_only_impl STATIC ${CMAKE_CURRENT_LIST_DIR}/web/header_only_impl.cpp)
target_link_libraries(meshedit_header_only_impl PUBLIC meshedit_header_only)
add_library(meshedit::tinygltf ALIAS meshedit_header_only_impl)
add_library(meshedit::stb ALIAS meshedit_header_only_impl)

# Lua 5.4.6 compiled as C++ so an error unwinds C++ frames, as Debian's lua5.4-c++ does natively (lua_sources.cmake).
include(${CMAKE_CURRENT_LIST_DIR}/lua_sources.cmake)
meshedit_lua_from_sources("${lua_SOURCE_DIR}")

# tinyxml2 9.0.0: one file.
add_library(meshedit_tinyxml2 STATIC "${tinyxml2_SOURCE_DIR}/tinyxml2.cpp")
target_include_directories(meshedit_tinyxml2 SYSTEM PUBLIC "${tinyxml2_SOURCE_DIR}")
target_compile_options(meshedit_tinyxml2 PRIVATE -w)
add_library(meshedit::tinyxml2 ALIAS meshedit_tinyxml2)

# Dear ImGui 1.86: the core, imgui_stdlib, and the GLFW and OpenGL3 backends (WebGL 2 through emscripten's GLES3),
# below (imgui_sources.cmake).
include(${CMAKE_CURRENT_LIST_DIR}/imgui_sources.cmake)
meshedit_imgui_from_sources("${imgui_SOURCE_DIR}")

# The browser's GLFW (emscripten's port) and WebGL 2 with all of OpenGL ES 3.0.
add_library(meshedit_web_glfw INTERFACE)
target_link_options(meshedit_web_glfw INTERFACE -sUSE_GLFW=3)
add_library(meshedit::glfw ALIAS meshedit_web_glfw)
add_library(meshedit_web_gl INTERFACE)
target_link_options(meshedit_web_gl INTERFACE -sUSE_WEBGL2=1 -sMIN_WEBGL_VERSION=2 -sMAX_WEBGL_VERSION=2 -sFULL_ES3=1)
add_library(meshedit::gl ALIAS meshedit_web_gl)

meshedit_imgui_backends_from_sources("${imgui_SOURCE_DIR}/backends" "${imgui_SOURCE_DIR}/backends" meshedit_imgui)
# ImGui 1.86 takes emscripten for WebGL 1 (GLES 2, no vertex arrays); the page has WebGL 2, whose GLES 3 the backend
# then uses with its own vertex array, as on the desktop.
target_compile_definitions(meshedit_imgui_backends PRIVATE IMGUI_IMPL_OPENGL_ES3)
target_link_libraries(meshedit_imgui_backends PUBLIC meshedit_web_gl)
