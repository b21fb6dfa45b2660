#!/usr/bin/env bash
# One shadow method over the corpus (docs/CORPUS.md, "The shadow volumes", "The opacity
# maps"): renders each model the corpus test wrapped (build/test-output/InventorData.*/
# wrapped.iv, left by bench/corpus_table.sh or `ctest -R InventorData`) with its light's
# method METHOD (VOLUMES, OPACITY_MAP, MAP) and with RAYS at 160 x 120, and prints per model
# both exit statuses, the PSNR of METHOD against RAYS (the exact method: what differs is
# METHOD's error) and how many warnings named the method (the volumes' averaged colours).
# Further arguments go to both renders' --set (e.g. ShadowLight.slices=16). BUILD_DIR as for
# ./run.
#   bench/corpus_method.sh VOLUMES > volumes.txt
#   bench/corpus_method.sh OPACITY_MAP ShadowLight.slices=16 > opacity.txt
set -uo pipefail
cd "$(dirname "$0")/.."
method=${1:?usage: bench/corpus_method.sh METHOD [NAME.field=VALUE ...]}
shift
sets=()
for assignment in "$@"; do sets+=(--set "$assignment"); done
build=${BUILD_DIR:-build}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "model method_exit rays_exit psnr_db method_warnings"
for dir in "$build"/test-output/InventorData.*/; do
  wrapped=$dir/wrapped.iv
  [ -f "$wrapped" ] || continue
  model=$(basename "$dir")
  model=${model#InventorData.}
  timeout 300 "$build/bin/ivshadow" render "$wrapped" -o "$tmp/m.png" --size 160x120 \
    --set "ShadowLight.method=$method" "${sets[@]}" >/dev/null 2>"$tmp/m.err"
  status=$?
  timeout 300 "$build/bin/ivshadow" render "$wrapped" -o "$tmp/r.png" --size 160x120 \
    --set ShadowLight.method=RAYS >/dev/null 2>&1
  rays=$?
  psnr=-
  if [ "$status" = 0 ] && [ "$rays" = 0 ]; then
    psnr=$("$build/bin/ivshadow" compare "$tmp/r.png" "$tmp/m.png" | awk '/^all/ {print $4}')
  fi
  echo "$model $status $rays $psnr $(grep -c "method $method" "$tmp/m.err")"
done
