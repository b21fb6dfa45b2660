#!/usr/bin/env bash
# The viewer's frame rate while the light is dragged (docs/PERFORMANCE.md, "The viewer while
# the light is dragged"): opens iv_scenes/stress_100k.iv (96.8k triangles) at 800 x 600 on
# a virtual X server (xvfb-run; Mesa's llvmpipe draws), drags the light STEPS steps (default
# 30) with `--drag-light`, and prints frames per second and the median frame for plain Coin
# (the group inactive), renderer RASTER, renderer TRACER and TRACER with movingResolution
# 0.5, in one run. BUILD_DIR as for ./run.
#   bench/viewer_drag.sh > drag.txt
set -uo pipefail
cd "$(dirname "$0")/.."
steps=${1:-30}
build=${BUILD_DIR:-build}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "setting frames_per_second frame_ms_median frames_after_drag"
for setting in "Stress.isActive=FALSE" "Stress.renderer=RASTER" "Stress.renderer=TRACER" \
  "Stress.renderer=TRACER Stress.movingResolution=0.5"; do
  sets=()
  for assignment in $setting; do sets+=(--set "$assignment"); done
  rm -f "$tmp/figures.json"
  xvfb-run -a -s "-screen 0 1280x1024x24" "$build/bin/ivshadow-viewer" iv_scenes/stress_100k.iv \
    --screenshot "$tmp/shot.png" --figures "$tmp/figures.json" --size 800x600 "${sets[@]}" \
    --drag-light "$steps" >/dev/null 2>"$tmp/err"
  if [ ! -f "$tmp/figures.json" ]; then
    echo "\"$setting\" failed: $(head -c 300 "$tmp/err")"
    continue
  fi
  python3 -c 'import json, sys
d = json.load(open(sys.argv[1]))["drag"]
print("\"%s\" %.1f %.1f %d" % (sys.argv[2], d["frames_per_second"], d["frame_ms_median"], d["frames_after"]))' \
    "$tmp/figures.json" "$setting"
done
