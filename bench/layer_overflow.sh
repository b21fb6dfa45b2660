#!/usr/bin/env bash
# The deep shadow map's two ways with surfaces past maxLayers (docs/DEEP_SHADOWS.md,
# "Surfaces past maxLayers"): renders each bundled scene's first DeepShadowLight with method
# MAP at maxLayers 1, 2 and 4, merged (layerOverflow MERGE) and truncated, at 400 x 300, and
# prints per setting the PSNR against `ivshadow reference` of the same scene and size, the
# texels merged and the largest error left (the --stats figures). BUILD_DIR as for ./run.
#   bench/layer_overflow.sh > layer_overflow.txt
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "scene light maxLayers layerOverflow psnr_db merged_texels merge_error"
for scene in coloured_shadows peeled_glasses chapel bottles atrium; do
  file=iv_scenes/$scene.iv
  light=$(sed -n 's/.*DEF \([A-Za-z_0-9]*\) DeepShadowLight.*/\1/p' "$file" | head -1)
  "$build/bin/ivshadow" reference "$file" -o "$tmp/reference.png" --size 400x300 >/dev/null
  for layers in 1 2 4; do
    for overflow in MERGE TRUNCATE; do
      "$build/bin/ivshadow" render "$file" -o "$tmp/map.png" --size 400x300 \
        --set "$light.method=MAP" --set "$light.maxLayers=$layers" \
        --set "$light.layerOverflow=$overflow" --stats "$tmp/stats.json" >/dev/null 2>&1
      psnr=$("$build/bin/ivshadow" compare "$tmp/reference.png" "$tmp/map.png" |
        awk '$1 == "all" {print $4}')
      merged=$(python3 -c "import json, sys; l = json.load(open(sys.argv[1]))['dsm_layers_used']
l = [x for x in l if x['light'] == sys.argv[2]][0]
print(l['merged_texels'], round(l['merge_error'], 4))" "$tmp/stats.json" "$light")
      echo "$scene $light $layers $overflow $psnr $merged"
    done
  done
done
