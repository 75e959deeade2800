# The command-line tool's contract, run by ctest as
#   cmake -DTOOL=<texture_mesh> -DPROBE=<image_probe> -DMESHES=<mesh dir> -DWORK=<scratch dir>
#         -DPHOTO_COLOURS=<R,G,B;R,G,B> -DPYTHON=<python3> -DMESH_SCRIPT=<test_meshes.py>
#         -P check_cli.cmake
# every input format, the options, --help, and clear failures that write nothing.

include(${CMAKE_CURRENT_LIST_DIR}/run.cmake)
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

# Runs the tool with the given arguments; checks its exit status and that stderr/stdout match.
function(run expected_status expected_output)
  expect_run(${expected_status} "${expected_output}" "${TOOL}" ${ARGN})
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
run(2 "--tiles takes MxN, such as 2x3" --tiles 2by3)
run(2 "--fixed-pair takes two vertex indices" --fixed-pair 1,-2)
# The values of the options are checked as the Python module checks them (texture_settings.h).
run(2 "--tiles takes M and N of at least 1" --tiles 0x2)
run(2 "--guess takes xy, combination or graph" --guess XY)
run(2 "--fit takes uniform, clamp or none" --fit stretch)
run(2 "--quality takes draft, default or exact" --quality best)
run(2 "--tolerance takes a positive number" --tolerance -1)
run(2 "--tolerance takes a positive number" --tolerance inf)
run(2 "--tolerance takes a number" --tolerance 1e-3x)
run(2 "--time-limit takes a positive number of seconds" --time-limit 0)
run(2 "--time-limit takes a positive number of seconds" --time-limit nan)
run(2 "--time-limit takes a number of seconds" --time-limit soon)
run(2 "--fixed-pair takes two vertex indices" --fixed-pair 1)
run(2 "--format takes obj or glb" --format fbx)
run(2 "--texture takes an image file \\(PNG or JPEG\\)" --texture)
run(2 "--format glb and the output name out.obj disagree" "${MESHES}/cube_quad.off" out.obj --format glb)
run(0 "usage: .*--texture IMAGE.*--format obj\\|glb.*--viewer.*--quiet.*NP_PROGRESS_DELAY" --help)
# An infinite time limit is no limit, as the module's time_limit=inf.
run(0 "wrote no_limit.obj" "${MESHES}/cube_quad.off" no_limit --time-limit inf)

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
refused("error: --fixed-pair: .*cow.off has 2904 vertices" "${MESHES}/cow.off" out_farpair --fixed-pair 0,5000)
# What CGAL 5.5's readers throw on (a negative face size), a PLY header that is wrong, and
# values out of the range of their declared type (an index of 1e30 would be no integer).
refused_file("not a valid ply file: a property is declared before any element" orphan.ply
             "ply\nformat ascii 1.0\nproperty float x\nelement vertex 3\nproperty float x\nproperty float y\n"
             "property float z\nend_header\n0 0 0\n1 0 0\n0 1 0\n")
refused_file("not a valid ply file: its vertices have no z coordinate" no_z.ply
             "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
             "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0\n1 0\n0 1\n3 0 1 2\n")
refused_file("not a valid off file: a count is negative or out of range" negative_size.off
             "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n-3 0 1 2\n")
refused_file("not a valid stl file: Error while" truncated.stl
             "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\n"
             "endloop\nendfacet\nfacet normal 0 0 1\n")
# PLY files whose faces cannot be read say what they hold.
refused_file("the ply file has vertex and edge elements; no face element" edges.ply
             "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
             "element edge 2\nproperty int vertex1\nproperty int vertex2\nend_header\n0 0 0\n1 0 0\n0 1 0\n0 1\n1 2\n")
refused_file("the ply file has a vertex element; no face element" vertices_only.ply
             "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
             "end_header\n0 0 0\n1 0 0\n0 1 0\n")
refused_file("the ply file has no face" no_strip.ply
             "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
             "element tristrips 1\nproperty list int int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n")
refused_file("not a valid ply file: element tristrips, item 1 of 1, property vertex_indices: -2 is not a vertex index"
             bad_strip.ply
             "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
             "element tristrips 1\nproperty list int int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 -2 1\n")
refused_file("not a valid ply file: element tristrips, item 2 of 2, property vertex_indices: the data ends"
             short_strips.ply
             "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
             "element tristrips 2\nproperty list int int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0\n")
refused_file("not a valid ply file: header line 4: unknown type \"float16\"" half.ply
             "ply\nformat ascii 1.0\nelement vertex 3\nproperty float16 x\nend_header\n")
