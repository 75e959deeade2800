# Tests that run in a real Blender, headless: Debian's blender with its factory settings (no
# user preference or add-on interferes), the script's uncaught exception failing the test
# (--python-exit-code). Without blender the tests are still registered, and fail saying so.
#
# Also np_failing_test(), for every test whose program is missing.

# np_failing_test(NAME name MESSAGE text): a test that prints `text` and fails (exit 1).
set(NP_FAILING_TEST_SCRIPT ${CMAKE_BINARY_DIR}/np_failing_test.cmake)
file(WRITE ${NP_FAILING_TEST_SCRIPT} "# Written by cmake/NP_blender.cmake: a test whose program is missing.\n"
                                     "message(FATAL_ERROR \"\${MESSAGE}\")\n")
function(np_failing_test)
  cmake_parse_arguments(T "" "NAME;MESSAGE" "" ${ARGN})
  add_test(NAME ${T_NAME} COMMAND ${CMAKE_COMMAND} "-DMESSAGE=${T_MESSAGE}" -P ${NP_FAILING_TEST_SCRIPT})
endfunction()

find_program(NP_BLENDER blender)
if(NOT NP_BLENDER)
  message(STATUS "blender not found: the Blender tests will fail (apt-get install blender)")
endif()

# np_blender_test(NAME name SCRIPT script.py [ENV VAR=value...] [ARGS arg...]): runs
#   VAR=value... blender -b --factory-startup --python-exit-code 1 --python script.py -- arg...
function(np_blender_test)
  cmake_parse_arguments(T "" "NAME;SCRIPT" "ARGS;ENV" ${ARGN})
  if(NP_BLENDER)
    add_test(NAME ${T_NAME}
             COMMAND ${CMAKE_COMMAND} -E env ${T_ENV}
                     ${NP_BLENDER} -b --factory-startup --python-exit-code 1 --python ${T_SCRIPT} -- ${T_ARGS})
  else()
    np_failing_test(NAME ${T_NAME} MESSAGE "blender not found: apt-get install blender")
  endif()
endfunction()
