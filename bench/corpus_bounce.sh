#!/usr/bin/env bash
# One bounce over the corpus (docs/CORPUS.md, "One bounce"): renders each model the corpus
# test wrapped (build/test-output/InventorData.*/wrapped.iv, left by bench/corpus_table.sh or
# `ctest -R InventorData`) at 160 x 120 with its group's bounce TRUE (LIGHTS virtual point
# lights, default 256) and the reference of the same with 256 rays per point, and prints per
# model both exit statuses, the PSNR of the GL render against the reference with the bounce
# and without it (both paths, the same model: what the bounce adds to the error), and the
# warnings that named the bounce. BUILD_DIR as for ./run.
#   bench/corpus_bounce.sh > bounce.txt
#   bench/corpus_bounce.sh 64 > bounce64.txt
set -uo pipefail
cd "$(dirname "$0")/.."
lights=${1:-256}
build=${BUILD_DIR:-build}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
psnr() { "$build/bin/ivshadow" compare "$1" "$2" | awk '/^all/ {print $4}'; }
echo "model render_exit reference_exit psnr_bounce_db psnr_plain_db bounce_warnings"
for dir in "$build"/test-output/InventorData.*/; do
  wrapped=$dir/wrapped.iv
  [ -f "$wrapped" ] || continue
  model=$(basename "$dir")
  model=${model#InventorData.}
  on=(--set ShadowGroup.bounce=TRUE --set "ShadowGroup.bounceLights=$lights")
  timeout 300 "$build/bin/ivshadow" render "$wrapped" -o "$tmp/g.png" --size 160x120 \
    --set ShadowLight.method=RAYS "${on[@]}" >/dev/null 2>"$tmp/g.err"
  status=$?
  timeout 300 "$build/bin/ivshadow" reference "$wrapped" -o "$tmp/r.png" --size 160x120 \
    --bounce 256 "${on[@]}" >/dev/null 2>&1
  reference=$?
  bounce=- plain=-
  if [ "$status" = 0 ] && [ "$reference" = 0 ]; then
    bounce=$(psnr "$tmp/r.png" "$tmp/g.png")
    "$build/bin/ivshadow" render "$wrapped" -o "$tmp/g0.png" --size 160x120 \
      --set ShadowLight.method=RAYS >/dev/null 2>&1
    "$build/bin/ivshadow" reference "$wrapped" -o "$tmp/r0.png" --size 160x120 --bounce 0 \
      >/dev/null 2>&1
    plain=$(psnr "$tmp/r0.png" "$tmp/g0.png")
  fi
  echo "$model $status $reference $bounce $plain $(grep -ci "bounce" "$tmp/g.err")"
done
