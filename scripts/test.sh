#!/usr/bin/env bash
# Installs the dependencies, builds everything and runs the whole test suite.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh
# the browser tests of viewer.html: headless Chromium, and python3 to read its screenshots
for p in chromium python3; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    apt-get update
    DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends chromium python3
    break
  fi
done
build=${CGAL_QD_BUILD_DIR:-build}
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DCGAL_QD_BUILD_TESTS=ON -DBUILD_TESTING=ON -DCGAL_QD_BUILD_EXAMPLES=ON
cmake --build "$build" -j "$(nproc)"
echo "test.sh: dependencies and build took $SECONDS s"
cd "$build"
ctest --output-on-failure --no-tests=error -j "$(nproc)"
