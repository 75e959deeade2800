# The command-line tool's contract, run by ctest as
#   cmake -DTOOL=<texture_mesh> -DMESHES=<mesh dir> -DWORK=<scratch dir> -P check_cli.cmake
# every input format, the options, --help, and clear failures that write nothing.

file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

# Runs the tool with the given arguments; checks its exit status and that stderr/stdout match.
function(run expected_status expected_output)
  execute_process(COMMAND "${TOOL}" ${ARGN} WORKING_DIRECTORY "${WORK}"
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL expected_status)
    message(FATAL_ERROR "texture_mesh ${ARGN}: exit ${status}, expected ${expected_status}\n${out}\n${err}")
  endif()
  if(NOT "${err}${out}" MATCHES "${expected_output}")
    message(FATAL_ERROR "texture_mesh ${ARGN}: output does not match '${expected_output}':\n${out}\n${err}")
  endif()
endfunction()

function(expect_nothing_written basename)
  file(GLOB written "${WORK}/${basename}*")
  if(written)
    message(FATAL_ERROR "a failed run left files behind: ${written}")
  endif()
endfunction()

function(expect_textured basename)
  foreach(suffix .obj .mtl .png _uv.svg _report.txt)
    if(NOT EXISTS "${WORK}/${basename}${suffix}")
      message(FATAL_ERROR "${basename}${suffix} was not written")
    endif()
  endforeach()
  file(STRINGS "${WORK}/${basename}.obj" v REGEX "^v ")
  file(STRINGS "${WORK}/${basename}.obj" vt REGEX "^vt ")
  list(LENGTH v nv)
  list(LENGTH vt nvt)
  if(NOT nv EQUAL nvt OR nv EQUAL 0)
    message(FATAL_ERROR "${basename}.obj: ${nv} vertices but ${nvt} texture coordinates")
  endif()
  set(${basename}_vertices ${nv} PARENT_SCOPE)
endfunction()

# The tool on `input`, writing to `basename`, with the options that follow: it must fail with
# exit status 1 and a message matching `expected_output`, and write nothing.
function(refused expected_output input basename)
  run(1 "${expected_output}" "${input}" ${basename} ${ARGN})
  expect_nothing_written(${basename})
endfunction()

# refused() on a file `name` of the given content (the strings after `name`, joined), written to
# out_<name without extension>.
function(refused_file expected_output name)
  set(content "")
  math(EXPR last "${ARGC} - 1")
  foreach(i RANGE 2 ${last})
    string(APPEND content "${ARGV${i}}")
  endforeach()
  file(WRITE "${WORK}/${name}" "${content}")
  get_filename_component(stem "${name}" NAME_WE)
  refused("cannot read .*${name}: ${expected_output}" ${name} out_${stem})
endfunction()

# A small output: every uv in [0,1], and every face corner `i/i` names an existing vertex and
# its own texture coordinate.
function(expect_faces_reference_vt basename)
  expect_textured(${basename})
  file(STRINGS "${WORK}/${basename}.obj" v REGEX "^v ")
  list(LENGTH v nv)
  file(STRINGS "${WORK}/${basename}.obj" vt REGEX "^vt ")
  foreach(line ${vt})
    string(REGEX REPLACE "^vt ([^ ]+) ([^ ]+)$" "\\1;\\2" uv "${line}")
    foreach(value ${uv})
      if(value LESS 0 OR value GREATER 1)
        message(FATAL_ERROR "${basename}.obj: ${line} is outside [0,1]")
      endif()
    endforeach()
  endforeach()
  file(STRINGS "${WORK}/${basename}.obj" elements REGEX "^[fl] ")
  if(NOT elements)
    message(FATAL_ERROR "${basename}.obj has no face")
  endif()
  foreach(line ${elements})
    string(REGEX MATCHALL "[0-9]+/[0-9]+" corners "${line}")
    foreach(corner ${corners})
      string(REPLACE "/" ";" pair "${corner}")
      list(GET pair 0 vi)
      list(GET pair 1 ti)
      if(NOT vi EQUAL ti OR vi LESS 1 OR vi GREATER nv)
        message(FATAL_ERROR "${basename}.obj: '${line}' does not reference its vertices' vt")
      endif()
    endforeach()
  endforeach()
endfunction()

run(0 "usage: texture_mesh.*--tiles MxN" --help)
run(2 "unknown option --bogus" --bogus)
run(2 "--tiles takes MxN" --tiles 0x2)
run(2 "--fixed-pair takes two vertex indices" --fixed-pair 1)

# Inputs that cannot be read or textured: exit 1, a message that says what is wrong, no file.
refused("cannot read .*missing.off: no such file" missing.off out_missing)
refused_file("not a valid off file" garbage.off "this is not a mesh\n")
refused_file("the file is empty" empty.obj "")
refused_file(".*no face" points.obj "v 0 0 0\nv 1 0 0\n")
refused_file("not a valid obj file: line 4: vertex 4 of 3" bad_index.obj "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n")
refused_file("not a valid obj file: line 2: a vertex needs three coordinates" bad_vertex.obj
             "v 0 0 0\nv 1 0\nv 0 1 0\nf 1 2 3\n")
