#!/usr/bin/env bash
# Runs the unit tests of the border solver, the flattening and the measures
# under Valgrind's memcheck, on the Release build of scripts/test.sh: reads of
# uninitialised memory, which AddressSanitizer does not look for, fail the run
# (an Eigen decomposition whose rank threshold was set after compute() read
# coefficients it had never formed, and the LPFB converged or not depending
# on the build: doc/robustness.md). About a minute; CI runs it after
# scripts/test.sh. Installs valgrind if it is missing (run as root).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${CGAL_QD_BUILD_DIR:-build}
if ! command -v valgrind > /dev/null; then
  apt-get update
  DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends valgrind
fi
for test in test_length_preserved_free_boundary test_flatten_patch test_distortion; do
  [ -x "$build/test/$test" ] || { echo "build first (bash scripts/test.sh): $build/test/$test is missing" >&2; exit 1; }
  echo "valgrind: $test"
  timeout 900 valgrind --quiet --error-exitcode=9 "$build/test/$test" --log_level=nothing
  echo "valgrind: $test: no error"
done
