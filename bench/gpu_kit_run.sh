#!/usr/bin/env bash
# The GPU kit's runner (docs/GPU.md), packed beside ivshadow-gpu-kit.tar.xz by
# bench/gpu_kit.sh as run.sh:
#   run.sh [--quick] OUTDIR
# unpacks the kit next to itself (or into a temporary folder where that is read-only), prints
# the GL vendor, renderer and version, runs the GL tests (all of gl_tests, or with --quick a
# subset across the shadow methods, transparency and the tracer), the benchmarks behind
# docs/PERFORMANCE.md's goals and the demo render, and writes to OUTDIR summary.txt
# ("N passed, M failed", the GL strings, the benchmark medians and the goals' table of
# docs/PERFORMANCE.md where python3 is at hand), tests.log, benchmarks.json,
# demo.png, glasses.png and gl_stats.json. Nothing here needs the network or a package
# manager: it runs on a machine with glibc, libstdc++ and a GL driver alone. Exit status: 0
# when every test passed, 1 when some failed, 3 (one line on stderr) when no GL context can be
# had through EGL, 2 for a wrong call or a kit that cannot be unpacked.
set -uo pipefail
export LC_ALL=C

usage() {
  echo "usage: run.sh [--quick] OUTDIR" >&2
  exit 2
}
die() {
  echo "run.sh: $*" >&2
  exit 2
}
quick=0
[ "${1:-}" = --quick ] && { quick=1; shift; }
[ $# -eq 1 ] || usage
here=$(cd "$(dirname "$0")" && pwd -P)
mkdir -p "$1" || die "cannot make $1"
out=$(cd "$1" && pwd -P)
archive=$here/ivshadow-gpu-kit.tar.xz
[ -f "$archive" ] || die "no $archive beside run.sh"
started=$SECONDS

# Unpacked afresh each run, so a kit packed again never mixes with an older one.
if [ -w "$here" ]; then
  root=$here/ivshadow-gpu-kit
else
  root=$(mktemp -d)/ivshadow-gpu-kit
fi
rm -rf "$root"
mkdir -p "$root"
if command -v xz >/dev/null; then
  tar -C "$(dirname "$root")" -xJf "$archive" || die "cannot unpack $archive"
else
  # Images without xz-utils mostly have Python, whose lzma module reads it.
  python3 -c 'import sys, tarfile; tarfile.open(sys.argv[1]).extractall(sys.argv[2])' \
    "$archive" "$(dirname "$root")" || die "cannot unpack $archive: no xz and no python3"
fi
. "$root/kit.env"
bin=$root/$build/bin
lib=$root/$build/lib

# A library of the kit built against a newer glibc than this machine's is left out, so that
# the machine's own copy loads instead (Debian 12's libexpat needs glibc 2.36; Ubuntu 22.04
# has 2.35 and its own libexpat).
have_glibc=$(getconf GNU_LIBC_VERSION 2>/dev/null | awk '{print $2}')
if [ -n "$have_glibc" ]; then
  while read -r file needs; do
    newest=$(printf '%s\n%s\n' "${needs#GLIBC_}" "$have_glibc" | sort -V | tail -1)
    [ "$newest" = "$have_glibc" ] && continue
    case "$file" in
      lib/*) mkdir -p "$root/too_new" && mv "$lib/${file#lib/}" "$root/too_new/" &&
        echo "run.sh: warning: ${file#lib/} needs $needs, this machine has glibc" \
          "$have_glibc: using the machine's copy" >&2 ;;
      *) echo "run.sh: $file needs $needs, this machine has glibc $have_glibc:" \
           "the kit cannot run here" >&2
        exit 2 ;;
    esac
  done <"$root/glibc_needs.txt"
fi

# The test binaries read their scenes, the CLI and their output folder under $link (rewritten
# at packing from the source folder), which points at this unpacked kit. One run at a time.
if command -v flock >/dev/null; then
  exec 9>"$link.lock"
  flock -w 600 9 || die "another kit run holds $link.lock"
fi
if [ -e "$link" ] && [ ! -L "$link" ]; then
  die "$link exists and is not a link; the test binaries need that path"
fi
ln -sfn "$root" "$link" || die "cannot link $link to $root"
mkdir -p "$root/$build/test-output"

# The loader's cache, also where /sbin is not on the PATH (env -i, the device's shell).
ld_cache() {
  local tool
  for tool in ldconfig /sbin/ldconfig /usr/sbin/ldconfig; do
    command -v "$tool" >/dev/null && { "$tool" -p 2>/dev/null; return; }
  done
}

# libglvnd finds the vendor's EGL library through JSON files; NVIDIA's images keep theirs
# under /usr/local/nvidia, where Debian's libglvnd does not look.
if [ -z "${__EGL_VENDOR_LIBRARY_FILENAMES:-}${__EGL_VENDOR_LIBRARY_DIRS:-}" ]; then
  dirs=()
  for nvidia in /usr/local/nvidia/lib64 /usr/local/nvidia/lib; do
    # Named by its path where the loader's cache does not know it.
    if [ -f "$nvidia/libEGL_nvidia.so.0" ] &&
       ! ld_cache | grep libEGL_nvidia.so.0 >/dev/null; then
      mkdir -p "$root/egl_vendor.d"
      printf '{"file_format_version": "1.0.0", "ICD": {"library_path": "%s"}}\n' \
        "$nvidia/libEGL_nvidia.so.0" >"$root/egl_vendor.d/10_nvidia.json"
      dirs+=("$root/egl_vendor.d")
      break
    fi
  done
  for dir in /usr/local/nvidia/share/glvnd/egl_vendor.d /etc/glvnd/egl_vendor.d \
             /usr/share/glvnd/egl_vendor.d /usr/local/share/glvnd/egl_vendor.d; do
    [ -d "$dir" ] && dirs+=("$dir")
  done
  if [ ${#dirs[@]} -eq 0 ]; then
    echo "run.sh: no EGL vendor library: no glvnd egl_vendor.d folder on this machine" >&2
    exit 3
  fi
  __EGL_VENDOR_LIBRARY_DIRS=$(IFS=:; echo "${dirs[*]}")
  export __EGL_VENDOR_LIBRARY_DIRS
fi

summary=$out/summary.txt
log=$out/tests.log
: >"$log"
say() { echo "$*" | tee -a "$summary"; }
: >"$summary"

# The GL strings: the CLI's statistics name the renderer and version; the vendor comes from
# a small EGL probe through the kit's own libEGL where Python is at hand.
probe_err=$(mktemp)
if ! "$bin/ivshadow" render "$root/iv_scenes/lit_plane.iv" -o "$out/probe.png" --size 16x16 \
     --stats "$out/gl_stats.json" >/dev/null 2>"$probe_err"; then
  line="run.sh: no GL context through EGL on this machine: $(head -1 "$probe_err")"
  echo "$line" >&2
  # What the one call on a lent machine brings back must say why: the vendor files libglvnd
  # read, the libraries they name and whether the loader knows them, the GPUs the machine has.
  {
    echo "$line"
    echo "__EGL_VENDOR_LIBRARY_DIRS=${__EGL_VENDOR_LIBRARY_DIRS:-}"
    echo "__EGL_VENDOR_LIBRARY_FILENAMES=${__EGL_VENDOR_LIBRARY_FILENAMES:-}"
    for dir in ${__EGL_VENDOR_LIBRARY_DIRS//:/ }; do
      for json in "$dir"/*.json; do
        [ -f "$json" ] || continue
        library=$(sed -n 's/.*"library_path" *: *"\([^"]*\)".*/\1/p' "$json")
        echo "$json: $library: $(ld_cache | grep -F "${library##*/}" | head -1 |
          sed 's/.*=> //')"
      done
    done
    ls -l /dev/nvidia* /dev/dri 2>&1
    command -v nvidia-smi >/dev/null && nvidia-smi -L 2>&1
    cat "$probe_err"
  } >"$summary"
  exit 3
