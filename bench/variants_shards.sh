#!/usr/bin/env bash
# Times one sweep three ways on this machine (docs/PERFORMANCE.md, "Variants in shards"): one
# process rendering a variant at a time, two shards (--shard 0/2 and 1/2) running at once, and
# one process with --jobs 2. Prints the wall times and their ratios; nothing is asserted.
# Usage: bench/variants_shards.sh [BUILD_DIR]   (after ./run build; about a minute on 2 cores)
set -euo pipefail
cd "$(dirname "$0")/.."
exe=${1:-build}/bin/ivshadow
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat >"$work/sweep.variants" <<'SWEEP'
sweep grid Lamp.maxLayers = 1 .. 4 step 1 * Lamp.intensity = 0.6 | 0.8 | 1 | 1.2
  Lamp.resolution = 256
  Lamp.method = MAP
SWEEP
args=(iv_scenes/coloured_shadows.iv "$work/sweep.variants" --size 320x240 --frames 3)
seconds() { date +%s.%N; }
# awk, not bc, which a minimal Debian lacks.
minus() { awk "BEGIN { print $1 - $2 }"; }
ratio() { awk "BEGIN { print $1 / $2 }"; }

start=$(seconds)
"$exe" variants "${args[@]}" -o "$work/one" --jobs 1 >/dev/null 2>&1
one=$(minus "$(seconds)" "$start")

start=$(seconds)
"$exe" variants "${args[@]}" -o "$work/shards" --shard 0/2 >/dev/null 2>&1 &
first=$!
"$exe" variants "${args[@]}" -o "$work/shards" --shard 1/2 >/dev/null 2>&1 &
second=$!
wait "$first" "$second"
"$exe" variants-merge "$work/shards" >/dev/null
shards=$(minus "$(seconds)" "$start")

start=$(seconds)
"$exe" variants "${args[@]}" -o "$work/jobs" --jobs 2 >/dev/null 2>&1
jobs=$(minus "$(seconds)" "$start")

printf 'cores %s, 16 variants at 320x240, 3 frames each\n' "$(nproc)"
printf 'one process, --jobs 1      %6.2f s  1.00\n' "$one"
printf 'two shards at once + merge %6.2f s  %.2f\n' "$shards" "$(ratio "$one" "$shards")"
printf 'one process, --jobs 2      %6.2f s  %.2f\n' "$jobs" "$(ratio "$one" "$jobs")"
