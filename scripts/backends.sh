#!/usr/bin/env bash
# Microseconds per step of each anchor scene on each platform backend
# (engine/platform/kernels.h), in one run, as a Markdown table with each
# backend's speed-up over the reference (reference time / backend time).
#
#   scripts/backends.sh [--build DIR] [--rounds N] [peer_bench options...]
#   e.g. scripts/backends.sh --rounds 7 --scenes topple,pile1000
#
# Builds karma-platforms and bench/peers/peer_bench in DIR (default
# build/bench, the `bench` preset), then runs `peer_bench --engines karma
# --reps 1` N times (default 5) for every backend this CPU supports, the
# backends interleaved within each round (KARMA_PLATFORM=<backend> per
# process), and reports per scene the median over the rounds. Engine
# warnings go to DIR/backends.log.
set -euo pipefail
cd "$(dirname "$0")/.."

build=build/bench
rounds=5
args=()
while [ $# -gt 0 ]; do
  case "$1" in
    --build) build=$2; shift 2 ;;
    --rounds) rounds=$2; shift 2 ;;
    *) args+=("$1"); shift ;;
  esac
done

if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake --preset bench >/dev/null
fi
cmake --build "$build" -j2 --target peer_bench karma-platforms >/dev/null
platforms="$build/tools/platform/karma-platforms"
bench="$build/bench/peers/peer_bench"
log="$build/backends.log"
: >"$log"

backends=()
for b in $("$platforms" --names); do
  if "$platforms" --supported "$b"; then backends+=("$b"); else echo "backends: this CPU lacks $b: skipped" >&2; fi
done

# One line per (round, backend, scene): backend<TAB>scene (steps)<TAB>us per step.
samples=$(mktemp)
trap 'rm -f "$samples"' EXIT
for ((r = 1; r <= rounds; r++)); do
  for b in "${backends[@]}"; do
    echo "backends: round $r/$rounds, $b" >&2
    KARMA_PLATFORM=$b "$bench" --engines karma --reps 1 "${args[@]}" 2>>"$log" |
      awk -F'|' -v b="$b" '$3 ~ /karma/ { s = $2; gsub(/^ +| +$/, "", s); t = $4; sub(/\[.*/, "", t);
                                         gsub(/[ ,]/, "", t); print b "\t" s "\t" t }' >>"$samples"
  done
done

echo
echo "Anchor scenes per platform backend: µs per step, median of $rounds interleaved rounds ($(date -u +%Y-%m-%d), $(nproc) cores);"
echo "× = speed-up over reference (reference time / backend time)."
echo
awk -F'\t' -v order="${backends[*]}" '
  function median(list,   a, n, i, j, t) {
    n = split(list, a, " ")
    for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) if (a[j] + 0 < a[i] + 0) { t = a[i]; a[i] = a[j]; a[j] = t }
    return n % 2 ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2
  }
  { if (!($2 in seen)) { seen[$2] = 1; scenes[++ns] = $2 } times[$1 SUBSEP $2] = times[$1 SUBSEP $2] " " $3 }
  END {
    nb = split(order, bs, " ")
    header = "| scene (steps) |"; rule = "|---|"
    for (i = 1; i <= nb; i++) { header = header " " bs[i] " µs |"; rule = rule "---:|"; if (i > 1) { header = header " " bs[i] " × |"; rule = rule "---:|" } }
    print header; print rule
    for (s = 1; s <= ns; s++) {
      line = "| " scenes[s] " |"; ref = median(times[bs[1] SUBSEP scenes[s]])
      for (i = 1; i <= nb; i++) {
        m = median(times[bs[i] SUBSEP scenes[s]])
        line = line sprintf(" %.1f |", m)
        if (i > 1) line = line sprintf(" %.2f |", ref / m)
      }
      print line
    }
  }' "$samples"
