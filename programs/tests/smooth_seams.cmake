# Runs segment_mesh (PROGRAM) on elephant (MESH), a coarse mesh whose smoothed
# seams push several pieces beyond A_loc <= 2.5 %, with and without the seam
# smoothing, and checks that the smoothing is kept with every piece within the
# thresholds, that the borders it smooths less instead of leaving them along
# the edges make it smooth most of them, and that the seams match as the
# smoothing promises: every curve whose two sides matched (within 0.5 %)
# still does, and none ends up further apart than the worst seam of the
# unsmoothed pieces or, where all of those matched, than 0.5 %.

function(run_json out)
  execute_process(COMMAND "${PROGRAM}" "${MESH}" --json ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE json
                  ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "segment_mesh ${ARGN} failed (${code}): ${err}")
  endif()
  set(${out} "${json}" PARENT_SCOPE)
endfunction()

# the smoothing alone: the cut shortening after it changes the seam curves of both runs
run_json(edges --no-smooth-seams --no-shorten-cuts)
run_json(smooth --no-shorten-cuts)

string(JSON status GET "${smooth}" status)
string(JSON rejected GET "${smooth}" rejected_charts)
string(JSON overlapping GET "${smooth}" overlapping_charts)
string(JSON max_local GET "${smooth}" max_local_area_distortion_pct)
string(JSON kept GET "${smooth}" seam_smoothing kept)
string(JSON curves GET "${smooth}" seam_smoothing curves)
string(JSON smoothed GET "${smooth}" seam_smoothing curves_smoothed)
string(JSON zigzag GET "${smooth}" seam_zigzag)
string(JSON mismatch GET "${smooth}" max_seam_length_mismatch)
string(JSON zigzag_edges GET "${edges}" seam_zigzag)
string(JSON mismatch_edges GET "${edges}" max_seam_length_mismatch)
string(JSON matched GET "${smooth}" seam_curves_matched)
string(JSON matched_edges GET "${edges}" seam_curves_matched)
string(JSON charts GET "${smooth}" charts)
string(JSON charts_edges GET "${edges}" charts)
message(STATUS "elephant: ${charts} pieces, ${smoothed} of ${curves} curves smoothed, zigzag ${zigzag_edges} -> "
               "${zigzag}, largest seam mismatch ${mismatch_edges} -> ${mismatch}, largest A_loc ${max_local} %")

if(NOT status STREQUAL "success")
  message(FATAL_ERROR "status ${status}")
endif()
if(NOT charts EQUAL charts_edges)
  message(FATAL_ERROR "the smoothing changed the number of pieces: ${charts_edges} -> ${charts}")
endif()
if(NOT rejected EQUAL 0 OR NOT overlapping EQUAL 0)
  message(FATAL_ERROR "${rejected} pieces beyond the thresholds, ${overlapping} overlapping")
endif()
string(REGEX REPLACE "^([0-9]+)\\.([0-9][0-9][0-9]).*$" "\\1\\2" a_loc "${max_local}000")
if(a_loc GREATER 2500)
  message(FATAL_ERROR "largest A_loc ${max_local} % beyond 2.5 %")
endif()
if(NOT kept)
  message(FATAL_ERROR "the smoothed seams were not kept")
endif()
# with the borders of a rejected piece left along the edges at once, 6 of the 68 curves were smoothed
math(EXPR third "${curves} / 3")
if(NOT smoothed GREATER third)
  message(FATAL_ERROR "only ${smoothed} of ${curves} curves smoothed")
endif()
# Z as a whole number of thousandths, for math(EXPR)
string(REGEX REPLACE "^([0-9]+)\\.([0-9][0-9][0-9]).*$" "\\1\\2" z "${zigzag}000")
string(REGEX REPLACE "^([0-9]+)\\.([0-9][0-9][0-9]).*$" "\\1\\2" z_edges "${zigzag_edges}000")
math(EXPR gain "${z_edges} - ${z}")
if(NOT gain GREATER 50)
  message(FATAL_ERROR "zigzag ${zigzag_edges} -> ${zigzag}: less than 0.05 smoother")
endif()
if(matched LESS matched_edges)
  message(FATAL_ERROR "${matched} seam curves matched after the smoothing, ${matched_edges} before")
endif()
# mismatches as whole numbers of ten-thousandths; a matched seam is within 50 of them
string(REGEX REPLACE "^0\\.([0-9][0-9][0-9][0-9]).*$" "\\1" m "${mismatch}0000")
string(REGEX REPLACE "^0\\.([0-9][0-9][0-9][0-9]).*$" "\\1" m_edges "${mismatch_edges}0000")
math(EXPR m "${m}")
math(EXPR m_edges "${m_edges}")
if(m_edges LESS 50)
  set(m_edges 50)
endif()
if(m GREATER m_edges)
  message(FATAL_ERROR "a seam ends ${mismatch} apart, the worst before the smoothing ${mismatch_edges}")
endif()