refused_file("not a mesh format: .xyz" mesh.xyz "0 0 0\n")
refused("error: .*fixed vertices are not" "${MESHES}/cow.off" out_badpair --fixed-pair 0,2000)
refused("error: .*the file has 2904 vertices" "${MESHES}/cow.off" out_farpair --fixed-pair 0,5000)
# What CGAL 5.5's readers crash on (a PLY of integer coordinates) or throw on (a negative face
# size), and a position the OBJ would carry as it is (a NaN on a vertex on no face).
refused_file("not a readable ply file: its vertex coordinate x is of type int" int_coordinates.ply
             "ply\nformat ascii 1.0\nelement vertex 3\nproperty int x\nproperty int y\nproperty int z\n"
             "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
refused_file("not a readable ply file: a property is declared before any element" orphan.ply
             "ply\nformat ascii 1.0\nproperty float x\nelement vertex 3\nproperty float x\nproperty float y\n"
             "property float z\nend_header\n0 0 0\n1 0 0\n0 1 0\n")
refused_file("not a readable ply file: its vertices have no z coordinate" no_z.ply
             "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
             "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0\n1 0\n0 1\n3 0 1 2\n")
refused_file("not a valid off file: a count is negative or out of range" negative_size.off
             "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n-3 0 1 2\n")
refused_file("not a valid stl file: Error while" truncated.stl
             "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\n"
             "endloop\nendfacet\nfacet normal 0 0 1\n")
file(WRITE "${WORK}/nan_alone.obj" "v 0 0 0\nv 1 0 0\nv 0 1 0\nv nan nan nan\nf 1 2 3\n")
refused("vertex 3 of nan_alone.obj is on no face and has a non-finite coordinate" nan_alone.obj out_nan_alone)

# Outputs that cannot be written: a basename that names no file (exit 2), a directory that does
# not exist (created by nothing), an output file that is a directory; a scratch directory of the
# same name as the tool's is left as it was.
run(2 "the output basename must end in a file name, not 'sub/'" "${MESHES}/cube_quad.off" sub/)
run(1 "cannot write .*no such directory: .*not_there; nothing written" "${MESHES}/cube_quad.off" not_there/out)
if(EXISTS "${WORK}/not_there")
  message(FATAL_ERROR "the tool created the missing output directory")
endif()
file(MAKE_DIRECTORY "${WORK}/blocked_uv.svg")
run(1 "cannot write .*blocked_uv.svg is a directory; nothing written" "${MESHES}/cube_quad.off" blocked)
file(GLOB left "${WORK}/blocked.*")
if(left)
  message(FATAL_ERROR "a refused write left files behind: ${left}")
endif()
file(WRITE "${WORK}/kept.partial/mine.txt" "not the tool's\n")
run(0 "wrote kept.obj" "${MESHES}/cube_quad.off" kept)
file(GLOB left "${WORK}/kept.partial.*")
if(NOT EXISTS "${WORK}/kept.partial/mine.txt" OR left)
  message(FATAL_ERROR "the tool removed a kept.partial directory it had not made, or left its own: ${left}")
endif()
# A PLY whose elements are named "vertices" and "faces" (CGAL reads it) is not refused.
file(WRITE "${WORK}/plural.ply" "ply\nformat ascii 1.0\nelement vertices 3\nproperty float x\nproperty float y\n"
     "property float z\nelement faces 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
run(0 "wrote plural.obj" plural.ply plural)

# Every defect of real files is textured with the default options.
# Two triangles that share only a vertex (a bow tie).
file(WRITE "${WORK}/bowtie.off" "OFF\n5 2 0\n0 0 0\n1 0 0\n0 1 0\n-1 0 0\n0 -1 0\n3 0 1 2\n3 0 3 4\n")
# Three triangles on one edge (a fin).
file(WRITE "${WORK}/fin.off" "OFF\n5 3 0\n0 0 0\n1 0 0\n0.5 1 0\n0.5 -1 0\n0.5 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n")
# Two triangles of opposite orientation on one edge.
file(WRITE "${WORK}/opposite.off" "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0.5\n3 0 1 2\n3 1 2 3\n")
# A Moebius strip of eight quads.
file(WRITE "${WORK}/moebius.off" "OFF\n16 8 0\n0.6 0 0\n1.4 0 0\n0.4458 0.4458 -0.1531\n0.9684 0.9684 0.1531\n"
           "0 0.7172 -0.2828\n0 1.2828 0.2828\n-0.5989 0.5989 -0.3696\n-0.8153 0.8153 0.3696\n-1 0 -0.4\n"
           "-1 0 0.4\n-0.8153 -0.8153 -0.3696\n-0.5989 -0.5989 0.3696\n0 -1.2828 -0.2828\n0 -0.7172 0.2828\n"
           "0.9684 -0.9684 -0.1531\n0.4458 -0.4458 0.1531\n4 0 2 3 1\n4 2 4 5 3\n4 4 6 7 5\n4 6 8 9 7\n"
           "4 8 10 11 9\n4 10 12 13 11\n4 12 14 15 13\n4 14 1 0 15\n")
# An export split along a uv seam (coincident vertices), with vt, vn, groups and a face
# with a repeated corner, a face of two vertices and a vertex on no face.
file(WRITE "${WORK}/exported.obj" "# exported\no Plane\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 1 0 0\nv 2 0 0.3\n"
           "v 2 1 0\nv 1 1 0\nv 5 5 5\nvt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\ns off\nusemtl none\n"
           "f 1/1/1 2/2/1 3/3/1 4/1/1\nf 5/1/1 6/2/1 7/3/1 8/3/1\nf 7/1/1 7/2/1 6/3/1\nf 6/1 7/2\n")
foreach(defect bowtie fin opposite moebius)
  run(0 "wrote ${defect}_textured.obj" ${defect}.off)
  expect_faces_reference_vt(${defect}_textured)
endforeach()
run(0 "2 coincident vertices welded.*wrote exported_textured.obj" exported.obj)
expect_faces_reference_vt(exported_textured)
file(READ "${WORK}/exported_textured_report.txt" report)
if(NOT report MATCHES "vertices on no face \\(no uv, written as vt 0 0\\): 1\n.*welded: 2\n.*repeats: 1\n")
  message(FATAL_ERROR "exported_textured_report.txt does not count the defects:\n${report}")
endif()
run(0 "2 component" exported.obj exported_apart --keep-coincident)
expect_faces_reference_vt(exported_apart)
# The tool reads back its own output, whose face of two corners is an `l` statement.
file(STRINGS "${WORK}/exported_textured.obj" lines REGEX "^l ")
if(NOT lines)
  message(FATAL_ERROR "exported_textured.obj has no l statement to read back")
endif()
run(0 "9 vertices, 4 faces.*wrote read_back.obj" exported_textured.obj read_back)
expect_faces_reference_vt(read_back)
# A Blender export (CRLF): material library, object, normals, quads with v/vt/vn corners, a
# loose edge (`l`), a face with negative indices and one continued on the next line.
file(WRITE "${WORK}/blender.obj" "# Blender v3.6.0 OBJ File\r\nmtllib cube.mtl\r\no Cube\r\n"
           "v 1 1 -1\r\nv 1 -1 -1\r\nv 1 1 1\r\nv 1 -1 1\r\nv -1 1 -1\r\nv -1 -1 -1\r\nv -1 1 1\r\nv -1 -1 1\r\n"
           "vt 0.625 0.5\r\nvt 0.875 0.5\r\nvt 0.875 0.75\r\nvt 0.625 0.75\r\nvn 0 1 0\r\nusemtl Material\r\ns off\r\n"
           "f 1/1/1 5/2/1 7/3/1 3/4/1\r\nf 4/1/1 3/2/1 7/3/1 8/4/1\r\nf 8//1 7//1 5//1 6//1\r\nf -3 -7 -5 -1\r\n"
           "f 2/1 1/2 \\\r\n3/3 4/4\r\nf 6 5 1 2\r\nl 1 8\r\n")
run(0 "8 vertices, 7 faces.*1 component.*wrote blender_textured.obj" blender.obj)
expect_faces_reference_vt(blender_textured)

# Every input format, and the options.
run(0 "wrote cow.obj" "${MESHES}/cow.off" cow --guess combination --tiles 2x3 --fit clamp)
expect_textured(cow)
run(0 "wrote from_obj.obj" cow.obj from_obj --guess graph)
expect_textured(from_obj)
run(0 "wrote sphere.obj" "${MESHES}/sphere.ply" sphere --fit none --refine-signs --refine-euclidean)
expect_textured(sphere)
file(READ "${WORK}/sphere_report.txt" report)
if(NOT report MATCHES "sign refinement, Euclidean refinement")
  message(FATAL_ERROR "sphere_report.txt does not record the refinements:\n${report}")
endif()
run(0 "wrote pig.obj" "${MESHES}/pig.stl" pig)
expect_textured(pig)

# --tiles 2x3 with the clamp fit: u within [0,2], v within [0,3], one of them reaching its end.
file(STRINGS "${WORK}/cow.obj" vt REGEX "^vt ")
set(max_u 0)
set(max_v 0)
foreach(line ${vt})
  string(REGEX REPLACE "^vt ([^ ]+) ([^ ]+)$" "\\1;\\2" uv "${line}")
  list(GET uv 0 u)
  list(GET uv 1 v)
  if(u GREATER max_u)
    set(max_u ${u})
  endif()
  if(v GREATER max_v)
    set(max_v ${v})
  endif()
endforeach()
if(max_u GREATER 2.000001 OR max_v GREATER 3.000001 OR (max_u LESS 1.999999 AND max_v LESS 2.999999))
  message(FATAL_ERROR "--tiles 2x3 --fit clamp: uvs reach (${max_u}, ${max_v}); expected within (2, 3), one end reached")
endif()
message(STATUS "texture_mesh: every check passed")
