# `cmake --install BUILD --prefix PREFIX`: the program and the files it reads at run time, in the layout
# core/data_folders.h looks for beside it:
#   PREFIX/bin/meshedit
#   PREFIX/share/meshedit/{lessons,shaders,assets,scripts/student,scripts/exercises,scripts/api,fonts}
#   PREFIX/share/meshedit/tests/grading/suites: the course's suites, which File > Check my work runs
# fonts/ holds the two DejaVu files the window's text uses (ui/fonts.h), copied from MESHEDIT_INSTALL_FONTS_FROM when
# they are there (empty: none installed, and the program looks in Debian's font folder). The destinations are fixed:
# the program finds share/meshedit from bin/, so CMAKE_INSTALL_BINDIR and CMAKE_INSTALL_DATADIR do not move them.
install(TARGETS meshedit RUNTIME DESTINATION bin)

set(meshedit_share share/meshedit)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/lessons ${PROJECT_SOURCE_DIR}/shaders ${PROJECT_SOURCE_DIR}/assets
        DESTINATION ${meshedit_share})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/scripts/student ${PROJECT_SOURCE_DIR}/scripts/exercises
        ${PROJECT_SOURCE_DIR}/scripts/api DESTINATION ${meshedit_share}/scripts)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/tests/grading/suites DESTINATION ${meshedit_share}/tests/grading)

set(MESHEDIT_INSTALL_FONTS_FROM /usr/share/fonts/truetype/dejavu CACHE PATH
    "Folder of DejaVuSans.ttf and DejaVuSansMono.ttf to install with the program (empty: none)")
foreach(font DejaVuSans.ttf DejaVuSansMono.ttf)
  if(MESHEDIT_INSTALL_FONTS_FROM AND EXISTS "${MESHEDIT_INSTALL_FONTS_FROM}/${font}")
    install(FILES "${MESHEDIT_INSTALL_FONTS_FROM}/${font}" DESTINATION ${meshedit_share}/fonts)
  endif()
endforeach()