fi
rm -f "$out/probe.png"
stat_field() { sed -n "s/^ *\"$1\": \"\(.*\)\",\{0,1\}$/\1/p" "$out/gl_stats.json" | head -1; }
vendor=unknown
if command -v python3 >/dev/null; then
  vendor=$(python3 "$root/gl_vendor.py" "$lib" "$(stat_field egl_platform)" 2>/dev/null) ||
    vendor=unknown
fi
mode=full
[ $quick = 1 ] && mode=quick
say "ivshadow GPU kit $commit (packed $packed), $mode run on $(uname -n)," \
  "$(date -u +%Y-%m-%dT%H:%M:%SZ)"
say "GL vendor: $vendor"
say "GL renderer: $(stat_field gl_renderer)"
say "GL version: $(stat_field gl_version)"
say "EGL platform: $(stat_field egl_platform)"
if { [ -e /dev/nvidia0 ] || [ -e /dev/dri/renderD128 ]; } &&
   stat_field gl_renderer | grep -q llvmpipe; then
  say "warning: a GPU is present but GL runs on llvmpipe"
fi

# The tests, one process per test as CTest runs them (gtest_discover_tests): some tests count
# messages that Coin or the plugin say once per process. A test that never reported OK or
# SKIPPED (its process crashed or hung past 5 minutes) counts as failed.
if [ $quick = 1 ]; then
  filter='DeepShadow.*:Cases/DeepShadowAnalytic.*:ShadowVolumes.*:RayShadows.*'
  filter+=':Methods/ScreenShadows.*:MapFragmentListsGLTest.*:ImperfectShadowMapsGLTest.*'
  filter+=':GroupPeeling.*:Cases/OpacityMapAnalytic.*:TracedGroup.*:Cases/TracedGroupAnalytic.*'
  filter+=':LightTypesMap.*:GlContextGLTest.*:PassInstrumentsGLTest.*:ShadingVariantsGLTest.*'
  filter+=':HeadlessRendering.*:RenderCommand.*:Examples.*:GlFault.*:UniformLocationsGLTest.*'
  filter+=':PerContextGLTest.*:ShadowGroupElementGLTest.*:CoinShadowGroupAgreement.*:KeptFrame.*'
