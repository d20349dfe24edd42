# The web build's output, a static site in <build>/site (included by engine/app/CMakeLists.txt under emscripten):
# index.html (web/index.html: the page, its canvas and its start-up), student_code_worker.js
# (web/student_code_worker.js: the student's code in a Web Worker, for Check my work, Run mine and your_turn),
# meshedit.js, meshedit.wasm and meshedit.data, the last holding the files the program reads, packaged under
# MESHEDIT_DATA_DIR (/meshedit) as in the source tree (lessons/, shaders/, assets/, scripts/student/,
# scripts/exercises/, tests/grading/suites/: the course's suites Check my work runs), and the two DejaVu fonts where
# the window looks for them natively, with a Chinese font cut to the page's characters. Any static file server serves
# the folder as it is.
set(site_dir "${PROJECT_BINARY_DIR}/site")
set_target_properties(meshedit PROPERTIES RUNTIME_OUTPUT_DIRECTORY "${site_dir}" SUFFIX ".js")

set(MESHEDIT_FONT_FILES /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf
    /usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf CACHE STRING "The window's two fonts, packaged in the page")

set(packaged "")  # SHELL: keeps CMake from merging the repeated --preload-file options
foreach(folder lessons shaders assets scripts/student scripts/exercises tests/grading/suites)
  list(APPEND packaged "SHELL:--preload-file ${PROJECT_SOURCE_DIR}/${folder}@${MESHEDIT_DATA_DIR}/${folder}")
endforeach()
foreach(font IN LISTS MESHEDIT_FONT_FILES)
  list(APPEND packaged "SHELL:--preload-file ${font}@${font}")
endforeach()

# The Chinese font, cut down to the characters the page can show (scripts/font_subset.py), beside the DejaVu files
# where the window looks for it (ui/fonts.h). Without Debian's fonts-wqy-microhei or fonttools' pyftsubset the page is
# built without it, and the window says so when Chinese is chosen.
set(MESHEDIT_CJK_FONT /usr/share/fonts/truetype/wqy/wqy-microhei.ttc CACHE FILEPATH "The Chinese font the page's is cut from")
find_program(MESHEDIT_PYFTSUBSET pyftsubset)
list(GET MESHEDIT_FONT_FILES 0 first_font)
get_filename_component(font_dir "${first_font}" DIRECTORY)
set(cjk_subset "${PROJECT_BINARY_DIR}/fonts/WenQuanYiMicroHei.ttf")
if(EXISTS "${MESHEDIT_CJK_FONT}" AND MESHEDIT_PYFTSUBSET)
  file(GLOB subset_texts CONFIGURE_DEPENDS "${PROJECT_SOURCE_DIR}/lessons/*.lua"
       "${PROJECT_SOURCE_DIR}/assets/translations/*/*.po")
  add_custom_command(
    OUTPUT "${cjk_subset}"
    COMMAND ${CMAKE_COMMAND} -E make_directory "${PROJECT_BINARY_DIR}/fonts"
    COMMAND python3 "${PROJECT_SOURCE_DIR}/scripts/font_subset.py" "${PROJECT_SOURCE_DIR}"
            "${imgui_SOURCE_DIR}/imgui_draw.cpp" "${MESHEDIT_CJK_FONT}" "${cjk_subset}"
    DEPENDS ${subset_texts} "${PROJECT_SOURCE_DIR}/scripts/font_subset.py"
    COMMENT "The page's Chinese font (scripts/font_subset.py)")
  add_custom_target(meshedit_cjk_font DEPENDS "${cjk_subset}")
  add_dependencies(meshedit meshedit_cjk_font)
  list(APPEND packaged "SHELL:--preload-file ${cjk_subset}@${font_dir}/WenQuanYiMicroHei.ttf")
  set_property(TARGET meshedit APPEND PROPERTY LINK_DEPENDS "${cjk_subset}")
else()
  message(WARNING "no ${MESHEDIT_CJK_FONT} or pyftsubset (fonts-wqy-microhei, fonttools): the page has no Chinese font")
endif()

target_link_options(meshedit PRIVATE
  ${packaged}
  -sALLOW_MEMORY_GROWTH=1
  -sINITIAL_MEMORY=67108864
  -sTOTAL_STACK=5242880
  # The browser's storage (IndexedDB) for the student's saved files: web/index.html mounts it at /kept.
  -lidbfs.js
  # web/index.html writes the files the user hands the page with FS and gives their paths to the program with ccall.
  # The worker for student code (web/student_code_worker.js) copies calls in and results out through HEAPU8.
  "SHELL:-sEXPORTED_RUNTIME_METHODS=['ccall','FS','HEAPU8']")
# The packaged folders are read at link time: a change in them relinks the page.
file(GLOB_RECURSE packaged_files CONFIGURE_DEPENDS "${PROJECT_SOURCE_DIR}/lessons/*" "${PROJECT_SOURCE_DIR}/shaders/*"
     "${PROJECT_SOURCE_DIR}/assets/*" "${PROJECT_SOURCE_DIR}/scripts/student/*"
     "${PROJECT_SOURCE_DIR}/scripts/exercises/*" "${PROJECT_SOURCE_DIR}/tests/grading/suites/*")
set_property(TARGET meshedit APPEND PROPERTY LINK_DEPENDS ${packaged_files})

# The page itself: copied at configure time, and again whenever it changes (configure_file makes CMake watch it).
configure_file("${PROJECT_SOURCE_DIR}/web/index.html" "${site_dir}/index.html" COPYONLY)
configure_file("${PROJECT_SOURCE_DIR}/web/student_code_worker.js" "${site_dir}/student_code_worker.js" COPYONLY)
