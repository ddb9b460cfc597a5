#!/usr/bin/env bash
# The robustness sweep over every mesh of libcgal-demo (OFF, PLY, STL): runs
# build/test/test_robustness --sweep (test/sweep_mesh.h) on each with a time
# limit and prints the Markdown table of doc/robustness.md (one row per mesh,
# then the totals). Run after a build with the tests on (bash scripts/test.sh).
# The same runs are the CTest tests labelled 'sweep' (ctest -L sweep).
# usage: [LIMIT=300] bash scripts/robustness_sweep.sh > table.md
set -uo pipefail
cd "$(dirname "$0")/.."
meshes=build/cgal_data/data/meshes
program=build/test/test_robustness
limit=${LIMIT:-300}
[ -x "$program" ] || { echo "build first: $program is missing" >&2; exit 1; }
"$program" --sweep --header
met=0; missed=0; crashed=0; timed_out=0; refused=0; total=0
for mesh in "$meshes"/*.off "$meshes"/*.ply "$meshes"/*.stl; do
  name=$(basename "$mesh")
  total=$((total + 1))
  row=$(timeout "$limit" "$program" --sweep "$mesh" 2>/dev/null)
  code=$?
  if [ $code -eq 124 ]; then
    timed_out=$((timed_out + 1)); echo "| $name | **timeout after $limit s** |"
  elif [ $code -ge 2 ]; then
    crashed=$((crashed + 1)); echo "| $name | **crashed (exit code $code)** $row |"
  else
    echo "$row"
    if [ $code -eq 0 ]; then met=$((met + 1)); else missed=$((missed + 1)); fi
    case "$row" in *"| – | – | – | – | – | – | – | – | – |"*) refused=$((refused + 1));; esac
  fi
done
echo
echo "$total meshes: $met met every target ($refused of them refused with a named status), $missed missed a target, $crashed crashed, $timed_out timed out (limit $limit s)."
