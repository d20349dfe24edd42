# cmake -DPREFIX=... -P check_paths.cmake: fails unless `PREFIX/bin/meshedit paths` names, for each of its folders,
# the copy installed under PREFIX/share/meshedit (fonts too when the install has them), not the source tree's.
execute_process(COMMAND "${PREFIX}/bin/meshedit" paths RESULT_VARIABLE status OUTPUT_VARIABLE out)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "meshedit paths failed: ${status}")
endif()
set(folders lessons assets shaders scripts/student scripts/exercises tests/grading/suites)
if(EXISTS "${PREFIX}/share/meshedit/fonts")
  list(APPEND folders fonts)
endif()
foreach(folder ${folders})
  string(REGEX MATCH "(^|\n)${folder} +([^\n]*)" line "${out}")
  set(found "${CMAKE_MATCH_2}")
  if(NOT found STREQUAL "${PREFIX}/share/meshedit/${folder}")
    message(FATAL_ERROR "meshedit paths: ${folder} is '${found}', not the installed ${PREFIX}/share/meshedit/${folder}"
                        "\n${out}")
  endif()
endforeach()
message(STATUS "${out}")
