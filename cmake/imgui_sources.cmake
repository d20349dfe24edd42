# Dear ImGui compiled here from its sources: for the web build (web.cmake) and natively from IMGUI_DIR (imgui.cmake).
#
# meshedit_imgui_from_sources(DIR): meshedit_imgui and the alias meshedit::imgui from a checkout of
#   github.com/ocornut/imgui (v1.86): the core, the demo window and misc/cpp/imgui_stdlib.
# meshedit_imgui_backends_from_sources(SOURCE_DIR INCLUDE_DIR IMGUI): meshedit_imgui_backends and the alias
#   meshedit::imgui_backends: the GLFW and OpenGL3 backends of SOURCE_DIR (their headers in INCLUDE_DIR), linked with
#   the target IMGUI and meshedit::glfw.

function(meshedit_imgui_from_sources dir)
  if(NOT EXISTS "${dir}/imgui.cpp" OR NOT EXISTS "${dir}/misc/cpp/imgui_stdlib.cpp")
    message(FATAL_ERROR "${dir} is not a Dear ImGui checkout (no imgui.cpp, misc/cpp/imgui_stdlib.cpp)")
  endif()
  add_library(meshedit_imgui STATIC "${dir}/imgui.cpp" "${dir}/imgui_draw.cpp" "${dir}/imgui_tables.cpp"
              "${dir}/imgui_widgets.cpp" "${dir}/imgui_demo.cpp" "${dir}/misc/cpp/imgui_stdlib.cpp")
  target_include_directories(meshedit_imgui SYSTEM PUBLIC "${dir}" "${dir}/misc/cpp")
  target_compile_options(meshedit_imgui PRIVATE $<IF:$<CXX_COMPILER_ID:MSVC>,/w,-w>)
  add_library(meshedit::imgui ALIAS meshedit_imgui)
endfunction()

function(meshedit_imgui_backends_from_sources source_dir include_dir imgui)
  foreach(file imgui_impl_glfw.cpp imgui_impl_opengl3.cpp)
    if(NOT EXISTS "${source_dir}/${file}")
      message(FATAL_ERROR "No ImGui backend ${source_dir}/${file}")
    endif()
  endforeach()
  add_library(meshedit_imgui_backends STATIC "${source_dir}/imgui_impl_glfw.cpp" "${source_dir}/imgui_impl_opengl3.cpp")
  target_include_directories(meshedit_imgui_backends SYSTEM PUBLIC "${include_dir}")
  target_compile_options(meshedit_imgui_backends PRIVATE $<IF:$<CXX_COMPILER_ID:MSVC>,/w,-w>)
  target_link_libraries(meshedit_imgui_backends PUBLIC ${imgui} meshedit::glfw)
  if(NOT EMSCRIPTEN)
    target_link_libraries(meshedit_imgui_backends PUBLIC ${CMAKE_DL_LIBS})  # the OpenGL3 backend loads GL itself
  endif()
  add_library(meshedit::imgui_backends ALIAS meshedit_imgui_backends)
endfunction()
