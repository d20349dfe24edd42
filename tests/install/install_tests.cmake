# The installed program (cmake/install.cmake), run from a prefix in the build tree that install_into_prefix empties
# and fills first: its `paths` name the installed folders, not the source tree's; lesson 4 runs headless from the
# installed lessons/ (with the installed scripts/exercises) and lesson 2 opens the installed teapot beside them;
# `demo` opens its default asset, and `render` draws the installed Suzanne with the installed shaders.
set(prefix "${PROJECT_BINARY_DIR}/install-test")
set(installed "${prefix}/bin/meshedit")
set(share "${prefix}/share/meshedit")
set(answers "${PROJECT_SOURCE_DIR}/tests/lesson/lessons")
set(solutions "${PROJECT_SOURCE_DIR}/tests/exercise/solutions")

add_test(NAME install_into_prefix
         COMMAND ${CMAKE_COMMAND} -DBUILD_DIR=${PROJECT_BINARY_DIR} -DPREFIX=${prefix} -DCONFIG=$<CONFIG>
                 -P ${CMAKE_CURRENT_LIST_DIR}/install_into.cmake)
set_tests_properties(install_into_prefix PROPERTIES FIXTURES_SETUP meshedit_installed)

add_test(NAME installed_paths COMMAND ${CMAKE_COMMAND} -DPREFIX=${prefix} -P ${CMAKE_CURRENT_LIST_DIR}/check_paths.cmake)
add_test(NAME installed_lesson_4_edge_flip
         COMMAND ${installed} lesson ${share}/lessons/4_edge_flip.lua --headless
                 --answers ${answers}/4_edge_flip_answers.lua --student ${solutions})
add_test(NAME installed_lesson_2_bezier_patches
         COMMAND ${installed} lesson ${share}/lessons/2_bezier_patches.lua --headless
                 --answers ${answers}/2_bezier_patches_answers.lua --student ${solutions})
add_test(NAME installed_demo COMMAND ${installed} demo)
add_test(NAME installed_render
         COMMAND ${installed} render ${share}/assets/suzanne.obj -o ${CMAKE_CURRENT_BINARY_DIR}/installed_render.png
                 --size 160x120)
set(installed_tests installed_paths installed_lesson_4_edge_flip installed_lesson_2_bezier_patches installed_demo
    installed_render)
# MESHEDIT_SHADERS and MESHEDIT_FONT_DIR would come before the installed folders: the tests run without them.
set_tests_properties(${installed_tests} PROPERTIES FIXTURES_REQUIRED meshedit_installed TIMEOUT 300 LABELS install
                     ENVIRONMENT "MESHEDIT_SHADERS=;MESHEDIT_FONT_DIR=")
set_tests_properties(installed_demo PROPERTIES PASS_REGULAR_EXPRESSION "loaded ${share}/assets/teapot\\.bez")
