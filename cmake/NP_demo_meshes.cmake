# Extracts CGAL's mesh collection from Debian's libcgal-demo (data.tar.gz) into the build
# tree at configure time. Sets NP_MESH_DIR. Nothing of it is committed to the repository.
set(NP_CGAL_DATA_TARBALL "/usr/share/doc/libcgal-dev/data.tar.gz" CACHE FILEPATH
    "data.tar.gz of Debian's libcgal-demo")
set(NP_MESH_DIR "${CMAKE_BINARY_DIR}/data/meshes")
if(NOT EXISTS "${NP_MESH_DIR}/cow.off")
  if(NOT EXISTS "${NP_CGAL_DATA_TARBALL}")
    message(FATAL_ERROR "${NP_CGAL_DATA_TARBALL} not found: apt-get install libcgal-demo")
  endif()
  file(MAKE_DIRECTORY "${CMAKE_BINARY_DIR}/data")
  execute_process(COMMAND ${CMAKE_COMMAND} -E tar xzf "${NP_CGAL_DATA_TARBALL}" data/meshes
                  WORKING_DIRECTORY "${CMAKE_BINARY_DIR}" RESULT_VARIABLE np_tar_result)
  if(NOT np_tar_result EQUAL 0)
    message(FATAL_ERROR "could not extract meshes from ${NP_CGAL_DATA_TARBALL}")
  endif()
endif()
