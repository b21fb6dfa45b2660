#!/usr/bin/env bash
# Builds the libFuzzer harnesses (fuzz/, clang, AddressSanitizer + UBSan) in build-fuzz/ and
# runs each for up to SECONDS (default 60; a finding stops it sooner) on one core, seeded from
# the bundled scenes, malformed files, variants files and images. Prints a Markdown table
# (seconds run, runs, findings) and writes its rows into docs/RELIABILITY.md's table between
# the "fuzz table" markers (the rows of harnesses not run stay). This run's findings (crash-*, leak-*, oom-*, timeout-* files) are kept in
# build-fuzz/findings/HARNESS/; fix each and add it to the tests as a regression case.
#   bench/fuzz.sh [SECONDS [HARNESS...]]   (every harness when none is named)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
build=build-fuzz
if [ ! -f "$build/CMakeCache.txt" ]; then
  CXX=clang++ CC=clang cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DIVSHADOW_FUZZ=ON \
    -DBUILD_TESTING=OFF >/dev/null
fi
all=(SceneReaderFuzzer SceneRenderFuzzer FieldAssignmentFuzzer VariantsFileFuzzer ImageReaderFuzzer
     CommandLineFuzzer)
harnesses=("${@:2}")
[ ${#harnesses[@]} -eq 0 ] && harnesses=("${all[@]}")
for harness in "${harnesses[@]}"; do
  [[ " ${all[*]} " == *" $harness "* ]] || { echo "no harness $harness: ${all[*]}" >&2; exit 2; }
done
cmake --build "$build" -j "$(nproc)" --target "${harnesses[@]}" >/dev/null

seed() {
  local harness=$1 dir=$2
  rm -rf "$dir" && mkdir -p "$dir"
  case "$harness" in
    SceneReaderFuzzer|SceneRenderFuzzer)
      cp iv_scenes/*.iv iv_scenes/malformed/*.iv tests/loader/*.iv fuzz/seeds/*.iv "$dir"/
      # The stress scenes are large and say nothing the small ones do not.
      rm -f "$dir"/stress_*.iv ;;
    FieldAssignmentFuzzer)
      local i=0
      for text in "Lamp.resolution=512" "Lamp.location=0 0 4" "Lamp.method=RAYS" \
                  "Lamp.maxLayers=64" "Lamp.colorModel=POWER" "Lamp.bias=0.001" \
                  "Group.isActive=FALSE" "Peel.maxPasses=8" "Glass.transparency=[0.5, 1]" \
                  "Lamp.color=1 0 0"; do
        printf '%s' "$text" >"$dir/seed$((i++))"
      done ;;
    CommandLineFuzzer)
      # One argument per line, in the scratch folder's names (fuzz/CommandLineFuzzer.cpp).
      local i=0
      for line in "render a.iv -o out.png --size 32x24" \
                  "render a.iv -o a.iv --size 8x8" \
                  "render a.iv -o out.jpg --stats out.jpg --size 8x8" \
                  "render a.iv -o out.png --size 16x16 --set Lamp.method=MAP --frames 2" \
                  "render a.iv -o out.png --size 16x16 --set Glass.transparency=1e39" \
                  "reference a.iv -o ref.png --pfm ref.pfm --size 16x12 --bounce 1" \
                  "compare b.png c.png --diff c.png --json d.json" \
                  "compare b.png c.png --diff diff.jpg --scale 4" \
                  "variants-merge --status sweep" "view a.iv --screenshot a.png" \
                  "trade a.iv -o t --layers 1,2 --method map,tracer" \
                  "variants a.iv v.variants -o out --shard 1/3 --list"; do
        local name=$dir/seed$((i++))
        printf '%s' "$line" | tr ' ' '\n' >"$name"
      done ;;
    VariantsFileFuzzer)
      cp iv_scenes/*.variants tests/variants/*.variants "$dir"/ ;;
    ImageReaderFuzzer)
      local i=0
      for png in docs/trade/*/*.png; do
        { printf '\001'; cat "$png"; } >"$dir/png$((i++))"
      done
      { printf '\000PF\n2 1\n-1.0\n'; head -c 24 /dev/zero; } >"$dir/pfm0" ;;
  esac
}

export ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1
# SceneRenderFuzzer's differential oracle (docs/AGREEMENT.md's floors); 0 turns it off.
export IVSHADOW_FUZZ_ORACLE=${IVSHADOW_FUZZ_ORACLE-1}
export LSAN_OPTIONS=suppressions=$PWD/tests/sanitizers/lsan.supp:print_suppressions=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1:suppressions=$PWD/tests/sanitizers/ubsan.supp
table="| harness | seconds | runs | findings |
|---|---|---|---|"
for harness in "${harnesses[@]}"; do
  # Absolute: CommandLineFuzzer works in a scratch folder of its own.
  corpus=$PWD/$build/corpus/$harness findings=$PWD/$build/findings/$harness
  seed "$harness" "$corpus"
  # The last run's findings move aside (findings/HARNESS.previous), kept until the next run.
  rm -rf "$findings.previous"
  [ -d "$findings" ] && mv "$findings" "$findings.previous"
  mkdir -p "$findings"
  log=$build/$harness.log
  began=$(date +%s)
  "$build/bin/$harness" "$corpus" -max_total_time="$seconds" -rss_limit_mb=4096 -timeout=20 \
    -artifact_prefix="$findings/" -print_final_stats=1 >"$log" 2>&1 || true
  # A finding stops the harness early: the table says how long it really ran.
  ran=$(( $(date +%s) - began ))
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  found=$(find "$findings" -type f | wc -l)
  table+=$'\n'"| $harness | $ran | ${runs:-0} | $found |"
  echo "$harness: ${runs:-0} runs in $ran s, $found findings ($log)" >&2
done
echo "$table"
python3 - "$table" "${all[@]}" <<'PY'
import re, sys
path = "docs/RELIABILITY.md"
text = open(path).read()
table, order = sys.argv[1], sys.argv[2:]
start, end = "<!-- fuzz table -->\n", "\n<!-- /fuzz table -->"
old = text[text.index(start) + len(start):text.index(end)]
def rows(block):
    return {line.split("|")[1].strip(): line for line in block.splitlines()
            if line.startswith("| ") and not line.startswith("| harness")}
merged = {**rows(old), **rows(table)}
lines = table.splitlines()[:2] + [merged[name] for name in order if name in merged]
text = text.replace(start + old + end, start + "\n".join(lines) + end)
open(path, "w").write(text)
PY
