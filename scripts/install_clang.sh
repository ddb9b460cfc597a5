#!/usr/bin/env bash
# Installs Debian's clang and its sanitizer and libFuzzer runtimes
# (libclang-rt-14-dev) if they are missing: scripts/sanitize.sh and
# scripts/fuzz.sh build with them.
set -euo pipefail
if ! command -v clang++ > /dev/null || ! dpkg-query -W -f='${Status}' libclang-rt-14-dev 2>/dev/null | grep -q "install ok installed"; then
  export DEBIAN_FRONTEND=noninteractive
  apt-get update
  apt-get install -y --no-install-recommends clang libclang-rt-14-dev
fi
