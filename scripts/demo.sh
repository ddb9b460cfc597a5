#!/usr/bin/env bash
# Installs the dependencies, builds the examples and runs the main demo:
# segment_mesh on the default mesh, fandisk from Debian's libcgal-demo (which
# the dependencies include), or on the mesh given as first argument; further
# arguments go to segment_mesh (for instance --scale 10 --units mm --tabs).
# The outputs go to build/demo/: charts.ply, atlas.obj, atlas.mtl,
# patterns.svg and segmentation.svg.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh
build=${CGAL_QD_BUILD_DIR:-build}
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DCGAL_QD_BUILD_TESTS=OFF
cmake --build "$build" -j "$(nproc)" --target segment_mesh
if [ $# -ge 1 ]; then
  mesh=$1
  shift
  "$build/examples/segment_mesh" "$mesh" --out-dir "$build/demo" "$@"
else
  # fandisk is about 1 mesh unit tall: 80 mm per unit puts its four pieces on one A4 page
  "$build/examples/segment_mesh" "$build/cgal_data/data/meshes/fandisk.off" --out-dir "$build/demo" \
    --scale 80 --tabs
fi
