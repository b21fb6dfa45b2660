#!/usr/bin/env bash
# Soak: FRAMES frames (default 10000) of coloured_shadows.iv with MAP and with RAYS and of
# peeled_glasses.iv (peeling with shadows), the light moving every frame so that each frame
# rebuilds its map or traces again, and 200 GL context create/destroy cycles; resident memory
# sampled 100 times per run. Prints a Markdown table (first and last RSS, slope over the
# second half) and writes it into docs/RELIABILITY.md between its "soak table" markers.
# Run after ./run build on an otherwise idle machine. IVSHADOW_SOAK names another
# ivshadow_soak (a copy of the build, so that rebuilding meanwhile leaves the run alone);
# SOAK_SAMPLES=DIR keeps each run's samples there as JSON.
#   bench/soak.sh [FRAMES]
set -euo pipefail
cd "$(dirname "$0")/.."
frames=${1:-10000}
soak=${IVSHADOW_SOAK:-build/bin/ivshadow_soak}
samples=${SOAK_SAMPLES:-}
table="| run | frames or cycles | RSS first (MiB) | RSS last (MiB) | slope, second half (KiB per 1,000) |
|---|---|---|---|---|"
row() {
  local name=$1 count=$2
  shift 2
  local json
  json=$("$soak" "$@" 2>/dev/null)
  if [ -n "$samples" ]; then
    mkdir -p "$samples"
    echo "$json" >"$samples/$(echo "$name" | tr -c 'A-Za-z0-9\n' _).json"
  fi
  table+=$'\n'$(python3 -c '
import json, sys
d = json.loads(sys.argv[1])
print("| %s | %s | %.1f | %.1f | %.0f |" % (sys.argv[2], sys.argv[3], d["rss_kib_first"] / 1024,
      d["rss_kib_last"] / 1024, d["slope_kib_per_1000"]))' "$json" "$name" "$count")
  echo "$name done" >&2
}
row "MAP, light moving" "$frames" iv_scenes/coloured_shadows.iv --frames "$frames" --move Lamp \
  --set Lamp.method=MAP --set Lamp.resolution=128
row "RAYS, light moving" "$frames" iv_scenes/coloured_shadows.iv --frames "$frames" --move Lamp \
  --set Lamp.method=RAYS
row "peeling + RAYS, light moving" "$frames" iv_scenes/peeled_glasses.iv --frames "$frames" \
  --move Lamp
row "GL contexts created and destroyed" 200 --contexts 200
echo "$table"
python3 - "$table" <<'PY'
import re, sys
path = "docs/RELIABILITY.md"
text = open(path).read()
new = re.sub(r"(<!-- soak table -->\n).*?(\n<!-- /soak table -->)",
             lambda m: m.group(1) + sys.argv[1] + m.group(2), text, flags=re.S)
open(path, "w").write(new)
PY
