# np_checked_program(NAME name TEST test SOURCES file... EXPECTED regex): builds the program
# `name` on the package and, with the tests on, registers the test `test` that runs it and checks its exit status and its output against the regular expression (kept in a file: the
# expressions hold characters a command line would eat; np_check_output.cmake).
function(np_checked_program)
  cmake_parse_arguments(P "" "NAME;TEST;EXPECTED" "SOURCES" ${ARGN})
  add_executable(${P_NAME} ${P_SOURCES})
  target_link_libraries(${P_NAME} PRIVATE CGAL::Norm_preserving_parameterization np_warnings)
  target_compile_definitions(${P_NAME} PRIVATE NP_MESH_DIR="${NP_MESH_DIR}")
  if(NP_BUILD_TESTS)
    file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/${P_NAME}.expected "${P_EXPECTED}")
    add_test(NAME ${P_TEST}
             COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:${P_NAME}> -DEXPECTED=${CMAKE_CURRENT_BINARY_DIR}/${P_NAME}.expected
                     -P ${PROJECT_SOURCE_DIR}/cmake/np_check_output.cmake
             WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  endif()
endfunction()
