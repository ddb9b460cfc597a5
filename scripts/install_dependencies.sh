#!/usr/bin/env bash
# Installs what CGAL_QD needs on a Debian machine (run as root).
# Core: CGAL 5.5, Eigen 3.4, Boost.Graph, Boost.Test, CMake, a C++17 compiler.
# libcgal-demo brings CGAL's real test meshes; ccache speeds up rebuilds.
# The program segment_mesh parses its options with CLI11 and writes its report
# with nlohmann-json (both header-only), and writes PDF patterns with cairo
# (optional; pkg-config finds it), and seam allowances with Clipper
# (libpolyclipping-dev, optional); poppler-utils lets a test print a PDF
# pattern to pixels and measure it. segment_mesh's viewer.html inlines
# three.js from the npm registry (viewer/package.json, pinned in
# viewer/package-lock.json): npm installs it into viewer/node_modules, where
# CMake finds it; without it segment_mesh writes no viewer.html.
# Optional accelerators, detected at configure time: SuiteSparse (CHOLMOD) with
# OpenBLAS for the interior system of flatten_patch(), TBB for the parallel
# trials of the chart merging; CGAL_QD builds and works without them.
set -euo pipefail
packages=(build-essential cmake ccache libcgal-dev libeigen3-dev libboost-graph-dev
          libboost-test-dev libcgal-demo libcli11-dev nlohmann-json3-dev
          libcairo2-dev libpolyclipping-dev pkg-config poppler-utils libsuitesparse-dev libopenblas-dev libtbb-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  export DEBIAN_FRONTEND=noninteractive
  apt-get update
  apt-get install -y --no-install-recommends "${missing[@]}"
fi
viewer="$(cd "$(dirname "$0")/../viewer" && pwd)"
if [ ! -f "$viewer/node_modules/three/build/three.min.js" ]; then
  if ! command -v npm > /dev/null; then
    export DEBIAN_FRONTEND=noninteractive
    apt-get update
    apt-get install -y --no-install-recommends npm
  fi
  (cd "$viewer" && npm ci --no-audit --no-fund) ||
    echo "install_dependencies: three.js could not be installed from npm; segment_mesh will write no viewer.html" >&2
fi
