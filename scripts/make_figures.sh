#!/usr/bin/env bash
# Regenerates the figures of doc/ and the README with programs/segment_mesh:
# the segmentations of elephant and bunny00 (pictures of the mesh in its chart colours),
# the first page of bunny00's sewing pattern (6 mm seam allowance, notches),
# the true-scale pattern of fandisk (80 mm per mesh unit, with glue tabs), and
# the net of cube_quad, and (with Chromium) a screenshot of bunny00's
# viewer.html. Run after a build (bash scripts/demo.sh or
# bash scripts/test.sh), from any directory.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${CGAL_QD_BUILD_DIR:-build}
program=$build/programs/segment_mesh
meshes=$build/cgal_data/data/meshes
[ -x "$program" ] || { echo "build first: $program is missing" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$program" "$meshes/elephant.off" --out-dir "$tmp/elephant" --quiet > /dev/null
"$program" "$meshes/bunny00.off" --out-dir "$tmp/bunny00" --quiet > /dev/null
# bunny00 as a sewing pattern (felt): a seam allowance, notches, no fold lines
"$program" "$meshes/bunny00.off" --out-dir "$tmp/bunny00_felt" --seam-allowance 6mm --notches 30mm \
  --fold-angle 180 --quiet > /dev/null
"$program" "$meshes/fandisk.off" --out-dir "$tmp/fandisk" --scale 80 --tabs --quiet > /dev/null
"$program" "$meshes/cube_quad.off" --out-dir "$tmp/cube" --scale 25 --tabs --no-assembly-page --quiet > /dev/null
cp "$tmp/elephant/segmentation.svg" doc/figures/elephant_segmentation.svg
cp "$tmp/bunny00/segmentation.svg" doc/figures/bunny00_segmentation.svg
cp "$tmp/fandisk/patterns.svg" doc/figures/fandisk_patterns.svg
# its first A4 page: the drawing's height and view cut to one page (297 mm)
sed -E '0,/<svg /s/height="[0-9.]+mm" viewBox="0 0 ([0-9.]+) [0-9.]+"/height="297.0000mm" viewBox="0 0 \1 297.0000"/' \
  "$tmp/bunny00_felt/patterns.svg" > doc/figures/bunny00_felt_pattern_page1.svg
cp "$tmp/cube/patterns.svg" doc/figures/cube_net.svg
if command -v chromium > /dev/null && [ -f "$tmp/bunny00/viewer.html" ]; then
  chromium --headless --no-sandbox --use-angle=swiftshader --enable-unsafe-swiftshader --hide-scrollbars \
    --window-size=1400,800 --virtual-time-budget=20000 --screenshot="$PWD/doc/figures/bunny00_viewer.png" \
    "file://$tmp/bunny00/viewer.html" 2> /dev/null
fi
ls -l doc/figures
