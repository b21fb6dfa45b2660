#!/usr/bin/env bash
# The GPU kit as the lent machine gets it (issue 39, docs/GPU.md): packed from this build into
# an empty folder, unpacked there, its quick run on this machine's EGL (llvmpipe) from an
# environment with nothing set (no LD_LIBRARY_PATH, no build tree on the PATH) reports every
# test passed; and every library its files resolve, or a render through it loads, comes from
# the kit or from glibc, the C++ runtime and the GL driver (check_kit_libraries.py); without an
# EGL vendor it fails at once, in one line.
#   gpu_kit_test.sh SOURCE_DIR BUILD_DIR WORK_DIR
set -euo pipefail
source_dir=$1 build_dir=$2 work=$3
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work"
mkdir -p "$work"
# The fastest compression: this test checks the packing, not the archive's best size.
# Exit status 4: a checkout whose path is too short for the rewrite (under 6 characters); the
# test is skipped there (77, SKIP_RETURN_CODE) rather than failed.
status=0
GPU_KIT_XZ_LEVEL=1 BUILD_DIR=$build_dir "$source_dir/bench/gpu_kit.sh" pack "$work/kit" --no-build ||
  status=$?
[ "$status" -eq 4 ] && exit 77
[ "$status" -eq 0 ]
ls "$work/kit"
[ "$(ls "$work/kit" | sort | tr '\n' ' ')" = "ivshadow-gpu-kit.tar.xz run.sh " ]
status=0
env -i PATH=/usr/bin:/bin "$work/kit/run.sh" --quick "$work/report" || status=$?
cat "$work/report/summary.txt"
# One line of the report says how the tests went; a render of the demo came back.
grep -Eq '^total [0-9]+s; [1-9][0-9]* passed, 0 failed$' "$work/report/summary.txt"
grep -Eq '^GL renderer: .+' "$work/report/summary.txt"
[ -s "$work/report/demo.png" ] && [ -s "$work/report/tests.log" ] && [ -s "$work/report/benchmarks.json" ]
[ "$status" -eq 0 ]
# With no EGL vendor to be had it stops at once: exit status 3 and one line saying so.
status=0
env -i PATH=/usr/bin:/bin __EGL_VENDOR_LIBRARY_DIRS=/nonexistent "$work/kit/run.sh" --quick \
  "$work/no_egl" >"$work/no_egl.out" 2>"$work/no_egl.err" || status=$?
cat "$work/no_egl.err"
[ "$status" -eq 3 ] && [ "$(wc -l <"$work/no_egl.err")" -eq 1 ]
grep -q '^run.sh: no GL context through EGL' "$work/no_egl.err"
build_rel=$(sed -n 's/^build=//p' "$work/kit/ivshadow-gpu-kit/kit.env")
env -i PATH=/usr/bin:/bin python3 "$here/check_kit_libraries.py" "$work/kit/ivshadow-gpu-kit" \
  "$build_rel" "$work/kit/ivshadow-gpu-kit/iv_scenes/coloured_glasses.iv" "$work/glasses.png"
# The report stays for reading; the kit and its unpacked copy (about 170 MB) go.
rm -rf "$work/kit"
