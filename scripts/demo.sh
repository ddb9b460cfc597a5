#!/usr/bin/env bash
# Installs the dependencies, builds the examples and runs the main demo on the
# default mesh (or on the mesh given as first argument).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh
build=${CGAL_QD_BUILD_DIR:-build}
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DCGAL_QD_BUILD_TESTS=OFF
cmake --build "$build" -j "$(nproc)" --target length_preserved_free_boundary
"$build/examples/length_preserved_free_boundary" "$@"
