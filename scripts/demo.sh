#!/usr/bin/env bash
# Command A: install what is missing, build Release, run the main demo
# headless and write its frames and trajectory under out/demo/.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install-deps.sh
cmake --preset release -DKARMA_BUILD_TESTS=OFF >/dev/null
cmake --build --preset release --target karma_demo -j "$(nproc)"

out=out/demo
rm -rf "$out" && mkdir -p "$out"
build/release/tutorials/demo/karma_demo -frames 240 -out "$out" -trajectory "$out/trajectory.txt"
echo "demo: frames and trajectory written to $out/"
