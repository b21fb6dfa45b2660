#!/usr/bin/env bash
# Times one 100-variant sweep of iv_scenes/coloured_shadows.iv (the light's intensity, 3 frames
# each, the default renderer: traced on a software rasteriser) both ways on this machine, at
# 320x240 and at 800x600 (docs/PERFORMANCE.md, "Variants sweeps"): through the workers (the
# default) and with one `ivshadow render` process per variant (IVSHADOW_VARIANTS_WORKERS=0).
# The two ways alternate, ROUNDS times each (default 3); printed are the median wall times
# and CPU times (user + system, the sweep's processes together; less moved by other load on
# the machine than the wall clock) and their ratios. The pictures of the two ways must be the
# same files. Nothing is asserted about the times.
# Usage: bench/variants_workers.sh [BUILD_DIR] [ROUNDS] [JOBS]   (after ./run build; about
# 4 minutes on 2 cores with 3 rounds)
set -euo pipefail
cd "$(dirname "$0")/.."
exe=$(realpath "${1:-build}")/bin/ivshadow
rounds=${2:-3}
jobs=${3:-1}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf 'sweep light Lamp.intensity = 0.01 .. 1 step 0.01\n' >"$work/sweep.variants"
# awk, not bc, which a minimal Debian lacks.
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
ratio() { awk "BEGIN { print $1 / $2 }"; }

# sweep OUT SIZE [NAME=VALUE...]: one sweep into a fresh OUT; appends its wall and CPU seconds
# to OUT.wall and OUT.cpu.
sweep() {
  local out=$1 size=$2
  shift 2
  rm -rf "$out"
  /usr/bin/time -f '%e %U %S' -o "$work/time" env "$@" "$exe" variants \
    iv_scenes/coloured_shadows.iv "$work/sweep.variants" -o "$out" --size "$size" \
    --jobs "$jobs" >/dev/null 2>&1
  read -r wall user system <"$work/time"
  echo "$wall" >>"$out.wall"
  awk "BEGIN { print $user + $system }" >>"$out.cpu"
}

printf 'cores %s, load %s, 100 variants of coloured_shadows.iv, 3 frames each, --jobs %s, ' \
  "$(nproc)" "$(cut -d' ' -f1-3 /proc/loadavg)" "$jobs"
printf 'medians of %s rounds\n' "$rounds"
printf '%-8s %18s %18s %10s %10s\n' size 'processes wall/cpu' 'workers wall/cpu' 'wall ratio' \
  'cpu ratio'
for size in 320x240 800x600; do
  rm -f "$work"/*.wall "$work"/*.cpu
  for _ in $(seq "$rounds"); do
    sweep "$work/p" "$size" IVSHADOW_VARIANTS_WORKERS=0
    sweep "$work/w" "$size"
  done
  for picture in "$work"/p/*.png; do
    cmp -s "$picture" "$work/w/$(basename "$picture")" || {
      echo "the two ways drew $(basename "$picture") differently" >&2
      exit 1
    }
  done
  pw=$(median <"$work/p.wall") pc=$(median <"$work/p.cpu")
  ww=$(median <"$work/w.wall") wc=$(median <"$work/w.cpu")
  printf '%-8s %8.2f /%7.2f s %8.2f /%7.2f s %10.2f %10.2f\n' "$size" "$pw" "$pc" "$ww" "$wc" \
    "$(ratio "$pw" "$ww")" "$(ratio "$pc" "$wc")"
done
printf 'load after %s\n' "$(cut -d' ' -f1-3 /proc/loadavg)"
