#!/usr/bin/env bash
# Installs the Debian 12 packages Karma needs to build, test and render, if
# any are missing. Safe to run again: it does nothing when all are present.
# apt's output goes to a log file; the script prints one line saying what
# it installs, and the log's end only if apt fails.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git   # toolchain
  libeigen3-dev libccd-dev libqhull-dev              # maths, convex collision, hulls
  libosmesa6-dev                                     # offscreen OpenGL (MeViewer)
  libsdl2-dev                                        # MeViewer's window (-window)
  libstb-dev                                         # PNG/BMP read and write
  ffmpeg                                             # videos (-video)
  gnuplot-nox                                        # karma-tradeoff's plots (docs/ACCURACY.md)
  libgtest-dev libgmock-dev libbenchmark-dev         # tests and benchmarks
  xvfb xauth xdotool                                 # the window test: X server, synthetic input
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then SUDO=sudo; else
    echo "install-deps: need root to install: ${missing[*]}" >&2; exit 1
  fi
else
  SUDO=""
fi
log=$(mktemp /tmp/karma-install-deps.XXXXXX.log)
echo "install-deps: installing ${#missing[@]} Debian packages and what they need" \
     "(compilers, CMake, maths, OpenGL, SDL2, ffmpeg, test tools): ${missing[*]}; apt's log: $log"
export DEBIAN_FRONTEND=noninteractive
if ! { $SUDO apt-get update -qq && $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"; } >"$log" 2>&1; then
  echo "install-deps: apt failed; the end of $log:" >&2
  tail -n 30 "$log" >&2
  exit 1
fi
echo "install-deps: done"
