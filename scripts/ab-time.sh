#!/usr/bin/env bash
# Time A/B of two builds of peer_bench on one scene, Karma alone: the two
# binaries run in turn, A then B, for ROUNDS rounds, so the machine's drift
# in speed (up to 2x within minutes here) touches both alike. Prints each
# binary's µs per step, round by round, and their medians. For a change
# that instruction counts cannot see (a wait on memory or on a chain of
# dependent operations); for one they can, scripts/instructions.sh is
# steadier.
#
#   scripts/ab-time.sh A_PEER_BENCH B_PEER_BENCH ROUNDS [peer_bench options]
#   e.g. cp build/bench/bench/peers/peer_bench /tmp/pb_before   (then change, rebuild)
#        scripts/ab-time.sh /tmp/pb_before build/bench/bench/peers/peer_bench 6 \
#            --scenes pile1000 --pile-steps 600
#
# Each run is `peer_bench --reps 1 --engines karma OPTIONS`; give one scene
# (and, for a short one, more repetitions: --reps 9 takes the median of 9).
set -euo pipefail

if [ $# -lt 3 ]; then
  sed -n '2,16p' "$0" >&2
  exit 2
fi
a=$1
b=$2
rounds=$3
shift 3

# The µs per step of one run: the first number of the table's third column.
time_of() {
  "$1" --reps 1 --engines karma "${@:2}" 2>/dev/null |
    awk -F'|' '$3 ~ /karma/ { split($4, t, " "); gsub(",", "", t[1]); print t[1]; exit }'
}

median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2) }'; }

as=()
bs=()
for ((i = 0; i < rounds; ++i)); do
  as+=("$(time_of "$a" "$@")")
  bs+=("$(time_of "$b" "$@")")
done
echo "A ($a): ${as[*]} µs a step; median $(printf '%s\n' "${as[@]}" | median)"
echo "B ($b): ${bs[*]} µs a step; median $(printf '%s\n' "${bs[@]}" | median)"
