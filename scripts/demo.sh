#!/usr/bin/env bash
# Command A: install what is missing, build Release, and render the whole
# QuadBike tutorial's scripted ride (tutorials/quadbike/README.md) headless:
# PNG frames, the trajectory and the video quadbike.mp4 (ffmpeg comes with
# the other packages; were it missing, the frames are still made), all under
# out/quadbike/. The render prints its progress (frame n of N, elapsed, to go).
#
# The ride is 8 s at 60 steps/s; every second frame is kept (241 frames at
# 640x480, 0 to 480), so the video plays at 30 frames/s in real time.
#
# The build folder and flags are those of scripts/test.sh's first
# configuration (build/release, warnings as errors, benchmarks on), so
# command B reuses everything built here instead of rebuilding it.
#
# The placeholder demo of the early project is still built and tested
# (tutorials/demo, golden/demo); `build/release/tutorials/demo/karma_demo
# -out DIR` runs it.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install-deps.sh
cmake --preset release -DKARMA_WARNINGS_AS_ERRORS=ON -DKARMA_BUILD_BENCH=ON >/dev/null
cmake --build --preset release --target quadbike -j "$(nproc)"

out=out/quadbike
rm -rf "$out" && mkdir -p "$out"
video=()
if command -v ffmpeg >/dev/null 2>&1; then
  video=(-video "$out/quadbike.mp4")
fi
build/release/tutorials/quadbike/quadbike -frames 481 -every 2 -size 640x480 -out "$out" \
  -trajectory "$out/trajectory.txt" "${video[@]}"

echo "demo: the QuadBike ride: $(ls "$out"/frame_*.png | wc -l) frames in $out/ (frame_00000.png ... frame_00480.png)"
echo "demo: its trajectory: $out/trajectory.txt"
if [ ${#video[@]} -gt 0 ] && [ -f "$out/quadbike.mp4" ]; then
  echo "demo: the video: $out/quadbike.mp4"
else
  echo "demo: no video (install ffmpeg for $out/quadbike.mp4)"
fi
