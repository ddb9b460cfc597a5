#!/usr/bin/env bash
# The speed of the segmentation (segment_mesh at its defaults), in
# one run, and writes benchmark/results/segmentation.md:
#
# 1. this tree against a baseline built from git history (BASELINE, default
#    b75b356, the code when the speed issue was filed; built once into
#    $build/baseline-COMMIT), run in turn RUNS times each (default 3) on the
#    seven meshes of doc/segmentation_results.md: the medians of the wall
#    time, their ratio, and the pieces;
# 2. elephant Loop-subdivided 1 to 4 times (22K to 1.4M faces): the wall time
#    and peak resident memory of one run each, and the pieces; a level is
#    left out once the one before took more than SERIES_LIMIT seconds
#    (default 150), or beyond MAX_FACES faces (default 1,500,000).
#
# Needs the git history (a clone has it), python3 and GNU time (installed if
# missing). Takes about 16 minutes on two cores, 7 of them the 1.4M-face run.
# usage: [RUNS=3] [BASELINE=b75b356] [MESHES="cow elephant"] [SERIES_LIMIT=150] [MAX_FACES=N]
#        bash scripts/segmentation_benchmark.sh
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh
[ -x /usr/bin/time ] || { export DEBIAN_FRONTEND=noninteractive; apt-get install -y --no-install-recommends time; }
build=${CGAL_QD_BUILD_DIR:-build}
runs=${RUNS:-3}
baseline=${BASELINE:-b75b356}
series_limit=${SERIES_LIMIT:-150}
max_faces=${MAX_FACES:-1500000}
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build "$build" -j "$(nproc)" --target segment_mesh qd_benchmark
program=$build/programs/segment_mesh
meshes=$build/cgal_data/data/meshes

# the baseline, from git history
commit=$(git rev-parse --short "$baseline")
base=$build/baseline-$commit
if [ ! -x "$base/build/examples/segment_mesh" ]; then
  rm -rf "$base"
  mkdir -p "$base/src"
  git archive "$commit" | tar -x -C "$base/src"
  cmake -S "$base/src" -B "$base/build" -DCMAKE_BUILD_TYPE=Release -DCGAL_QD_BUILD_TESTS=OFF > /dev/null
  cmake --build "$base/build" -j "$(nproc)" --target segment_mesh
fi
baseline_program=$base/build/examples/segment_mesh

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# one run: prints "seconds peak_kb pieces"
run() {
  /usr/bin/time -f '%e %M' -o "$tmp/time" "$1" "$2" --json > "$tmp/json" 2> /dev/null || true
  local pieces
  pieces=$(grep -o '"charts": *[0-9]*' "$tmp/json" | head -1 | grep -o '[0-9]*$' || echo 0)
  echo "$(cat "$tmp/time") ${pieces:-0}"
}

results=$tmp/results
: > "$results"
for name in ${MESHES:-fandisk bunny00 cow camel elephant mannequin-devil armadillo}; do
  for ((k = 0; k < runs; ++k)); do
    echo "compare $name $(run "$baseline_program" "$meshes/$name.off") $(run "$program" "$meshes/$name.off")" >> "$results"
  done
  echo "$name done" >&2
done
last=0
for level in 1 2 3 4; do
  "$build/benchmark/qd_benchmark" --subdivide "$meshes/elephant.off" "$level" "$tmp/elephant_$level.off"
  faces=$(sed -n 2p "$tmp/elephant_$level.off" | awk '{print $2}')
  if [ "$faces" -gt "$max_faces" ] || awk "BEGIN{exit !($last > $series_limit)}"; then
    echo "series $level $faces skipped" >> "$results"
    continue
  fi
  line=$(run "$program" "$tmp/elephant_$level.off")
  echo "series $level $faces $line" >> "$results"
  last=$(echo "$line" | awk '{print $1}')
  echo "elephant x$level: $line" >&2
done

mkdir -p benchmark/results
python3 - "$results" "$commit" "$(git rev-parse --short HEAD)" "$runs" "$series_limit" > "$tmp/segmentation.md" <<'PY'
import statistics, sys
path, baseline, head, runs, limit = sys.argv[1:]
compare, series = {}, []
for line in open(path):
    f = line.split()
    if f[0] == "compare":
        compare.setdefault(f[1], []).append([float(x) for x in f[2:8]])
    else:
        series.append(f[1:])
# a report without a piece count is a failed run, not a segmentation into 0 pieces
if any(r[2] == 0 or r[5] == 0 for rows in compare.values() for r in rows) or \
   any(len(s) >= 5 and s[4] == "0" for s in series):
    sys.exit("segmentation_benchmark: a run gave no piece count (it failed, or its report changed)")
print("# Segmentation speed\n")
print("`bash scripts/segmentation_benchmark.sh`: `segment_mesh --json` at its defaults, wall time, this tree "
      "(%s) and the baseline %s run in turn, %s times each; medians. Ratio = this tree / baseline.\n" % (head, baseline, runs))
print("| mesh | baseline s | now s | ratio | pieces, baseline | pieces, now | peak MB now |")
print("|---|---:|---:|---:|---:|---:|---:|")
for mesh, rows in compare.items():
    b = statistics.median(r[0] for r in rows)
    n = statistics.median(r[3] for r in rows)
    print("| %s | %.2f | %.2f | %.2f× | %d | %d | %.0f |" % (mesh, b, n, n / b if b > 0 else 0, rows[0][2], rows[0][5],
                                                         max(r[4] for r in rows) / 1024))
print("\n## Scaling: elephant Loop-subdivided\n")
print("One run each; a level is left out once the one before took more than %s s.\n" % limit)
print("| subdivisions | faces | pieces | s | peak MB |")
print("|---:|---:|---:|---:|---:|")
for s in series:
    if len(s) < 5:
        print("| %s | %s | - | left out | - |" % (s[0], s[1]))
    else:
        print("| %s | %s | %s | %.1f | %.0f |" % (s[0], s[1], s[4], float(s[2]), float(s[3]) / 1024))
PY
# written whole or not at all
mv "$tmp/segmentation.md" benchmark/results/segmentation.md
cat benchmark/results/segmentation.md
