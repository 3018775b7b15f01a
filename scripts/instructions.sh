#!/usr/bin/env bash
# Instructions each anchor scene executes in Karma, counted by callgrind.
# Unlike wall time on a shared machine, the count is the same run after run,
# so it can show a change of a few percent that timing cannot resolve.
# It is not a time: it ignores cache misses and how instructions overlap.
#
#   scripts/instructions.sh [--binary PEER_BENCH] [--top N] [SCENE...] [-- peer_bench options]
#   e.g. scripts/instructions.sh topple stack21
#        scripts/instructions.sh --top 15 pile1000 -- --pile-steps 200
#        scripts/instructions.sh --binary /tmp/old_peer_bench ragdoll   (an A/B pair)
#
# Each scene runs once (`peer_bench --scenes SCENE --engines karma --reps 1`,
# setup included) under `valgrind --tool=callgrind`. The script prints the
# whole run's instruction count per scene and, with --top N, the N functions
# with the most instructions, their callees included. The default binary is
# build/bench's peer_bench (the `bench` preset), built if needed. It needs
# valgrind (Debian package `valgrind`). Callgrind runs about 50 times slower
# than native: pile1000's 600 steps take several minutes, so --pile-steps
# shortens it.
set -euo pipefail
cd "$(dirname "$0")/.."

binary=""
top=0
scenes=()
extra=()
while [ $# -gt 0 ]; do
  case "$1" in
    --binary) binary=$2; shift 2 ;;
    --top) top=$2; shift 2 ;;
    --) shift; extra=("$@"); break ;;
    *) scenes+=("$1"); shift ;;
  esac
done
[ ${#scenes[@]} -gt 0 ] || scenes=(car topple stack21 ragdoll)

if ! command -v valgrind >/dev/null 2>&1; then
  echo "instructions: valgrind is missing (apt-get install valgrind)" >&2
  exit 1
fi
if [ -z "$binary" ]; then
  [ -f build/bench/CMakeCache.txt ] || cmake --preset bench >/dev/null
  cmake --build build/bench -j2 --target peer_bench >/dev/null
  binary=build/bench/bench/peers/peer_bench
fi

out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "| scene | instructions |"
echo "|---|---:|"
for scene in "${scenes[@]}"; do
  file="$out/$scene.callgrind"
  valgrind --tool=callgrind --callgrind-out-file="$file" "$binary" --scenes "$scene" --engines karma --reps 1 \
    ${extra[@]+"${extra[@]}"} >/dev/null 2>"$out/$scene.log"
  callgrind_annotate --inclusive=yes "$file" >"$out/$scene.txt" 2>/dev/null
  total=$(awk '/PROGRAM TOTALS/ {print $1}' "$out/$scene.txt")
  echo "| $scene | $total |"
  if [ "$top" -gt 0 ]; then
    awk '/^-+$/ {rule++; next} rule >= 4 && NF > 2 && $1 ~ /^[0-9,]+$/' "$out/$scene.txt" |
      grep -v -E 'PROGRAM TOTALS|below main|libc-start|ld-linux|\?\?\?:main |0x0000' | sed -n "1,${top}p" |
      sed -E 's/ \[[^]]*\]$//' | cut -c1-140 | sed 's/^/    /'
  fi
done
