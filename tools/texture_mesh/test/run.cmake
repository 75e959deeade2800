# The helpers of the command-line tool's test scripts (check_cli.cmake, make_outputs.cmake), which
# set WORK, the directory the commands run in:
#   expect_run(STATUS REGEX command...)  runs the command; fails the script unless it exits with
#                                        STATUS and its stderr and stdout, joined, match REGEX
#   run_or_fail(command...)              expect_run(0 "" command...), and shows its output

function(expect_run expected_status expected_output)
  execute_process(COMMAND ${ARGN} WORKING_DIRECTORY "${WORK}" RESULT_VARIABLE status OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  if(NOT status EQUAL expected_status)
    message(FATAL_ERROR "${ARGN}: exit ${status}, expected ${expected_status}\n${out}\n${err}")
  endif()
  if(NOT "${err}${out}" MATCHES "${expected_output}")
    message(FATAL_ERROR "${ARGN}: the output does not match '${expected_output}':\n${out}\n${err}")
  endif()
  set(expect_run_output "${err}${out}" PARENT_SCOPE)
endfunction()

function(run_or_fail)
  expect_run(0 "" ${ARGN})
  message(STATUS "${expect_run_output}")
endfunction()
