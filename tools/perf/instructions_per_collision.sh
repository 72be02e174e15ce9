#!/bin/sh
# Instructions a collision of the world's engine on the hard-disk gas, counted by callgrind.
# Unlike a time, the count is the same on every run of the same binary with the same inputs,
# whatever else the host is doing and whichever host it is (valgrind runs the AVX2 kernel on any
# x86-64 with AVX2; it hides AVX-512): a change of the engine's work shows here even where the
# host's noise hides it in the times (docs/decisions/0024-judging-speed-on-shared-hosts.md).
#
# Usage: tools/perf/instructions_per_collision.sh PROBE [N ETA]...
#   PROBE: build/release/tools/perf/carom_world_gas_probe (a release build of it)
#   N ETA: gases to count (default: 10000 0.3 10000 0.6)
# Each gas is run twice, with 10 and with 30 collisions a disk after the probe's 2 a disk of
# equilibration, counting only inside World::run_collisions; the difference over the 20·N
# collisions more is the figure, so the grid's building and the first prediction of every ball
# (in both runs alike) drop out, while the re-orderings by cell (one every 8 events a ball and
# 2^16 more) fall in it at about their steady rate.
set -eu

if [ $# -lt 1 ]; then
  echo "usage: $0 PROBE [N ETA]..." >&2
  exit 2
fi
probe=$1
shift
if [ ! -x "$probe" ]; then
  echo "$0: $probe: not an executable (build it: cmake --build --preset release --target carom_world_gas_probe)" >&2
  exit 2
fi
if ! command -v valgrind >/dev/null 2>&1; then
  echo "$0: valgrind is not installed (apt-get install valgrind)" >&2
  exit 2
fi
if [ $# -eq 0 ]; then
  set -- 10000 0.3 10000 0.6
fi
if [ $(($# % 2)) -ne 0 ]; then
  echo "$0: the gases come in pairs, N ETA; got an odd count of arguments: $*" >&2
  exit 2
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The instructions callgrind counted inside run_collisions for PROBE N ETA K.
count() {
  valgrind --tool=callgrind --callgrind-out-file="$work/out" \
    --toggle-collect='carom::World::run_collisions*' "$probe" "$1" "$2" "$3" 0 \
    >"$work/probe.log" 2>"$work/valgrind.log" || {
    echo "$0: the probe failed under valgrind for N=$1 ETA=$2; its output and valgrind's:" >&2
    cat "$work/valgrind.log" >&2
    exit 1
  }
  sed -n 's/^summary: \([0-9]*\).*/\1/p' "$work/out"
}

while [ $# -gt 0 ]; do
  n=$1
  eta=$2
  shift 2
  fewer=$(count "$n" "$eta" 10)
  more=$(count "$n" "$eta" 30)
  awk -v n="$n" -v eta="$eta" -v a="$fewer" -v b="$more" 'BEGIN {
    printf "N = %s, eta = %s: %.1f instructions a collision (callgrind; %.0f over %.0f collisions)\n",
           n, eta, (b - a) / (20 * n), b - a, 20 * n }'
done
