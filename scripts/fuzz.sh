#!/usr/bin/env bash
# Fuzzes the mesh readers (fuzz/fuzz_read_mesh.cpp) with libFuzzer under
# AddressSanitizer and UndefinedBehaviorSanitizer: read_polygon_soup() on OFF,
# OBJ, PLY and STL files, and read_and_repair_mesh(), each for SECONDS seconds
# (default 60) from the seed corpus in fuzz/corpus/, as many modes at a time
# as the machine has cores (each fuzzer runs on one). Installs clang and its
# runtime (Debian's clang and libclang-rt-14-dev) if needed. A finding prints
# the fuzzer's report, and the input that caused it is kept in build-fuzz/
# (<mode>-crash-*, -oom-*, -timeout-*), to be fixed and added to the tests;
# the other modes still run, and the script then fails, unless FUZZ_FATAL=0
# (the reporting run, while new campaigns still find new inputs).
# usage: [FUZZ_FATAL=0] [FUZZ_JOBS=N] bash scripts/fuzz.sh [SECONDS]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${SECONDS_PER_TARGET:-${1:-60}}
jobs=${FUZZ_JOBS:-$(nproc)}
bash scripts/install_clang.sh
out=build-fuzz
mkdir -p "$out"
clang++ -std=c++17 -O1 -g -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
  -Iinclude fuzz/fuzz_read_mesh.cpp -o "$out/fuzz_read_mesh" -lgmp -lmpfr
modes="off obj ply stl repair"
# one mode: its log in fuzz_<mode>.log, its exit status in fuzz_<mode>.status
fuzz_one() {
  local mode=$1
  # the corpus grows in build-fuzz/, the seeds stay as they are
  mkdir -p "$out/corpus_$mode"
  cp fuzz/corpus/$mode/* "$out/corpus_$mode/"
  rm -f "$out/fuzz_$mode.status"
  local status=0
  (cd "$out" && TMPDIR="$PWD" QD_FUZZ_FORMAT=$mode ./fuzz_read_mesh -max_total_time="$seconds" -rss_limit_mb=2048 \
     -timeout=10 -print_final_stats=1 -artifact_prefix="$mode-" "corpus_$mode" > "fuzz_$mode.log" 2>&1) || status=$?
  echo "$status" > "$out/fuzz_$mode.status"
}
running=0
for mode in $modes; do
  if [ "$running" -ge "$jobs" ]; then
    wait -n || true
    running=$((running - 1))
  fi
  echo "fuzz: $mode for $seconds s"
  fuzz_one "$mode" &
  running=$((running + 1))
done
wait || true
found=""
for mode in $modes; do
  status=$(cat "$out/fuzz_$mode.status" 2>/dev/null || echo missing)
  if [ "$status" = "0" ]; then
    echo "fuzz: $mode:" $(grep -E "^stat::number_of_executed_units|^stat::peak_rss_mb" "$out/fuzz_$mode.log" | tr '\n' ' ')
    continue
  fi
  grep -E "SUMMARY|runtime error|ERROR|fuzz_read_mesh:" "$out/fuzz_$mode.log" | head -5 || true
  grep -A30 "ERROR" "$out/fuzz_$mode.log" | grep -E "#[0-9]+ .* in " | grep -vE "sanitizer|fuzzer::" | head -12 || true
  echo "fuzz: $mode found a problem (status $status); the input is in $out/:" $(cd "$out" && ls "$mode"-* 2>/dev/null) >&2
  found="$found $mode"
done
if [ -n "$found" ]; then
  echo "fuzz: findings in$found" >&2
  [ "${FUZZ_FATAL:-1}" = "0" ] || exit 1
fi
