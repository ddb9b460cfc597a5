#!/usr/bin/env bash
# Installs the dependencies, builds the program segment_mesh and runs the main demo:
# segment_mesh on the default mesh, fandisk from Debian's libcgal-demo (which
# the dependencies include), or on the mesh given as first argument; further
# arguments go to segment_mesh (for instance --size 150mm --tabs).
# The outputs go to build/demo/: charts.ply, atlas.obj, atlas.mtl,
# patterns.svg, patterns.pdf, segmentation.svg, viewer.html (open it in a
# browser) and report.json.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh
build=${CGAL_QD_BUILD_DIR:-build}
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DCGAL_QD_BUILD_TESTS=OFF
cmake --build "$build" -j "$(nproc)" --target segment_mesh
if [ $# -ge 1 ]; then
  mesh=$1
  shift
  "$build/programs/segment_mesh" "$mesh" --out-dir "$build/demo" "$@"
else
  # the pattern at the default size: the model 200 mm at its largest, or less
  # (fandisk, with tabs: 96 mm) so that every piece fits on an A4 page
  "$build/programs/segment_mesh" "$build/cgal_data/data/meshes/fandisk.off" --out-dir "$build/demo" --tabs
fi
