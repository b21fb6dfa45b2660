#!/usr/bin/env bash
# The deep shadow map's two builds over the corpus (docs/CORPUS.md, "The map from fragment
# lists"): renders each model the corpus test wrapped (build/test-output/InventorData.*/
# wrapped.iv, left by `ctest -R InventorData`) with its light's method MAP, once as it is
# (the map from fragment lists) and once with IVSHADOW_FAIL_GL=list (the map peeled), at
# 160 x 120, and prints per model both exit statuses and the largest channel difference of
# the two pictures. The knob also makes the group's own transparency peel rather than list
# (docs/PEELING.md); further arguments go to both renders' --set (e.g.
# ShadowGroup.transparency=COIN_BLENDING leaves only the map's build to differ). Both renders
# truncate the surfaces past maxLayers (layerOverflow TRUNCATE), as a peeled map does: the
# lists' default, MERGE, differs from the peel wherever a texel has more. BUILD_DIR as for
# ./run.
#   bench/corpus_map_build.sh > map_build.txt
set -uo pipefail
cd "$(dirname "$0")/.."
sets=(--set "ShadowLight.layerOverflow=TRUNCATE")
for assignment in "$@"; do sets+=(--set "$assignment"); done
build=${BUILD_DIR:-build}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "model lists_exit peeled_exit largest_difference"
for dir in "$build"/test-output/InventorData.*/; do
  wrapped=$dir/wrapped.iv
  [ -f "$wrapped" ] || continue
  model=$(basename "$dir")
  model=${model#InventorData.}
  # A model whose light the wrapping did not name ShadowLight has no map to build.
  grep -q "DEF ShadowLight" "$wrapped" || continue
  timeout 300 "$build/bin/ivshadow" render "$wrapped" -o "$tmp/l.png" --size 160x120 \
    --set "ShadowLight.method=MAP" "${sets[@]}" >/dev/null 2>"$tmp/l.err"
  lists=$?
  IVSHADOW_FAIL_GL=list timeout 300 "$build/bin/ivshadow" render "$wrapped" -o "$tmp/p.png" \
    --size 160x120 --set "ShadowLight.method=MAP" "${sets[@]}" >/dev/null 2>"$tmp/p.err"
  peeled=$?
  difference=-
  if [ "$lists" = 0 ] && [ "$peeled" = 0 ]; then
    difference=$("$build/bin/ivshadow" compare "$tmp/p.png" "$tmp/l.png" |
      awk '/largest error/ {print $3}')
  fi
  echo "$model $lists $peeled $difference"
done
