# cmake -DCLANG_FORMAT=<exe> -DGIT=<exe> -DSOURCE_DIR=<checkout> -P check_format.cmake
# Fails, listing the files, when a C++ file git knows differs from what
# clang-format makes of it.
if(NOT CLANG_FORMAT)
  message(FATAL_ERROR "clang-format not found: install Debian's clang-format (bash .ci/setup does)")
endif()
if(NOT GIT)
  message(FATAL_ERROR "git not found")
endif()
execute_process(COMMAND ${GIT} ls-files -- "*.cpp" "*.hpp" WORKING_DIRECTORY ${SOURCE_DIR}
                OUTPUT_VARIABLE listed RESULT_VARIABLE git_result OUTPUT_STRIP_TRAILING_WHITESPACE)
if(NOT git_result EQUAL 0 OR listed STREQUAL "")
  message(FATAL_ERROR "git ls-files found no C++ files in ${SOURCE_DIR}")
endif()
string(REPLACE "\n" ";" files "${listed}")
list(LENGTH files count)
execute_process(COMMAND ${CLANG_FORMAT} --dry-run --Werror ${files}
                WORKING_DIRECTORY ${SOURCE_DIR} RESULT_VARIABLE result
                ERROR_VARIABLE diagnostics)
if(NOT result EQUAL 0)
  string(REGEX MATCHALL "[^\n]*: error: code should be clang-formatted" offending "${diagnostics}")
  list(TRANSFORM offending REPLACE ":[0-9]+:[0-9]+: error: code should be clang-formatted" "")
  list(REMOVE_DUPLICATES offending)
  list(LENGTH offending bad)
  string(REPLACE ";" "\n  " offending "${offending}")
  message(FATAL_ERROR "${bad} of ${count} C++ files are not formatted "
                      "(clang-format -i <file>):\n  ${offending}")
endif()
message(STATUS "all ${count} C++ files are formatted")
