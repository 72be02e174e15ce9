#!/bin/sh
# Two builds of the gas probe timed at the same moment, one on each core, the cores swapped every
# round: on a shared host whose speed moves by a fifth within minutes
# (docs/decisions/0024-judging-speed-on-shared-hosts.md), runs one after the other land in
# different stretches of its
# noise, while a pair run together meets the same stretch. Prints each round's ns a collision
# (the probe's CPU time) and the second build's over the first's, then the median and quartiles
# of the ratios of pairs of rounds (below): a change is told from the noise when the quartiles
# sit on one side of 1.
#
# Usage: tools/perf/paired_runs.sh OLD_PROBE NEW_PROBE N ETA COLLISIONS_PER_BALL ROUNDS
#   e.g. tools/perf/paired_runs.sh /tmp/old/carom_world_gas_probe \
#          build/release/tools/perf/carom_world_gas_probe 10000 0.3 20 20
# Needs two logical CPUs and taskset (util-linux). At 10^5 balls and more the two runs share the
# last-level cache and the memory bandwidth: each build is slowed by the other, alike by symmetry.
set -eu

if [ $# -ne 6 ]; then
  echo "usage: $0 OLD_PROBE NEW_PROBE N ETA COLLISIONS_PER_BALL ROUNDS" >&2
  exit 2
fi
old=$1
new=$2
n=$3
eta=$4
per_ball=$5
rounds=$6
for probe in "$old" "$new"; do
  if [ ! -x "$probe" ]; then
    echo "$0: $probe: not an executable (build it: cmake --build --preset release --target carom_world_gas_probe)" >&2
    exit 2
  fi
done
case $rounds in
  '' | *[!0-9]* | 0)
    echo "$0: ROUNDS must be a positive whole number, got '$rounds'" >&2
    exit 2
    ;;
esac
if ! command -v taskset >/dev/null 2>&1; then
  echo "$0: taskset is not installed (apt-get install util-linux)" >&2
  exit 2
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The probe's CPU ns a collision from its output line.
ns_of() {
  sed -n 's/.*cpu_ns_per_collision=\([0-9]*\).*/\1/p' "$1"
}

round=1
while [ "$round" -le "$rounds" ]; do
  old_core=$((round % 2))
  new_core=$((1 - old_core))
  taskset -c "$old_core" "$old" "$n" "$eta" "$per_ball" 0 >"$work/old" &
  old_pid=$!
  taskset -c "$new_core" "$new" "$n" "$eta" "$per_ball" 0 >"$work/new" &
  new_pid=$!
  wait "$old_pid" || { echo "$0: $old failed" >&2; exit 1; }
  wait "$new_pid" || { echo "$0: $new failed" >&2; exit 1; }
  echo "$(ns_of "$work/old") $(ns_of "$work/new")" >>"$work/rounds"
  round=$((round + 1))
done

awk '{ printf "round %d: old %s ns, new %s ns, new/old %.3f\n", NR, $1, $2, $2 / $1 }' "$work/rounds"
# Rounds 2k-1 and 2k run each build once on each core: the square root of their two ratios
# cancels a difference in speed between the cores (seen: one core a third slower than the other
# for minutes, which makes the rounds' ratios alternate between about 0.7 and 1.5). The median
# and quartiles are given of these pairs' ratios; an odd last round is left out of them.
awk 'NR % 2 == 1 { r = $2 / $1 } NR % 2 == 0 { printf "%.6f\n", sqrt(r * $2 / $1) }' \
  "$work/rounds" | sort -n >"$work/ratios"
awk -v n="$n" -v eta="$eta" -v rounds="$rounds" '
  { r[NR] = $1 }
  END {
    if (NR == 0) {
      printf "N = %s, eta = %s, 1 round: no pair of rounds to compare (ask for 2 or more)\n", n, eta
      exit
    }
    # Quartiles by the nearest rank: enough to see on which side of 1 the pairs sit.
    q1 = r[int((NR + 3) / 4)]; q2 = r[int((NR + 1) / 2)]; q3 = r[int((3 * NR + 3) / 4)]
    printf "N = %s, eta = %s, %d rounds: new/old median %.3f, quartiles %.3f and %.3f (of %d pairs of rounds, each build once on each core)\n",
           n, eta, rounds, q2, q1, q3, NR
  }' "$work/ratios"
