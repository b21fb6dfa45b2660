#!/usr/bin/env bash
# Regenerates the charts and tables of docs/TRADEOFF.md: every deep shadow setting of the
# bundled scenes, timed and compared with the exact reference. Run on an otherwise idle
# machine after ./run build; takes about twenty minutes on two cores with llvmpipe.
set -euo pipefail
cd "$(dirname "$0")/.."
for scene in coloured_shadows peeled_glasses chapel bottles; do
  build/bin/ivshadow trade "iv_scenes/$scene.iv" -o "docs/trade/$scene" --size 400x300 --frames 5 \
    --precision float --slices 2,8,32
done
