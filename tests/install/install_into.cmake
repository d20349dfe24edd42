# cmake -DBUILD_DIR=... -DPREFIX=... [-DCONFIG=...] -P install_into.cmake: installs the build into PREFIX, emptied
# first, as `cmake --install BUILD_DIR --prefix PREFIX` does for a user, and fails unless the program and each folder
# of its files (cmake/install.cmake) are there.
file(REMOVE_RECURSE "${PREFIX}")
set(config_args "")
if(CONFIG)
  set(config_args --config "${CONFIG}")
endif()
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${PREFIX}" ${config_args}
                RESULT_VARIABLE status OUTPUT_QUIET)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "cmake --install ${BUILD_DIR} --prefix ${PREFIX} failed: ${status}")
endif()
foreach(path bin/meshedit share/meshedit/lessons/4_edge_flip.lua share/meshedit/shaders/face.vert
        share/meshedit/assets/teapot.bez share/meshedit/scripts/student/flip.lua
        share/meshedit/scripts/exercises/collapse.lua share/meshedit/scripts/api/meshedit.lua
        share/meshedit/tests/grading/suites/all.lua)
  if(NOT EXISTS "${PREFIX}/${path}")
    message(FATAL_ERROR "the install has no ${PREFIX}/${path}")
  endif()
endforeach()
