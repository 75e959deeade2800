# Runs the command-line tool as a new user would, for the tests that read its outputs with other
# programs (ctest's fixture texture_mesh_outputs):
#   cmake -DTOOL=<texture_mesh> -DPROBE=<image_probe> -DPYTHON=<python3> -DMESHES=<mesh dir>
#         -DWORK=<scratch dir> -DINPUTS=<input;...> -DPHOTO_COLOURS=<R,G,B;R,G,B> -P make_outputs.cmake
# In WORK: the inputs (triangle-strip PLYs and an OBJ made from CGAL's cow, its cow.off and
# pig.stl), photo.jpg (cells of the two colours), and for each input, named <input with _ for .>:
#   <name>.glb               texture_mesh INPUT <name>.glb --texture photo.jpg (with --viewer
#                            for cow.off: cow_off.html)
#   <name>_reference.obj     texture_mesh INPUT <name>_reference.obj: the tool's uvs
# and cow_checkerboard.html (texture_mesh cow.off cow_checkerboard --viewer); and the same glb and
# reference OBJ, with --tiles 2x3, of defects.obj: an export split along a seam, with a loose
# edge (a line in the glb), a face with a repeated corner and a vertex on no face.

include(${CMAKE_CURRENT_LIST_DIR}/run.cmake)
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

run_or_fail("${PROBE}" write-jpeg photo.jpg ${PHOTO_COLOURS})
file(COPY "${MESHES}/cow.off" "${MESHES}/pig.stl" DESTINATION "${WORK}")
foreach(format ascii binary_little_endian binary_big_endian)
  run_or_fail("${PYTHON}" "${CMAKE_CURRENT_LIST_DIR}/test_meshes.py" strips cow.off cow_strips_${format}.ply ${format})
endforeach()
run_or_fail("${PYTHON}" "${CMAKE_CURRENT_LIST_DIR}/test_meshes.py" obj cow.off cow.obj)

foreach(input ${INPUTS})
  string(REPLACE "." "_" name "${input}")
  set(viewer "")
  if(input STREQUAL "cow.off")
    set(viewer --viewer)
  endif()
  run_or_fail("${TOOL}" ${input} ${name}.glb --texture photo.jpg ${viewer})
  run_or_fail("${TOOL}" ${input} ${name}_reference.obj)
endforeach()
run_or_fail("${TOOL}" cow.off cow_checkerboard --viewer)
file(WRITE "${WORK}/defects.obj" "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 1 0 0\nv 2 0 0.3\nv 2 1 0\nv 1 1 0\nv 5 5 5\n"
           "f 1 2 3 4\nf 5 6 7 8\nf 7 7 6\nl 6 9\nl 1 3\n")
run_or_fail("${TOOL}" defects.obj defects_obj.glb --tiles 2x3)
run_or_fail("${TOOL}" defects.obj defects_obj_reference.obj --tiles 2x3)
