#!/usr/bin/env bash
# window_test.sh PROGRAM KARMA_GOLDEN WORKDIR: the -window backend on a real
# X server (Xvfb, started here by xvfb-run on a free display number and
# stopped when the test ends).
#
#   1. PROGRAM (window_drive) opens a 320x240 window and records its input
#      (-record); xdotool sends it synthetic X events: the pointer moves in,
#      a left-button drag turns the camera, Right is pressed twice, Up once,
#      Space once, then Escape quits. At exit the program saves the window
#      as the X server shows it (-screenshot, XGetImage).
#   2. The recorded key script is replayed offscreen (-gl -keyfile) and the
#      last frame written; it must equal the screenshot pixel for pixel
#      (karma-golden compare-image --channel-tol 0 --max-fraction 0): the
#      window shows the offscreen frames, and live input reaches the same
#      callbacks, at the same frames, as a key script.
#   3. The record must hold the events sent, so the comparison is not of two
#      untouched scenes.
# Exit 77 (CTest: skipped) only when xvfb-run or xdotool is missing.
set -euo pipefail
program=$1 golden=$2 work=$3

if [ "${WINDOW_TEST_INSIDE:-}" != 1 ]; then
  for tool in xvfb-run xdotool xauth; do
    if ! command -v "$tool" >/dev/null 2>&1; then
      echo "SKIPPED: $tool is not installed (scripts/install-deps.sh installs xvfb, xauth and xdotool)"
      exit 77
    fi
  done
  rm -rf "$work" && mkdir -p "$work"
  export WINDOW_TEST_INSIDE=1
  # -a: the first free display number; the server dies with the command.
  exec xvfb-run -a -e "$work/xvfb.log" -s "-screen 0 640x480x24 -nolisten tcp" bash "$0" "$@"
fi

cd "$work"
"$program" -window -size 320x240 -record live.keys -screenshot window.png > program.log 2>&1 &
pid=$!
trap 'kill "$pid" 2>/dev/null || true' EXIT
wid=$(timeout 20 xdotool search --sync --onlyvisible --name '^window_drive$' | head -n 1)
echo "window $wid on display $DISPLAY"
xdotool mousemove --window "$wid" 40 120          # the pointer gives the keyboard focus (no window manager)
sleep 0.3
xdotool mousedown 1 mousemove --window "$wid" 90 120 mouseup 1
sleep 0.2
xdotool key --delay 150 Right Right Up space
sleep 0.3
xdotool key Escape
timeout 20 tail --pid="$pid" -f /dev/null
wait "$pid"
trap - EXIT
cat program.log

echo "--- recorded input (live.keys)"
cat live.keys
for want in "press Right" "release Right" "press Up" "press Space" "mouse 90,120,1" "press Escape"; do
  grep -q ":$want\$" live.keys || { echo "FAIL: the record lacks '$want'"; exit 1; }
done
[ "$(grep -c ':press Right$' live.keys)" -eq 2 ] || { echo "FAIL: Right was pressed twice"; exit 1; }
last=$(grep ':press Escape$' live.keys | cut -d: -f1)
echo "the window quit in frame $last"

"$program" -gl -size 320x240 -keyfile live.keys -out offscreen > replay.log 2>&1 || { cat replay.log; exit 1; }
frame=$(printf 'offscreen/frame_%05d.png' "$last")
[ -f "$frame" ] || { echo "FAIL: the replay did not end at frame $last"; ls offscreen | tail -3; exit 1; }
"$golden" compare-image "$frame" window.png --channel-tol 0 --max-fraction 0 --diff window.diff.png
echo "window screenshot equals the offscreen frame $last"
