cmake_policy(SET CMP0007 NEW)
# Runs segment_mesh (PROGRAM) on malformed mesh files written into WORK_DIR,
# and on a good one with bad options, and checks, for each, a non-zero exit
# code, a message naming the problem on standard error, and that nothing was
# written; then that a good run's report.json says how the pattern was drawn.

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

set(good_vertices "0 0 0\n1 0 0\n1 1 0\n0 1 0\n")
set(cases
  "empty.off||is empty"
  "blank.off|\n\n# only a comment\n|is empty"
  "header.off|PLY\n4 2 0\n|not an OFF header"
  "counts.off|OFF\nfour two zero\n|counts are not"
  "negative.off|OFF\n-4 2 0\n|counts are not"
  "truncated_vertices.off|OFF\n4 2 0\n0 0 0\n1 0 0\n|truncated"
  "truncated_faces.off|OFF\n4 2 0\n${good_vertices}3 0 1 2\n|truncated"
  "more_faces.off|OFF\n4 5 0\n${good_vertices}3 0 1 2\n3 0 2 3\n|truncated"
  "huge_counts.off|OFF\n99999999999999 99999999999999 0\n0 0 0\n|truncated"
  "huge_face.off|OFF\n4 1 0\n${good_vertices}4000000000 0 1 2\n|number of corners"
  "garbage_number.off|OFF\n4 2 0\n0 0 0\n1 zz 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n|is not a number"
  "garbage_index.off|OFF\n4 2 0\n${good_vertices}3 0 1 q\n3 0 2 3\n|is not a vertex index"
  "index_out_of_range.off|OFF\n4 2 0\n${good_vertices}3 0 1 9\n3 0 2 3\n|out of range"
  "nan.off|OFF\n4 2 0\n0 0 0\n1 nan 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n|NaN or infinite"
  "overflow.off|OFF\n4 2 0\n0 0 0\n1 1e999 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n|NaN or infinite"
  "point_cloud.off|OFF\n4 0 0\n${good_vertices}|no face"
  "collinear.off|OFF\n3 1 0\n0 0 0\n1 0 0\n2 0 0\n3 0 1 2\n|degenerate"
  "repeated_corners.off|OFF\n4 2 0\n${good_vertices}3 0 0 1\n3 2 2 2\n|3 distinct corners"
  "truncated.ply|ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n|truncated"
  "no_end_header.ply|ply\nformat ascii 1.0\nelement vertex 3\n|end_header"
  "garbage.stl|solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 zz\n|no face"
  "bad_index.obj|v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 9\n|OBJ"
  "unknown.xyz|0 0 0\n|extension"
)
set(failures 0)
foreach(case IN LISTS cases)
  string(REPLACE "|" ";" parts "${case}")
  list(GET parts 0 name)
  list(GET parts 1 content)
  list(GET parts 2 expected)
  string(REPLACE "\\n" "\n" content "${content}")
  file(WRITE "${WORK_DIR}/${name}" "${content}")
  set(out "${WORK_DIR}/out_${name}")
  execute_process(COMMAND "${PROGRAM}" "${WORK_DIR}/${name}" --out-dir "${out}" --quiet
                  RESULT_VARIABLE code OUTPUT_VARIABLE stdout ERROR_VARIABLE stderr TIMEOUT 60)
  set(problem "")
  if(code EQUAL 0)
    set(problem "exit code 0")
  elseif(NOT code EQUAL 1)
    set(problem "exit code '${code}' (a crash or a timeout?)")
  elseif(NOT stderr MATCHES "segment_mesh: cannot use")
    set(problem "no message on standard error")
  elseif(NOT stderr MATCHES "${expected}")
    set(problem "the message does not say '${expected}'")
  elseif(EXISTS "${out}")
    set(problem "an output directory was written")
  endif()
  if(problem)
    math(EXPR failures "${failures} + 1")
    message("FAILED ${name}: ${problem}\n  stderr: ${stderr}")
  else()
    string(STRIP "${stderr}" stderr)
    message("ok     ${name}: ${stderr}")
  endif()
endforeach()
# a missing file
execute_process(COMMAND "${PROGRAM}" "${WORK_DIR}/missing.off" --out-dir "${WORK_DIR}/out_missing"
                RESULT_VARIABLE code ERROR_VARIABLE stderr)
