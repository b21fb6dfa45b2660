#!/usr/bin/env bash
# The shadow volumes over the corpus (docs/CORPUS.md, "The shadow volumes"): renders each
# model the corpus test wrapped (build/test-output/InventorData.*/wrapped.iv, left by
# bench/corpus_table.sh or `ctest -R InventorData`) with its light's method VOLUMES and with
# RAYS at 160 x 120, and prints per model both exit statuses, the PSNR of VOLUMES against
# RAYS (two exact methods: what differs is the volumes' error) and whether the volumes warned
# of casters whose colour they average. BUILD_DIR as for ./run.
#   bench/corpus_volumes.sh > volumes.txt
set -uo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "model volumes_exit rays_exit psnr_db averaged_warning"
for dir in "$build"/test-output/InventorData.*/; do
  wrapped=$dir/wrapped.iv
  [ -f "$wrapped" ] || continue
  model=$(basename "$dir")
  model=${model#InventorData.}
  timeout 300 "$build/bin/ivshadow" render "$wrapped" -o "$tmp/v.png" --size 160x120 \
    --set ShadowLight.method=VOLUMES >/dev/null 2>"$tmp/v.err"
  volumes=$?
  timeout 300 "$build/bin/ivshadow" render "$wrapped" -o "$tmp/r.png" --size 160x120 \
    --set ShadowLight.method=RAYS >/dev/null 2>&1
  rays=$?
  psnr=-
  if [ "$volumes" = 0 ] && [ "$rays" = 0 ]; then
    psnr=$("$build/bin/ivshadow" compare "$tmp/r.png" "$tmp/v.png" | awk '/^all/ {print $4}')
  fi
  echo "$model $volumes $rays $psnr $(grep -c 'method VOLUMES' "$tmp/v.err")"
done
