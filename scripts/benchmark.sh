#!/usr/bin/env bash
# Installs the dependencies, builds qd_benchmark and runs it; the results go to
# benchmark/results (table.md, results.csv, scaling.svg). Extra arguments go to
# qd_benchmark (--quick, --max-faces N, --budget SECONDS, --out DIR).
# A full run takes about a quarter of an hour on two cores.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh
build=${CGAL_QD_BUILD_DIR:-build}
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DCGAL_QD_BUILD_BENCHMARK=ON
cmake --build "$build" -j "$(nproc)" --target qd_benchmark
"$build/benchmark/qd_benchmark" --out benchmark/results "$@"