if(NOT code EQUAL 1 OR NOT stderr MATCHES "does not exist" OR EXISTS "${WORK_DIR}/out_missing")
  math(EXPR failures "${failures} + 1")
  message("FAILED missing.off: exit code ${code}, stderr: ${stderr}")
else()
  message("ok     missing.off")
endif()
# bad pattern options on a good mesh
file(WRITE "${WORK_DIR}/square.off" "OFF\n4 2 0\n${good_vertices}3 0 1 2\n3 0 2 3\n")
set(option_cases
  "--units furlong|--units: furlong not in [{]mm,cm,in,pt,pc,px[}]"
  "--size big|--size: 'big' is not a positive length"
  "--size -200mm|--size: '-200mm' is not a positive length"
  "--size 200parsecs|--size: '200parsecs' is not a positive length"
  "--size 200mm --scale 3|--size excludes --scale"
  "--scale 0|--scale: '0' is not a positive number"
  "--page a9|--page: a9 not in"
  "--seam-allowance 95mm|--seam-allowance: 95mm on each side of a piece leaves it no room on the page [(]a4, 190 mm between the margins[)]: give a narrower one"
  "--tabs --seam-allowance 1e300mm|--seam-allowance: 1e300mm on each side of a piece, with the glue tabs, leaves it no room on the page [(]a4, 190 mm between the margins[)]"
  "--notches 0.001mm|--notches: '0.001mm' is under 1 mm: notches so close could not be cut"
  "--notches 1e-300mm|--notches: '1e-300mm' is under 1 mm"
  "--size 0.5mm|--size: '0.5mm' is under 1 mm: too small to draw the pieces"
  "--scale 1e-300|the model would be [0-9.e-]+ mm at its largest: too small to draw the pieces [(]1 mm at least[)]. give a larger --scale"
  "--size 100000000mm|the patterns would take [0-9]+ pages or more [(]at most 1000[)]: give a smaller --size or --scale"
)
set(k 0)
foreach(case IN LISTS option_cases)
  string(REPLACE "|" ";" parts "${case}")
  list(GET parts 1 expected)
  list(GET parts 0 options)
  separate_arguments(parts UNIX_COMMAND "${options}")
  math(EXPR k "${k} + 1")
  set(out "${WORK_DIR}/out_option_${k}")
  execute_process(COMMAND "${PROGRAM}" "${WORK_DIR}/square.off" --out-dir "${out}" --quiet ${parts}
                  RESULT_VARIABLE code ERROR_VARIABLE stderr TIMEOUT 60)
  if(NOT code EQUAL 1 OR NOT stderr MATCHES "${expected}" OR EXISTS "${out}")
    math(EXPR failures "${failures} + 1")
    message("FAILED ${parts}: exit code ${code}, stderr: ${stderr}")
  else()
    string(STRIP "${stderr}" stderr)
    string(REGEX REPLACE "\n.*" "" stderr "${stderr}")
    message("ok     ${parts}: ${stderr}")
  endif()
endforeach()
# and good ones: report.json says how the pattern was drawn (string(JSON) needs CMake 3.19)
if(CMAKE_VERSION VERSION_GREATER_EQUAL 3.19)
  set(out "${WORK_DIR}/out_size")
  execute_process(COMMAND "${PROGRAM}" "${WORK_DIR}/square.off" --out-dir "${out}" --quiet --size 8in --units cm
                  RESULT_VARIABLE code ERROR_VARIABLE stderr TIMEOUT 60)
  if(code EQUAL 0 AND EXISTS "${out}/report.json")
    file(READ "${out}/report.json" report)
    string(JSON units GET "${report}" patterns units)
    string(JSON size GET "${report}" patterns model_size)
    string(JSON reduced GET "${report}" patterns reduced_to_fit)
  endif()
  if(NOT code EQUAL 0 OR NOT units STREQUAL "cm" OR NOT size STREQUAL "20.32" OR NOT reduced STREQUAL "OFF")
    math(EXPR failures "${failures} + 1")
    message("FAILED --size 8in --units cm: exit code ${code}, units '${units}', model size '${size}', "
            "reduced '${reduced}', stderr: ${stderr}")
  else()
    message("ok     --size 8in --units cm: the model ${size} cm at its largest in report.json")
  endif()
endif()
if(failures GREATER 0)
  message(FATAL_ERROR "${failures} malformed files or bad options were not refused cleanly")
endif()