else
  filter='*'
fi
jobs=$(nproc 2>/dev/null || echo 2)
[ "$jobs" -gt 8 ] && jobs=8
results=$(mktemp -d)
"$bin/gl_tests" --gtest_list_tests --gtest_filter="$filter" |
  awk '/^[^ ]/ && !/^Running main/ {suite = $1} /^  / {print suite $1}' >"$results/tests"
run_test() {
  local test=$1 name
  name=$(echo "$test" | tr '/.' '__')
  timeout 300 "$KIT_BIN/gl_tests" --gtest_filter="$test" --gtest_color=no \
    >"$KIT_RESULTS/$name.log" 2>&1
  if grep -q '^\[       OK \]' "$KIT_RESULTS/$name.log"; then
    echo passed >"$KIT_RESULTS/$name.result"
  elif grep -qE '^\[  SKIPPED \] .* \([0-9]+ ms\)$' "$KIT_RESULTS/$name.log"; then
    echo skipped >"$KIT_RESULTS/$name.result"
  else
    echo failed >"$KIT_RESULTS/$name.result"
  fi
  # Into the report as each test ends, so that a run cut off by the caller's time limit still
  # brings back the tests it finished.
  { flock 8 2>/dev/null
    echo "===== $test: $(cat "$KIT_RESULTS/$name.result")" >>"$KIT_LOG"
    cat "$KIT_RESULTS/$name.log" >>"$KIT_LOG"
  } 8>>"$KIT_LOG"
}
export -f run_test
tests_started=$SECONDS
KIT_BIN=$bin KIT_RESULTS=$results KIT_LOG=$log \
  xargs -P "$jobs" -L 1 bash -c 'run_test "$0"' <"$results/tests"
tests_seconds=$((SECONDS - tests_started))
passed=0 failed=0 skipped=0
failed_tests=()
while read -r test; do
  name=$(echo "$test" | tr '/.' '__')
  case "$(cat "$results/$name.result" 2>/dev/null)" in
    passed) passed=$((passed + 1)) ;;
    skipped) skipped=$((skipped + 1)) ;;
    *) failed=$((failed + 1)); failed_tests+=("$test") ;;
  esac