string(CONCAT strip_header "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                 "element tristrips 1\nproperty list int int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n")
foreach(index 1e30 inf 2.5 4294967296)
  string(MAKE_C_IDENTIFIER "${index}" name)
  refused_file("not a valid ply file: element tristrips, item 1 of 1, property vertex_indices: '${index}' is (not a value|out of the range) of type int"
               index_${name}.ply "${strip_header}" "4 0 1 ${index} 3\n")
endforeach()
refused_file("not a valid ply file: element face, item 1 of 1, property vertex_indices: '300' is out of the range of type uchar"
             long_face.ply "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
             "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n300 0 1 2\n")
refused_file("not a valid ply file: element vertex, item 2 of 3, property x: '1e39' is out of the range of type float"
             float_overflow.ply "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
             "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1e39 0 0\n0 1 0\n"
             "3 0 1 2\n")
refused_file("not a valid ply file: header line 3: the count of element vertex is not a count: -3" negative_count.ply
             "ply\nformat ascii 1.0\nelement vertex -3\nproperty float x\nend_header\n")

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
# The PLY faces CGAL 5.5's reader skips or refuses: triangle strips (-1 between strips, every
# second triangle reversed) beside a face element, indices of 16 bits, a face list of another
# name; elements named "vertices" and "faces"; integer coordinates (which CGAL 5.5 crashes on).
file(WRITE "${WORK}/strips_and_face.ply" "ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\nproperty float y\n"
     "property float z\nelement face 1\nproperty list uchar int vertex_indices\nelement tristrips 1\n"
     "property list int int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n2 1 0\n2 0 0\n"
     "3 1 5 4\n8 0 1 2 3 -1 1 4 3\n")
run(0 "6 vertices, 4 faces, 1 component.*wrote strips_and_face.obj" strips_and_face.ply strips_and_face)
file(STRINGS "${WORK}/strips_and_face.obj" faces REGEX "^f ")
if(NOT faces STREQUAL "f 2/2 6/6 5/5;f 1/1 2/2 3/3;f 3/3 2/2 4/4;f 2/2 5/5 4/4")
  message(FATAL_ERROR "strips_and_face.obj: faces ${faces}; expected the face, then the strips' triangles, every "
                      "second one of a strip reversed")
endif()
file(WRITE "${WORK}/short_indices.ply" "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
     "property float z\nelement face 2\nproperty list uchar ushort vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n"
     "1 1 0\n3 0 1 2\n3 1 3 2\n")
run(0 "4 vertices, 2 faces.*wrote short_indices.obj" short_indices.ply short_indices)
file(WRITE "${WORK}/vertex_list.ply" "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
     "property float z\nelement face 1\nproperty list uchar int vertex_list\nproperty uchar flags\nend_header\n"
     "0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3 7\n")
run(0 "4 vertices, 1 faces.*wrote vertex_list.obj" vertex_list.ply vertex_list)
file(WRITE "${WORK}/plural.ply" "ply\nformat ascii 1.0\nelement vertices 3\nproperty float x\nproperty float y\n"
     "property float z\nelement faces 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
run(0 "wrote plural.obj" plural.ply plural)
file(WRITE "${WORK}/int_coordinates.ply" "ply\nformat ascii 1.0\nelement vertex 3\nproperty int x\nproperty short y\n"
     "property uchar z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n-70000 0 0\n1 -300 0\n0 1 255\n"
     "3 0 1 2\n")
run(0 "3 vertices, 1 faces.*wrote int_coordinates.obj" int_coordinates.ply int_coordinates)
file(STRINGS "${WORK}/int_coordinates.obj" v REGEX "^v ")
if(NOT v STREQUAL "v -70000 0 0;v 1 -300 0;v 0 1 255")
  message(FATAL_ERROR "int_coordinates.obj: vertices ${v}, not those of the PLY")
endif()
# Every PLY value is read by its declared type, a binary one in the file's byte order whatever
# the host's: the same triangle of short, int and double coordinates (the extremes of each
# integer type) in ASCII and in both byte orders gives the same vertices.
foreach(format ascii binary_little_endian binary_big_endian)
  run_or_fail("${PYTHON}" "${MESH_SCRIPT}" ply-triangle ${format}.ply ${format})
  run(0 "3 vertices, 1 faces.*wrote ${format}.obj" ${format}.ply ${format})
  file(STRINGS "${WORK}/${format}.obj" v REGEX "^v ")
  if(NOT v STREQUAL "v 0 0 0;v 32767 -2147483648 0.5;v -32768 2147483647 -2.5")
    message(FATAL_ERROR "${format}.obj: vertices ${v}, not those of the PLY")
  endif()
endforeach()

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
# The output's name chooses the format; an OBJ's texture is beside it, a glb's inside it.
run(0 "wrote named.obj, .mtl, .png, _uv.svg, _report.txt" "${MESHES}/cube_quad.off" named.obj)
expect_textured(named)
run(0 "wrote packed.glb, _uv.svg, _report.txt\n" "${MESHES}/cube_quad.off" packed.glb)
run(0 "wrote packed_too.glb, _uv.svg, _report.txt, .html\n" "${MESHES}/cube_quad.off" packed_too --format glb --viewer)
foreach(file packed.glb packed_uv.svg packed_report.txt packed_too.html)
  if(NOT EXISTS "${WORK}/${file}")
    message(FATAL_ERROR "${file} was not written")
  endif()
endforeach()
file(GLOB beside "${WORK}/packed.obj" "${WORK}/packed.mtl" "${WORK}/packed.png" "${WORK}/packed.html")
if(beside)
  message(FATAL_ERROR "a glb without --viewer came with ${beside}")
endif()
file(READ "${WORK}/packed.glb" magic LIMIT 4 HEX)
if(NOT magic STREQUAL "676c5446") # glTF
  message(FATAL_ERROR "packed.glb does not start with glTF's magic: '${magic}'")
endif()

# The checkerboard is written by libpng: 512 x 512 pixels, 8 x 8 cells of cream and blue.
execute_process(COMMAND "${PROBE}" checkerboard "${WORK}/kept.png" RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "kept.png is not the checkerboard: ${out}${err}")
endif()

# --texture: a JPEG or PNG image of the user's, copied as it is beside the OBJ, named in the MTL.
execute_process(COMMAND "${PROBE}" write-jpeg "${WORK}/photo.jpg" ${PHOTO_COLOURS} RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "image_probe could not write photo.jpg")
endif()
foreach(image photo.jpg kept.png)
  get_filename_component(extension "${image}" EXT)
  run(0 "wrote with_${image}.obj, .mtl, ${extension}, _uv.svg, _report.txt" "${MESHES}/cube_quad.off" with_${image}
      --texture ${image})
  file(SHA256 "${WORK}/${image}" original)
  file(SHA256 "${WORK}/with_${image}${extension}" copy)
  file(STRINGS "${WORK}/with_${image}.mtl" map REGEX "^map_Kd ")
  if(NOT original STREQUAL copy OR NOT map STREQUAL "map_Kd with_${image}${extension}")
    message(FATAL_ERROR "with_${image}: the texture is not a copy of ${image} named in the MTL ('${map}')")
  endif()
endforeach()
if(EXISTS "${WORK}/with_photo.jpg.png")
  message(FATAL_ERROR "with --texture photo.jpg, the checkerboard was written too")
endif()

# A texture that is missing, not an image, or cut short: exit 1 before the work, nothing written.
refused("cannot read the texture nothere.png: no such file; nothing written" "${MESHES}/cow.off" out_tex_missing
        --texture nothere.png)
refused("cannot read the texture nothere.png: no such file" missing.off out_tex_first --texture nothere.png --viewer)
file(WRITE "${WORK}/notes.jpg" "not an image\n")
refused("cannot read the texture notes.jpg: not a PNG or JPEG image" "${MESHES}/cow.off" out_tex_text --texture notes.jpg)
execute_process(COMMAND head -c 3000 "${WORK}/photo.jpg" OUTPUT_FILE "${WORK}/cut.jpg")
refused("cannot read the texture cut.jpg: not a valid JPEG image: Premature end of JPEG file" "${MESHES}/cow.off"
        out_tex_cut_jpg --texture cut.jpg --format glb)
execute_process(COMMAND head -c 1000 "${WORK}/kept.png" OUTPUT_FILE "${WORK}/cut.png")
refused("cannot read the texture cut.png: not a valid PNG image: " "${MESHES}/cow.off" out_tex_cut_png --texture cut.png)
# Larger than 16384 pixels a side (a GPU's limit): refused.
run_or_fail("${PROBE}" write-jpeg wide.jpg ${PHOTO_COLOURS} 16385 8)
refused("cannot read the texture wide.jpg: the JPEG image is 16385 x 8 pixels: larger than 16384 pixels a side"
        "${MESHES}/cube_quad.off" out_tex_wide --texture wide.jpg)
run_or_fail("${PROBE}" write-png tall.png 8 16385)
refused("cannot read the texture tall.png: the PNG image is 8 x 16385 pixels: larger than 16384 pixels a side"
        "${MESHES}/cube_quad.off" out_tex_tall --texture tall.png)
run_or_fail("${PROBE}" write-png largest.png 16384 8)
run(0 "wrote largest.obj, .mtl, .png" "${MESHES}/cube_quad.off" largest --texture largest.png)

# glTF holds 32-bit floats: a coordinate beyond their range is refused, not written as inf.
file(WRITE "${WORK}/huge.obj" "v 0 0 0\nv 1e39 0 0\nv 0 1e39 0\nf 1 2 3\n")
refused("cannot write out_huge.glb, _uv.svg, _report.txt: vertex 1 has a coordinate beyond the range of glTF's 32-bit floats; nothing written"
        huge.obj out_huge.glb)
run(0 "wrote huge_obj.obj" huge.obj huge_obj) # an OBJ holds it

# --quiet: nothing on stdout or stderr but an error.
execute_process(COMMAND "${TOOL}" --quiet "${MESHES}/cube_quad.off" quiet WORKING_DIRECTORY "${WORK}"
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0 OR NOT "${out}${err}" STREQUAL "" OR NOT EXISTS "${WORK}/quiet.obj")
  message(FATAL_ERROR "--quiet: exit ${status}, printed '${out}${err}'")
endif()
run(1 "^error: cannot read missing.off: no such file\n$" --quiet missing.off quiet_missing)

message(STATUS "texture_mesh: every check passed")
