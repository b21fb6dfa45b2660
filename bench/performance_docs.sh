#!/usr/bin/env bash
# Regenerates the measurements of docs/PERFORMANCE.md's first section, "The fast end's goals"
# (issue 20), in one run on this machine: the benchmarks behind each goal (Google Benchmark
# JSON, medians of 3), a 100-variant sweep through the workers against one process per variant
# (bench/variants_workers.sh), the viewer's frame rate while the light is dragged
# (bench/viewer_drag.sh) and the demo's first frame on a cold shader cache, written to
# docs/performance/; then bench/performance_goals.py writes the goals' table from them into
# docs/PERFORMANCE.md between its markers. Every ratio compares two figures of this one run.
# Run on an otherwise idle machine after ./run build; about a minute on two cores with
# llvmpipe, plus about four for the sweeps. BUILD_DIR as for ./run.
#   bench/performance_docs.sh
set -euo pipefail
cd "$(dirname "$0")/.."
# EPOCHREALTIME and awk with a point for the decimals.
export LC_ALL=C
build=${BUILD_DIR:-build}
out=docs/performance
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$out"
bench() {
  local name=$1 filter=$2
  echo "$name: $filter" >&2
  "$build/bin/ivshadow_bench" --benchmark_filter="$filter" --benchmark_repetitions=3 \
    --benchmark_report_aggregates_only=true --benchmark_format=json >"$out/$name.json"
}
bench rays 'RaysAgainstCoin/(1000|100000)/[034]/[01]/'
bench still 'BundledStill/'
bench peel 'Peel/([1456789]|10)/'
bench map_build 'MapBuildMethods/(10000|100000)/4/[023]/'
echo "variants sweeps" >&2
bench/variants_workers.sh "$build" 3 >"$out/variants_workers.txt"
echo "viewer drag" >&2
bench/viewer_drag.sh >"$out/viewer_drag.txt"
echo "demo" >&2
{
  echo "run seconds"
  for run in 1 2 3; do
    start=$EPOCHREALTIME
    MESA_SHADER_CACHE_DISABLE=true "$build/bin/ivshadow" render iv_scenes/coloured_shadows.iv \
      -o "$tmp/demo.png" --size 800x600 >/dev/null
    awk -v run="$run" -v start="$start" -v end="$EPOCHREALTIME" 'BEGIN { print run, end - start }'
  done
} >"$out/demo.txt"
{
  echo "date $(date -u +%Y-%m-%dT%H:%M:%SZ)"
  echo "commit $(git rev-parse --short HEAD)"
  echo "load $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "renderer $("$build/bin/ivshadow" render iv_scenes/lit_plane.iv -o "$tmp/plane.png" \
    --size 16x16 2>&1 | sed -n 's/.* on \(.*\))$/\1/p')"
} >"$out/run.txt"
python3 bench/performance_goals.py "$out" docs/PERFORMANCE.md
