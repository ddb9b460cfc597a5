# The command line of segment_mesh (PROGRAM): --help lists every option with
# its default, --version prints VERSION, a bad option or value is named in the
# error, and what --json prints and report.json holds follow SCHEMA, on MESH;
# with PDF (built with cairo) patterns.pdf is written too, with CLIPPER a seam
# allowance is drawn (and refused without).
# Output directories are written into WORK_DIR.

cmake_minimum_required(VERSION 3.19)
include(${CMAKE_CURRENT_LIST_DIR}/check_json_schema.cmake)
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
set(failures "")

# --help: exit code 0, every option, the defaults
execute_process(COMMAND "${PROGRAM}" --help RESULT_VARIABLE code OUTPUT_VARIABLE help ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  string(APPEND failures "--help: exit code ${code}\n")
endif()
foreach(expected
    "--out-dir DIR" "--size LENGTH" "--scale S" "--units TEXT:{mm,cm,in,pt,pc,px}=mm" "--page TEXT:{a4,a3,letter}=a4"
    "--tabs" "--notches LENGTH" "--seam-allowance LENGTH" "--fold-angle DEGREES:FLOAT in [0 - 180]=10" "--min-fold-length LENGTH=5%" "--min-loose-piece LENGTH=2mm" "--no-assembly-page" "--no-scale-check" "--vsa-tolerance T:POSITIVE=0.25" "--max-area-distortion A:POSITIVE=0.1" "--max-stretch L2:POSITIVE=2"
    "--max-local-area-distortion A_LOC:POSITIVE=0.025" "--criterion TEXT:{lpfb-ip-arap,lpfb-ip}=lpfb-ip-arap"
    "--area-preservation ALPHA:0..1=0.5" "--arap-border TEXT:{free,keep-lengths}=free" "--merge-order TEXT:{smallest,largest,relative,compact}=smallest"
    "--denoise,--no-denoise" "--no-refine" "--no-merge" "--no-smooth-seams" "--no-shorten-cuts" "--sequential" "--json" "--verbose"
    "--quiet" "--version" "Default: 200 mm")
  string(FIND "${help}" "${expected}" at)
  if(at LESS 0)
    string(APPEND failures "--help does not show '${expected}'\n")
  endif()
endforeach()

# --version
execute_process(COMMAND "${PROGRAM}" --version RESULT_VARIABLE code OUTPUT_VARIABLE version)
if(NOT code EQUAL 0 OR NOT version MATCHES "segment_mesh \\(CGAL_QD\\) ${VERSION}")
  string(APPEND failures "--version: exit code ${code}, '${version}'\n")
endif()

# bad options and values: exit code 1, the option named, nothing written
set(cases
  "--bogus|not expected: --bogus"
  "--max-stretch nan|--max-stretch: 'nan' is not a positive number"
  "--max-area-distortion -0.1|--max-area-distortion: '-0.1' is not a positive number"
  "--vsa-tolerance 1e999|--vsa-tolerance: '1e999' is not a positive number"
  "--criterion paper|--criterion: paper not in"
  "--arap-border fixed|--arap-border: fixed not in"
  "--merge-order random|--merge-order: random not in"
  "--area-preservation 1.5|--area-preservation: '1.5' is not a number from 0 to 1"
  "--area-preservation nan|--area-preservation: 'nan' is not a number from 0 to 1"
  "--notches 0mm|--notches: '0mm' is not a positive length"
  "--fold-angle 200|--fold-angle: Value 200 not in range"
  "--min-fold-length 5furlongs|--min-fold-length: '5furlongs' is not a length"
  "--min-fold-length -1mm|--min-fold-length: '-1mm' is not a length"
  "--min-fold-length 150%|--min-fold-length: '150%' is not a length"
  "--seam-allowance 6furlongs|--seam-allowance: '6furlongs' is not a positive length"
  "--min-loose-piece 2furlongs|--min-loose-piece: '2furlongs' is not a length"
  "--min-loose-piece -1mm|--min-loose-piece: '-1mm' is not a length"
  "--out-dir|--out-dir"
)
set(k 0)
foreach(case IN LISTS cases)
  string(REPLACE "|" ";" parts "${case}")
  list(GET parts 0 options)
  list(GET parts 1 expected)
  separate_arguments(options UNIX_COMMAND "${options}")
  math(EXPR k "${k} + 1")
  set(out "${WORK_DIR}/out_${k}")
  if(options STREQUAL "--out-dir")
    execute_process(COMMAND "${PROGRAM}" "${MESH}" --quiet --out-dir RESULT_VARIABLE code ERROR_VARIABLE err)
  else()
    execute_process(COMMAND "${PROGRAM}" "${MESH}" --quiet --out-dir "${out}" ${options}
                    RESULT_VARIABLE code ERROR_VARIABLE err)
  endif()
  string(FIND "${err}" "${expected}" at)
  if(NOT code EQUAL 1 OR at LESS 0 OR NOT err MATCHES "^segment_mesh: " OR EXISTS "${out}")
    string(APPEND failures "${options}: exit code ${code}, stderr '${err}'\n")
  else()
    string(REGEX REPLACE "\n.*" "" err "${err}")
    message("ok     ${options}: ${err}")
  endif()
endforeach()

# an output directory that is a file: refused, the file left as it was
file(WRITE "${WORK_DIR}/a_file" "keep")
execute_process(COMMAND "${PROGRAM}" "${MESH}" --quiet --out-dir "${WORK_DIR}/a_file"
                RESULT_VARIABLE code ERROR_VARIABLE err)
file(READ "${WORK_DIR}/a_file" kept)
if(NOT code EQUAL 1 OR NOT err MATCHES "cannot write into" OR NOT kept STREQUAL "keep")
  string(APPEND failures "--out-dir onto a file: exit code ${code}, stderr '${err}'\n")
endif()

# the report against its schema: --json, then report.json with `patterns`
file(READ "${SCHEMA}" schema)
execute_process(COMMAND "${PROGRAM}" "${MESH}" --json RESULT_VARIABLE code OUTPUT_VARIABLE json ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  string(APPEND failures "--json: exit code ${code}, stderr '${err}'\n")
else()
  string(STRIP "${json}" json)
  if(json MATCHES "\n")
    string(APPEND failures "--json prints more than one line\n")
  endif()
  check_json_schema("${json}" "${schema}" "--json" failures)
  # seam_smoothing with more than one piece; patterns only in report.json
  string(JSON charts GET "${json}" charts)
  string(JSON smoothing ERROR_VARIABLE no_smoothing GET "${json}" seam_smoothing)
  string(JSON patterns ERROR_VARIABLE no_patterns GET "${json}" patterns)
  if((charts GREATER 1 AND no_smoothing) OR NOT no_patterns)
    string(APPEND failures "--json: seam_smoothing missing or patterns present\n")
  endif()
  # cut_shortening unless switched off (and never with the paper's criterion)
  string(JSON shortening ERROR_VARIABLE no_shortening GET "${json}" cut_shortening)
  if(no_shortening)
    string(APPEND failures "--json: cut_shortening missing\n")
  endif()
  foreach(off "--no-shorten-cuts" "--criterion;lpfb-ip")
    execute_process(COMMAND "${PROGRAM}" "${MESH}" --json ${off} RESULT_VARIABLE code OUTPUT_VARIABLE json_off
                    ERROR_VARIABLE err)
    string(JSON shortening ERROR_VARIABLE no_shortening GET "${json_off}" cut_shortening)
    if(NOT code EQUAL 0 OR NOT no_shortening)
      string(APPEND failures "--json ${off}: exit code ${code}, cut_shortening present or stderr '${err}'\n")
    endif()
  endforeach()
endif()
# with a seam allowance where the program has Clipper, refused with a message where it has not
set(allowance "")
if(CLIPPER)
  set(allowance --seam-allowance 5mm)
else()
  execute_process(COMMAND "${PROGRAM}" "${MESH}" --quiet --out-dir "${WORK_DIR}/out_allowance" --seam-allowance 5mm
                  RESULT_VARIABLE code ERROR_VARIABLE err)
  if(NOT code EQUAL 1 OR NOT err MATCHES "--seam-allowance: this segment_mesh was built without Clipper"
     OR EXISTS "${WORK_DIR}/out_allowance")
    string(APPEND failures "--seam-allowance without Clipper: exit code ${code}, stderr '${err}'\n")
  endif()
endif()
# bounds that no chart meets: every chart beyond them, and the summary says so
execute_process(COMMAND "${PROGRAM}" "${MESH}" --max-stretch 0.5 --no-smooth-seams
                RESULT_VARIABLE code OUTPUT_VARIABLE summary ERROR_VARIABLE err)
if(NOT code EQUAL 0 OR NOT summary MATCHES "beyond bounds  ([0-9]+) of ([0-9]+) charts beyond the thresholds"
   OR NOT CMAKE_MATCH_1 EQUAL CMAKE_MATCH_2)
  string(APPEND failures "--max-stretch 0.5: exit code ${code}, summary '${summary}'\n")
endif()
execute_process(COMMAND "${PROGRAM}" "${MESH}" --quiet --out-dir "${WORK_DIR}/out" --size 15cm --notches 2cm ${allowance}
                RESULT_VARIABLE code OUTPUT_VARIABLE summary ERROR_VARIABLE err)
if(NOT code EQUAL 0 OR NOT EXISTS "${WORK_DIR}/out/report.json")
  string(APPEND failures "--out-dir: exit code ${code}, stderr '${err}'\n")
else()
  file(READ "${WORK_DIR}/out/report.json" report)
  check_json_schema("${report}" "${schema}" "report.json" failures)
  string(JSON size GET "${report}" patterns model_size)
  if(NOT size EQUAL 150)
    string(APPEND failures "report.json: model_size '${size}' for --size 15cm\n")
  endif()
  # the shortest fold line: 5 % of the model's size by default
  string(JSON min_fold GET "${report}" patterns min_fold_length)
  if(NOT min_fold EQUAL 7.5)
    string(APPEND failures "report.json: min_fold_length '${min_fold}' for --size 15cm\n")
  endif()
  string(JSON drawn_allowance GET "${report}" patterns seam_allowance)
  if((CLIPPER AND NOT drawn_allowance EQUAL 5) OR (NOT CLIPPER AND NOT drawn_allowance EQUAL 0))
    string(APPEND failures "report.json: seam_allowance '${drawn_allowance}'\n")
  endif()
  string(JSON pdf GET "${report}" patterns pdf)
  # the scale check: 50 mm bars on A4, which the summary names with the PDF
  string(JSON check GET "${report}" patterns scale_check)
  if(NOT check EQUAL 50)
    string(APPEND failures "report.json: scale_check '${check}' on A4 in mm\n")
  endif()
  if(pdf AND NOT summary MATCHES "print          patterns.pdf at 100 % [^\n]* then 50 mm long")
    string(APPEND failures "the summary does not say how to check the printed scale: ${summary}\n")
  endif()
  string(JSON left LENGTH "${report}" patterns left_out_pieces)
  if(NOT left EQUAL 0)
    string(APPEND failures "report.json: ${left} loose pieces left out of a mesh in one piece\n")
  endif()
  # the assembly: every piece joined once, the first one onto itself
  string(JSON charts GET "${report}" charts)
  string(JSON steps LENGTH "${report}" assembly)
  string(JSON first GET "${report}" assembly 0 piece)
  string(JSON first_onto GET "${report}" assembly 0 onto)
  if(NOT steps EQUAL charts OR NOT first EQUAL first_onto)
    string(APPEND failures "report.json: ${steps} assembly steps for ${charts} pieces\n")
  endif()
  if(summary MATCHES "beyond bounds")
    string(APPEND failures "the summary has charts beyond the thresholds at the defaults: ${summary}\n")
  endif()
  if(NOT summary MATCHES "assembly       1\\. piece [0-9]+ \\(the largest\\)")
    string(APPEND failures "the summary has no assembly order: ${summary}\n")
  endif()
  file(GLOB written RELATIVE "${WORK_DIR}/out" "${WORK_DIR}/out/*" "${WORK_DIR}/out/.*")
  list(SORT written)
  set(expected "atlas.mtl;atlas.obj;charts.ply")
  set(expected_pdf OFF)
  if(PDF)  # built with cairo
    list(APPEND expected patterns.pdf)
    set(expected_pdf ON)
  endif()
  list(APPEND expected patterns.svg report.json segmentation.svg)
  string(JSON viewer GET "${report}" viewer)
  set(expected_viewer OFF)
  if(VIEWER)  # built with three.js
    list(APPEND expected viewer.html)
    set(expected_viewer ON)
  endif()
  if(NOT written STREQUAL expected OR NOT pdf STREQUAL expected_pdf OR NOT viewer STREQUAL expected_viewer)
    string(APPEND failures "--out-dir wrote '${written}', report.json says pdf ${pdf}, viewer ${viewer}\n")
  endif()
endif()

# coordinates beyond 2^64: the same pieces as at 1 (a cube's six sides,
# unmerged), their seams smoothed and cuts shortened likewise (a refused seam
# smoothing once emptied the result: "0 faces", no chart, and a success)
foreach(unit 1 1e30)
  set(u ${unit})
  file(WRITE "${WORK_DIR}/cube_${unit}.off"
       "OFF\n8 12 0\n0 0 0\n${u} 0 0\n${u} ${u} 0\n0 ${u} 0\n0 0 ${u}\n${u} 0 ${u}\n${u} ${u} ${u}\n0 ${u} ${u}\n"
       "3 0 2 1\n3 0 3 2\n3 4 5 6\n3 4 6 7\n3 0 1 5\n3 0 5 4\n3 1 2 6\n3 1 6 5\n3 2 3 7\n3 2 7 6\n3 3 0 4\n3 3 4 7\n")
  execute_process(COMMAND "${PROGRAM}" "${WORK_DIR}/cube_${unit}.off" --json --quiet --no-merge
                          --out-dir "${WORK_DIR}/cube_${unit}"
                  RESULT_VARIABLE code OUTPUT_VARIABLE json ERROR_VARIABLE err)
  if(NOT code EQUAL 0 OR NOT EXISTS "${WORK_DIR}/cube_${unit}/patterns.svg")
    string(APPEND failures "the cube at ${unit}: exit code ${code}, stderr '${err}'\n")
    continue()
  endif()
  string(JSON faces GET "${json}" faces)
  string(JSON charts GET "${json}" charts)
  string(JSON smoothing_status GET "${json}" seam_smoothing status)
  string(JSON shortening_status GET "${json}" cut_shortening status)
  if(NOT faces EQUAL 12 OR NOT charts EQUAL 6 OR NOT smoothing_status STREQUAL "success"
     OR NOT shortening_status STREQUAL "success")
    string(APPEND failures "the cube at ${unit}: ${faces} faces, ${charts} charts, seam smoothing "
                           "'${smoothing_status}', cut shortening '${shortening_status}'\n")
  endif()
  check_json_schema("${json}" "${schema}" "--json of the cube at ${unit}" failures)
endforeach()

# loose specks beside a model: the cube (12 cm on the page) with three loose
# triangles 0.01 of its side across (1.2 mm) and one a third of it (4 cm):
# the specks are left off the pattern and out of the assembly, and the
# summary says so; with --min-loose-piece 0 every piece is drawn (and, with
# --no-scale-check, no scale check)
file(WRITE "${WORK_DIR}/cube_specks.off"
     "OFF\n20 16 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
     "3 0 0\n3.01 0 0\n3 0.01 0\n4 0 0\n4.01 0 0\n4 0.01 0\n5 0 0\n5.01 0 0\n5 0.01 0\n"
     "6 0 0\n6.33 0 0\n6 0.33 0\n"
     "3 0 2 1\n3 0 3 2\n3 4 5 6\n3 4 6 7\n3 0 1 5\n3 0 5 4\n3 1 2 6\n3 1 6 5\n3 2 3 7\n3 2 7 6\n3 3 0 4\n3 3 4 7\n"
     "3 8 9 10\n3 11 12 13\n3 14 15 16\n3 17 18 19\n")
foreach(bound 2mm 0)
  set(no_check)
  if(bound STREQUAL "0")
    set(no_check --no-scale-check)
  endif()
  execute_process(COMMAND "${PROGRAM}" "${WORK_DIR}/cube_specks.off" --no-merge --scale 120 --min-loose-piece ${bound}
                          ${no_check} --out-dir "${WORK_DIR}/cube_specks_${bound}"
                  RESULT_VARIABLE code OUTPUT_VARIABLE summary ERROR_VARIABLE err)
  if(NOT code EQUAL 0 OR NOT EXISTS "${WORK_DIR}/cube_specks_${bound}/report.json")
    string(APPEND failures "the cube with specks, --min-loose-piece ${bound}: exit code ${code}, stderr '${err}'\n")
    continue()
  endif()
  file(READ "${WORK_DIR}/cube_specks_${bound}/report.json" report)
  check_json_schema("${report}" "${schema}" "report.json of the cube with specks" failures)
  string(JSON charts GET "${report}" charts)
  string(JSON left LENGTH "${report}" patterns left_out_pieces)
  string(JSON steps LENGTH "${report}" assembly)
  set(expected_left 0)
  if(bound STREQUAL "2mm")
    set(expected_left 3)
    if(NOT summary MATCHES "; 3 loose pieces shorter than 2 mm left out, --min-loose-piece 0 draws them")
      string(APPEND failures "the cube with specks: the summary does not say the specks were left out: ${summary}\n")
    endif()
  endif()
  string(JSON check GET "${report}" patterns scale_check)
  file(READ "${WORK_DIR}/cube_specks_${bound}/patterns.svg" svg)
  string(FIND "${svg}" "class=\"check\"" check_at)
  if((no_check AND (NOT check EQUAL 0 OR check_at GREATER -1 OR summary MATCHES "print          "))
     OR (NOT no_check AND (NOT check EQUAL 50 OR check_at LESS 0)))
    string(APPEND failures "the cube with specks, '${no_check}': scale_check ${check}, in patterns.svg at ${check_at}\n")
  endif()
  math(EXPR expected_steps "${charts} - ${expected_left}")
  if(NOT charts EQUAL 10 OR NOT left EQUAL expected_left OR NOT steps EQUAL expected_steps)
    string(APPEND failures "the cube with specks, --min-loose-piece ${bound}: ${charts} charts, ${left} left out, "
                           "${steps} assembly steps\n")
  endif()
endforeach()

if(failures)
  message(FATAL_ERROR "segment_mesh's command line:\n${failures}")
endif()
message("ok     --help, --version, the report against ${SCHEMA}")
