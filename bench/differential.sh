#!/usr/bin/env bash
# The differential test in full (tests/gl/DifferentialTest.cpp, docs/AGREEMENT.md): every
# bundled scene, every corpus model the corpus test wrapped (run bench/corpus_table.sh or
# `ctest -R InventorData` first), and SCENES generated scenes (default 200), each drawn by
# every path of cli/MethodAgreement.h and by the reference. Prints the report (one line per
# scene and path: PSNR, share of pixels off by more than 2/255, and BELOW where a path fell
# under its floor without saying why) and exits non-zero when one did. CI runs 12 scenes.
#   bench/differential.sh [SCENES]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
IVSHADOW_DIFFERENTIAL_SCENES=${1:-200} \
  IVSHADOW_DIFFERENTIAL_CORPUS="$(pwd)/$build/test-output" \
  "$build/bin/gl_tests" --gtest_filter='Differential.*'
