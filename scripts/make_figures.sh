#!/usr/bin/env bash
# Regenerates the figures of doc/ and the README with programs/segment_mesh:
# the segmentations of elephant and bunny00 (pictures of the mesh in its chart colours),
# the true-scale pattern of fandisk (80 mm per mesh unit, with glue tabs), and
# the net of cube_quad. Run after a build (bash scripts/demo.sh or
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
"$program" "$meshes/fandisk.off" --out-dir "$tmp/fandisk" --scale 80 --tabs --quiet > /dev/null
"$program" "$meshes/cube_quad.off" --out-dir "$tmp/cube" --scale 25 --tabs --no-assembly-page --quiet > /dev/null
cp "$tmp/elephant/segmentation.svg" doc/figures/elephant_segmentation.svg
cp "$tmp/bunny00/segmentation.svg" doc/figures/bunny00_segmentation.svg
cp "$tmp/fandisk/patterns.svg" doc/figures/fandisk_patterns.svg
cp "$tmp/cube/patterns.svg" doc/figures/cube_net.svg
ls -l doc/figures
