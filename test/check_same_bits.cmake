# The ways in give the same uvs bit for bit: the whole-soup call, the parameterizer (CGAL's
# drop-in where the mesh has a border) and the command-line tool, on the OFF files NAMES (comma
# separated) of MESH_DIR, run by ctest as
#   cmake -DUV_BITS=<uv_bits> -DTOOL=<texture_mesh> -DMESH_DIR=<dir> -DNAMES=<a,b,...> -DWORK=<scratch dir>
#         -P check_same_bits.cmake
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
string(REPLACE "," ";" names "${NAMES}")
foreach(name ${names})
  set(mesh "${MESH_DIR}/${name}.off")
  execute_process(COMMAND "${TOOL}" --quiet "${mesh}" "${name}" WORKING_DIRECTORY "${WORK}" RESULT_VARIABLE status
                  ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "texture_mesh ${mesh}: exit ${status}\n${err}")
  endif()
  execute_process(COMMAND "${UV_BITS}" "${mesh}" --obj "${WORK}/${name}.obj" RESULT_VARIABLE status
                  OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0 OR NOT out MATCHES "soup ([0-9a-f]+)\n")
    message(FATAL_ERROR "uv_bits ${mesh}: exit ${status}\n${out}\n${err}")
  endif()
  set(soup "${CMAKE_MATCH_1}")
  if(NOT out MATCHES "tool ${soup}\n")
    message(FATAL_ERROR "${name}: the command-line tool's uvs differ from the whole-soup call's:\n${out}")
  endif()
  if(out MATCHES "soup_kept_apart ([0-9a-f]+)\n") # the parameterizer's problem: no weld
    set(soup "${CMAKE_MATCH_1}")
  endif()
  if(out MATCHES "parameterizer ([0-9a-f]+)\n" AND NOT CMAKE_MATCH_1 STREQUAL soup)
    message(FATAL_ERROR "${name}: the parameterizer's uvs differ from the whole-soup call's:\n${out}")
  endif()
  if(NOT out MATCHES "parameterizer" AND NOT name STREQUAL "cube_poly") # the polygon soup has no mesh path
    message(FATAL_ERROR "${name}: the parameterizer did not run:\n${out}")
  endif()
  message(STATUS "${name}: the same bits\n${out}")
endforeach()
