# The progress fits where the standard error goes, run by ctest as
#   cmake -DTOOL=<texture_mesh> -DMESHES=<mesh dir> -DWORK=<scratch dir> -P check_progress.cmake
# NP_PROGRESS_DELAY sets how long a step runs before it is shown, which makes every check here
# independent of the machine's speed: 0 shows every step, 1e9 none.
# Into a pipe (a log): whole lines, no carriage return, the time of each step once. On a terminal
# (a pseudo-terminal made by util-linux's script, which turns each \n into \r\n): with a delay of
# 0, each step's line is drawn and redrawn in place (after a \r) and ends with its time; with a
# delay of 1e9, nothing.

file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
set(mesh "${MESHES}/cube_quad.off")
set(steps "reading [^\r\n]*cube_quad.off" "texturing 8 vertices" "writing out")

foreach(delay 0 1e9)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env NP_PROGRESS_DELAY=${delay} "${TOOL}" "${mesh}" out
                  WORKING_DIRECTORY "${WORK}" RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0 OR NOT out MATCHES "wrote out.obj")
    message(FATAL_ERROR "texture_mesh into a pipe: exit ${status}\n${out}\n${err}")
  endif()
  string(FIND "${err}" "\r" carriage_return)
  if(NOT carriage_return EQUAL -1 OR NOT err MATCHES "\n$")
    message(FATAL_ERROR "the progress into a pipe (NP_PROGRESS_DELAY=${delay}) is not whole lines:\n${err}")
  endif()
  string(REGEX REPLACE "\n$" "" lines "${err}")
  string(REPLACE "\n" ";" lines "${lines}")
  set(done "")
  foreach(line ${lines})
    if(line MATCHES "^(.*): done in [0-9]+\\.[0-9]+ s$")
      list(APPEND done "${CMAKE_MATCH_1}")
    elseif(NOT line MATCHES "^(reading .*|texturing 8 vertices|writing out): (25|50|75)%$")
      message(FATAL_ERROR "a progress line into a pipe is not a step's milestone or time: '${line}'")
    endif()
  endforeach()
  list(LENGTH done count)
  if(NOT count EQUAL 3)
    message(FATAL_ERROR "into a pipe, ${count} steps said their time, not 3:\n${err}")
  endif()
  foreach(k 0 1 2)
    list(GET done ${k} step)
    list(GET steps ${k} expected)
    if(NOT step MATCHES "^${expected}$")
      message(FATAL_ERROR "into a pipe, step ${k} is '${step}', not '${expected}':\n${err}")
    endif()
  endforeach()
endforeach()

find_program(SCRIPT script)
if(NOT SCRIPT)
  message(FATAL_ERROR "util-linux's script is needed to run the tool on a terminal: apt-get install bsdutils")
endif()
# The standard error as a terminal shows it: the transcript of `script`, without its own lines.
function(on_terminal delay name result)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env NP_PROGRESS_DELAY=${delay}
                          "${SCRIPT}" -q -e -c "'${TOOL}' '${mesh}' ${name} > ${name}_stdout.txt" ${name}_terminal.txt
                  WORKING_DIRECTORY "${WORK}" RESULT_VARIABLE status)
  file(READ "${WORK}/${name}_stdout.txt" out)
  file(READ "${WORK}/${name}_terminal.txt" terminal)
  string(REGEX REPLACE "Script (started|done) on [^\n]*\n?" "" terminal "${terminal}")
  if(NOT status EQUAL 0 OR NOT out MATCHES "wrote ${name}.obj")
    message(FATAL_ERROR "texture_mesh on a terminal: exit ${status}\n${out}\n${terminal}")
  endif()
  set(${result} "${terminal}" PARENT_SCOPE)
endfunction()

on_terminal(1e9 never terminal)
if(terminal MATCHES "reading|texturing|writing")
  message(FATAL_ERROR "on a terminal with NP_PROGRESS_DELAY=1e9, steps showed progress:\n${terminal}")
endif()

on_terminal(0 always terminal)
string(REPLACE "writing out" "writing always" steps "${steps}")
foreach(step ${steps})
  if(NOT terminal MATCHES "\r${step}: [^\r\n]*\r${step}: done in [0-9]+\\.[0-9]+ s *\r?\n")
    message(FATAL_ERROR "on a terminal with NP_PROGRESS_DELAY=0, step '${step}' is not a line drawn, then redrawn in "
                        "place with its time:\n${terminal}")
  endif()
endforeach()
string(REGEX REPLACE "\r(reading|texturing|writing)" "" unplaced "${terminal}")
if(unplaced MATCHES "reading|texturing|writing" OR terminal MATCHES "%\r?\n")
  message(FATAL_ERROR "on a terminal, a step's line is not drawn in place:\n${terminal}")
endif()
message(STATUS "progress: whole lines into a pipe; on a terminal, in place, and nothing when the delay is long")
