#!/usr/bin/env bash
# The peer comparison in one command: installs ODE and Bullet (Debian
# libode-dev, libbullet-dev) if missing, configures the `bench` build with
# them, builds bench/peers/peer_bench and runs it, printing the Markdown
# table of docs/PERFORMANCE.md. Arguments go to peer_bench, e.g.
#   scripts/peers.sh --scenes car,ragdoll --reps 7
#   scripts/peers.sh --pile-steps 600        (the full pile: tens of minutes)
# Progress and engine warnings go to build/bench/peer_bench.log.
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/install-deps.sh >/dev/null
packages=(libode-dev libbullet-dev)
missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "peers: installing ${missing[*]}" >&2
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then
    if command -v sudo >/dev/null 2>&1; then SUDO=sudo; else
      echo "peers: need root to install: ${missing[*]}" >&2; exit 1
    fi
  fi
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

cmake --preset bench -DKARMA_BENCH_PEERS=ON >/dev/null
cmake --build --preset bench -j2 --target peer_bench >/dev/null
log=build/bench/peer_bench.log
echo "peers: running build/bench/bench/peers/peer_bench $* (progress in $log)" >&2
build/bench/bench/peers/peer_bench "$@" 2>"$log"
