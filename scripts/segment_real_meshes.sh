#!/usr/bin/env bash
# Runs programs/segment_mesh on CGAL's real meshes (libcgal-demo) and writes
# the table of doc/segmentation_results.md to standard output. Run after a
# build (bash scripts/test.sh or bash scripts/demo.sh); needs python3.
# usage: [MESHES="cow elephant"] bash scripts/segment_real_meshes.sh [segment_mesh options] > table.md
set -euo pipefail
cd "$(dirname "$0")/.."
meshes=build/cgal_data/data/meshes
program=build/programs/segment_mesh
[ -x "$program" ] || { echo "build first: $program is missing" >&2; exit 1; }
for name in ${MESHES:-fandisk bunny00 cow camel elephant mannequin-devil armadillo}; do
  "$program" "$meshes/$name.off" --json "$@" | sed "s/^{/{\"mesh\": \"$name\", /"
done | python3 -c '
import json, sys
print("| mesh | faces | VSA | after splitting | final | max A(Ω) % | max L² | max A_loc % | overlapping | seam length | seam mismatch % | seams matched | zigzag Z | compactness | curves smoothed | trials | VSA s | refine s | merge s | flatten s | total s |")
print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
for line in sys.stdin:
    d = json.loads(line)
    s = lambda k: "%.2f" % (d[k] / 1000)
    sm = d.get("seam_smoothing")
    smoothed = "off" if sm is None else ("%d of %d" % (sm["curves_smoothed"], sm["curves"]) if sm["kept"] else "0 (%d charts failed)" % sm["rejected_charts"])
    print("| %s | %d | %d | %d | **%d** | %.2f | %.3f | %.2f | %d | %.4g | %.1f | %s | %.3f | %.3f | %s | %d | %s | %s | %s | %s | %s |" % (
        d["mesh"], d["faces"], d["charts_after_vsa"], d["charts_before_merging"], d["charts"],
        d["max_area_distortion_pct"], d["max_l2_stretch"], d["max_local_area_distortion_pct"],
        d["overlapping_charts"], d["seam_length"], 100 * d["max_seam_length_mismatch"], "%d of %d" % (d["seam_curves_matched"], d["seam_curves"]), d["seam_zigzag"],
        d["compactness"], smoothed, d["merge_trials"], s("time_vsa_ms"), s("time_refine_ms"), s("time_merge_ms"), s("time_flatten_ms"),
        s("time_total_ms")))
'
