#!/usr/bin/env bash
# renderer TRACER over the corpus (docs/CORPUS.md, "The group traced whole"): renders each
# model the corpus test wrapped (build/test-output/InventorData.*/wrapped.iv, left by
# bench/corpus_table.sh or `ctest -R InventorData`) with its group's renderer TRACER and with
# `ivshadow reference` at 160 x 120, and prints per model both exit statuses, the PSNR of the
# traced group against the reference, and how many warnings named renderer TRACER (shapes
# it draws through GL, which the reference does not draw). BUILD_DIR as for ./run.
#   bench/corpus_tracer.sh > tracer.txt
set -uo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "model tracer_exit reference_exit psnr_db tracer_warnings"
for dir in "$build"/test-output/InventorData.*/; do
  wrapped=$dir/wrapped.iv
  [ -f "$wrapped" ] || continue
  model=$(basename "$dir")
  model=${model#InventorData.}
  timeout 300 "$build/bin/ivshadow" render "$wrapped" -o "$tmp/t.png" --size 160x120 \
    --set ShadowGroup.renderer=TRACER >/dev/null 2>"$tmp/t.err"
  status=$?
  timeout 300 "$build/bin/ivshadow" reference "$wrapped" -o "$tmp/r.png" --size 160x120 \
    >/dev/null 2>&1
  reference=$?
  psnr=$("$build/bin/ivshadow" compare "$tmp/t.png" "$tmp/r.png" 2>/dev/null | awk '/^all/ {print $4}')
  echo "$model $status $reference ${psnr:--} $(grep -c 'renderer TRACER' "$tmp/t.err")"
done
