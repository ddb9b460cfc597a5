#!/usr/bin/env bash
# Builds the unit tests and segment_mesh with AddressSanitizer (leaks
# included) and UndefinedBehaviorSanitizer, CGAL's and Eigen's assertions on,
# in a build directory of its own, and runs them (the program on malformed
# files and bad options, and on elephant); any report fails the run. CI runs it
# after scripts/test.sh (which installs the dependencies). It builds with
# clang (installed if missing), which compiles the instrumented tests in
# about 60 % of g++'s time and half its memory.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
build=${CGAL_QD_SANITIZE_DIR:-build-sanitize}
bash scripts/install_clang.sh
flags="-O1 -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all"
cmake -S . -B "$build" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Sanitize -DCMAKE_CXX_FLAGS_SANITIZE="$flags" \
      -DCMAKE_EXE_LINKER_FLAGS_SANITIZE="-fsanitize=address,undefined" \
      -DCGAL_QD_BUILD_TESTS=ON -DBUILD_TESTING=ON -DCGAL_QD_BUILD_EXAMPLES=OFF \
      -DCGAL_QD_BUILD_BENCHMARK=OFF -DCGAL_QD_BUILD_SWEEP=OFF
cmake --build "$build" -j "$(nproc)"
echo "sanitize.sh: clang and the instrumented build took $SECONDS s"
cd "$build"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:check_initialization_order=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export LSAN_OPTIONS=suppressions=$root/scripts/lsan_suppressions.txt
ctest -L "unit|program" --output-on-failure --no-tests=error -j "$(nproc)"
