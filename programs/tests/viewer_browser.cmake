# Opens the viewer.html that segment_mesh (PROGRAM) writes for MESH in
# headless Chromium (CHROMIUM, software WebGL) and checks that it draws: the
# page reports itself ready with no error and no console error, and its
# screenshot is not blank and shows at least MIN_COLOURS of the charts'
# colours (each over at least 200 pixels; the flat pieces on the right are
# drawn unlit, in exactly those colours). PYTHON reads the screenshot
# (png_colours.py). With PROBE, a copy of the page with viewer_probe.js points
# at both views on a grid, and every piece must be named on the flat side, a
# seam named, and a clicked piece kept while the pointer moves on.

file(REMOVE_RECURSE "${WORK_DIR}")
execute_process(COMMAND "${PROGRAM}" "${MESH}" --quiet --out-dir "${WORK_DIR}" RESULT_VARIABLE code
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0 OR NOT EXISTS "${WORK_DIR}/viewer.html")
  message(FATAL_ERROR "segment_mesh failed (${code}) or wrote no viewer.html: ${err}")
endif()
set(browser "${CHROMIUM}" --headless --no-sandbox --disable-dev-shm-usage --use-angle=swiftshader
            --enable-unsafe-swiftshader --hide-scrollbars --window-size=1400,800 --virtual-time-budget=20000)
execute_process(COMMAND ${browser} --dump-dom "file://${WORK_DIR}/viewer.html" RESULT_VARIABLE code
                OUTPUT_VARIABLE dom ERROR_VARIABLE err TIMEOUT 240)
string(REGEX MATCH "<body[^>]*>" body "${dom}")
message(STATUS "${body}")
if(NOT body MATCHES "data-status=\"ready\"")
  message(FATAL_ERROR "the viewer did not draw (${code}): ${body}\n${err}")
endif()
if(NOT body MATCHES "data-errors=\"0\"")
  string(REGEX MATCH "<div id=\"info\">[^<]*" info "${dom}")
  message(FATAL_ERROR "the viewer saw errors: ${body} ${info}")
endif()
string(REGEX MATCH "data-palette=\"([^\"]*)\"" _ "${body}")
set(palette "${CMAKE_MATCH_1}")
execute_process(COMMAND ${browser} "--screenshot=${WORK_DIR}/screenshot.png" "file://${WORK_DIR}/viewer.html"
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 240)
if(NOT EXISTS "${WORK_DIR}/screenshot.png")
  message(FATAL_ERROR "no screenshot (${code}): ${err}")
endif()
execute_process(COMMAND "${PYTHON}" "${CMAKE_CURRENT_LIST_DIR}/png_colours.py" "${WORK_DIR}/screenshot.png" 200
                        "${palette}" RESULT_VARIABLE code OUTPUT_VARIABLE counts ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "cannot read the screenshot: ${err}")
endif()
string(STRIP "${counts}" counts)
message(STATUS "screenshot: ${counts}")
string(REGEX MATCH "pixels=([0-9]+) non_white=([0-9]+) colours=([0-9]+)" _ "${counts}")
set(pixels ${CMAKE_MATCH_1})
set(drawn ${CMAKE_MATCH_2})
set(colours ${CMAKE_MATCH_3})
math(EXPR tenth "${pixels} / 10")
if(drawn LESS tenth)
  message(FATAL_ERROR "the screenshot is nearly blank: ${drawn} of ${pixels} pixels are not white")
endif()
if(colours LESS MIN_COLOURS)
  message(FATAL_ERROR "the screenshot shows ${colours} chart colours, fewer than ${MIN_COLOURS}")
endif()

if(PROBE)
  file(READ "${CMAKE_CURRENT_LIST_DIR}/viewer_probe.js" probe)
  file(READ "${WORK_DIR}/viewer.html" page)
  string(REPLACE "</body>" "<script>${probe}</script></body>" page "${page}")
  file(WRITE "${WORK_DIR}/probe.html" "${page}")
  execute_process(COMMAND ${browser} --dump-dom "file://${WORK_DIR}/probe.html" RESULT_VARIABLE code
                  OUTPUT_VARIABLE dom ERROR_VARIABLE err TIMEOUT 240)
  string(REGEX MATCH "<body[^>]*>" body "${dom}")
  string(REGEX REPLACE "data-palette=\"[^\"]*\" " "" shown "${body}")
  message(STATUS "pointing: ${shown}")
  string(REGEX MATCH "data-charts=\"([0-9]+)\"" _ "${body}")
  set(charts ${CMAKE_MATCH_1})
  string(REGEX MATCH "data-pieces-right=\"([0-9]+)\"" _ "${body}")
  set(right ${CMAKE_MATCH_1})
  string(REGEX MATCH "data-pieces-left=\"([0-9]+)\"" _ "${body}")
  set(left ${CMAKE_MATCH_1})
  if(NOT body MATCHES "data-probe=\"done\"" OR NOT body MATCHES "data-errors=\"0\"")
    message(FATAL_ERROR "pointing at the page failed: ${shown}")
  endif()
  if(NOT right EQUAL charts OR left LESS 1)
    message(FATAL_ERROR "pointing named ${right} of ${charts} pieces on the flat side, ${left} on the mesh")
  endif()
  if(NOT body MATCHES "data-seam=\"[A-Z][0-9]* (between pieces|a cut inside piece)")
    message(FATAL_ERROR "pointing named no seam: ${shown}")
  endif()
  if(NOT body MATCHES "data-pinned=\"kept\"")
    message(FATAL_ERROR "a clicked piece was not kept: ${shown}")
  endif()
endif()
