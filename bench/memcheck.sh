#!/usr/bin/env bash
# valgrind memcheck over the paths the sanitizers cannot see into (Mesa's llvmpipe is not
# instrumented: an uninitialised value it hands the project reaches the project's code
# unnoticed by AddressSanitizer). Renders small scenes on each path of the release build (the
# default render, the map, the group traced whole, the reference)
# and fails on any error report outside the driver (tests/sanitizers/valgrind.supp). About
# ten minutes on two cores.
#   bench/memcheck.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
ivshadow=$build/bin/ivshadow
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
failed=0
check() {
  local name=$1
  shift
  if valgrind --error-exitcode=99 --track-origins=yes --num-callers=30 \
    --suppressions=tests/sanitizers/valgrind.supp "$@" >"$out/$name.log" 2>&1; then
    echo "$name: no errors"
  else
    local status=$?
    echo "$name: exit $status"
    grep -A30 "^==[0-9]*== [A-Z]" "$out/$name.log" | head -60 || true
    failed=1
  fi
}
scene=iv_scenes/coloured_shadows.iv
check default "$ivshadow" render "$scene" -o "$out/default.png" --size 64x48
check map "$ivshadow" render "$scene" -o "$out/map.png" --size 64x48 --set Lamp.method=MAP
check tracer "$ivshadow" render "$scene" -o "$out/tracer.png" --size 64x48 \
  --set Scene.renderer=TRACER
check reference "$ivshadow" reference "$scene" -o "$out/reference.png" --size 64x48
exit $failed
