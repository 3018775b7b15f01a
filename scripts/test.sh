#!/usr/bin/env bash
# Command B: install what is missing, then build and run every test.
#
#   1. Release, single precision (the default MeReal): every test, warnings
#      are errors; the benchmarks are compiled too.
#   2. Release, double precision: every test, warnings are errors.
#   3. ASan + UBSan with the check build's validation: every test.
#
# KARMA_TEST_CONFIGS="release double asan" selects which of the three run.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install-deps.sh

configs=${KARMA_TEST_CONFIGS:-"release double asan"}
jobs=$(nproc)
start=$SECONDS
for preset in $configs; do
  echo "=== $preset: configure and build"
  t0=$SECONDS
  extra=()
  [ "$preset" = asan ] || extra=(-DKARMA_WARNINGS_AS_ERRORS=ON)
  # The benchmarks are built (not run) once, so they cannot rot unnoticed.
  [ "$preset" = release ] && extra+=(-DKARMA_BUILD_BENCH=ON)
  cmake --preset "$preset" "${extra[@]}" >/dev/null
  cmake --build --preset "$preset" -j "$jobs"
  echo "=== $preset: test"
  ctest --preset "$preset" -j "$jobs"
  echo "=== $preset: done in $((SECONDS - t0)) s"
done
echo "=== all configurations passed ($configs) in $((SECONDS - start)) s"
