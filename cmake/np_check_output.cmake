# Runs one program, as ctest does with
#   cmake -DPROGRAM=<example> -DEXPECTED=<file holding a regular expression> -P np_check_output.cmake
# and fails unless it exits with 0 and its output matches the expression.
execute_process(COMMAND "${PROGRAM}" RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
file(READ "${EXPECTED}" expected)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${PROGRAM}: exit ${status}\n${out}\n${err}")
endif()
if(NOT "${out}" MATCHES "${expected}")
  message(FATAL_ERROR "${PROGRAM}: output does not match '${expected}':\n${out}\n${err}")
endif()
message(STATUS "${out}")