done <"$results/tests"
say "gl_tests ($((passed + failed + skipped)) tests, ${tests_seconds} s, $jobs at a time):" \
  "$passed passed, $failed failed, $skipped skipped"
for test in "${failed_tests[@]}"; do say "  failed: $test"; done

# The benchmarks behind docs/PERFORMANCE.md's goals (bench/performance_docs.sh's filters),
# medians of 3 repetitions; --quick times one repetition each, enough to see them run.
bench_started=$SECONDS
repetitions=3
[ $quick = 1 ] && repetitions=1
{
  echo "{"
  first=1
  while read -r name filter; do
    [ $first = 1 ] || echo ","
    first=0
    echo "\"$name\":"
    "$bin/ivshadow_bench" --benchmark_filter="$filter" --benchmark_repetitions=$repetitions \
      --benchmark_report_aggregates_only=true --benchmark_format=json 2>>"$log" || echo '{}'
  done <"$root/bench_filters.txt"
  echo "}"
} >"$out/benchmarks.json"
how="median of $repetitions"
[ $repetitions = 1 ] && how="one repetition"
say "benchmarks ($((SECONDS - bench_started)) s; real time, $how):"
awk '/"name":/ {gsub(/[",]/, "", $2); n = $2}
     /"real_time":/ {gsub(/,/, "", $2); t = $2}
     /"time_unit":/ {gsub(/[",]/, "", $2)
                     if (n !~ /_(mean|stddev|cv)$/) printf "  %-60s %12.3f %s\n", n, t, $2}' \
  "$out/benchmarks.json" | tee -a "$summary"
if command -v python3 >/dev/null; then
  say "goals (docs/PERFORMANCE.md's table, less the sweeps, the viewer's drag and the cold start):"
  python3 "$root/goals.py" "$out/benchmarks.json" 2>&1 | tee -a "$summary"
fi

# Whole frames of the CLI at both sizes the issue names, up to 1M triangles (full runs only):
# medians of 10 frames, each scene's groups as the file has them (AUTO).
if [ $quick = 0 ]; then
  say "frames (ivshadow render --frames 10, a still camera: the first frame, then the medians of"
  say "all 10 frames and of their GPU time, which kept frames bring down; what AUTO picked):"
  for scene in coloured_shadows stress_100k stress_1m; do
    for size in 800x600 1920x1080; do
      stats=$(mktemp)
      if "$bin/ivshadow" render "$root/iv_scenes/$scene.iv" -o "$stats.png" --size $size \
           --frames 10 --stats "$stats" >"$stats.log" 2>&1; then
        picked=$(grep -o 'uses [A-Z_]*' "$stats.log" | sort -u | tr '\n' ' ')
        say "$(awk -v scene=$scene -v size=$size -v picked="$picked" '
          /"frame_ms": \[/ {list = 1; next}
          list && /\]/ {list = 0}
          list && first == "" {first = $1; sub(/,/, "", first)}
          /"frame_ms_median"/ {gsub(/,/, "", $2); f = $2}
          /"gpu_ms_median"/ {gsub(/,/, "", $2); g = $2}
          END {printf "  %-18s %-10s %9.2f ms %9.2f ms %9.2f ms  %s",
                      scene, size, first, f, g, picked}' "$stats")"
      else
        say "  $scene $size: the render failed (see tests.log)"
      fi
      cat "$stats.log" >>"$log"
      rm -f "$stats" "$stats.png" "$stats.log"
    done
  done
fi

# The pictures: the demo as ./run demo renders it, and the glasses through exact transparency.
"$bin/ivshadow" render "$root/iv_scenes/coloured_shadows.iv" -o "$out/demo.png" --size 800x600 \
  >>"$log" 2>&1 || say "warning: the demo render failed (see tests.log)"
"$bin/ivshadow" render "$root/iv_scenes/coloured_glasses.iv" -o "$out/glasses.png" \
  --size 800x600 >>"$log" 2>&1 || say "warning: the glasses render failed (see tests.log)"
say "total ${SECONDS}s; $passed passed, $failed failed"
rm -rf "$results" "$probe_err"
[ "$failed" -eq 0 ]
