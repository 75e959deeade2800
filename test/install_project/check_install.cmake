# Installs the package from the build tree BUILD into WORK/prefix, then configures, builds and
# runs the outside project of this directory against it, which must find the CGAL and the Eigen
# the package was configured with (versions CGAL_VERSION and EIGEN_VERSION):
#   cmake -DBUILD=<build dir> -DWORK=<scratch dir> -DCGAL_VERSION=<x.y.z> -DEIGEN_VERSION=<x.y.z> -P check_install.cmake
file(REMOVE_RECURSE "${WORK}")
function(step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${ARGN}\nfailed (${status}):\n${out}\n${err}")
  endif()
  set(output "${out}" PARENT_SCOPE)
endfunction()
step(${CMAKE_COMMAND} --install "${BUILD}" --prefix "${WORK}/prefix")
if(EXISTS "${WORK}/prefix/include/CGAL/Surface_mesh_parameterization/internal/Norm_preserving/Sign_constrained_admm.h"
   AND EXISTS "${WORK}/prefix/include/CGAL/Surface_mesh_parameterization/Norm_preserving_parameterizer_3.h")
  message(STATUS "headers installed")
else()
  message(FATAL_ERROR "the headers are not installed under ${WORK}/prefix/include")
endif()
step(${CMAKE_COMMAND} -S "${CMAKE_CURRENT_LIST_DIR}" -B "${WORK}/build" -DCMAKE_BUILD_TYPE=Release
     "-DCMAKE_PREFIX_PATH=${WORK}/prefix")
step(${CMAKE_COMMAND} --build "${WORK}/build")
step("${WORK}/build/use_package")
if(NOT output MATCHES "installed package: 12 of 12 uvs in")
  message(FATAL_ERROR "unexpected output: ${output}")
endif()
string(REGEX REPLACE "\\.0$" "" cgal_release "${CGAL_VERSION}") # CGAL_VERSION_STR has no ".0" patch level
if(NOT output MATCHES "built with CGAL ${cgal_release}[ ,]" OR NOT output MATCHES "Eigen ${EIGEN_VERSION}\n")
  message(FATAL_ERROR "the outside project was not built with the package's CGAL ${CGAL_VERSION} and Eigen ${EIGEN_VERSION}: ${output}")
endif()
message(STATUS "${output}")
