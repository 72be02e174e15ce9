#!/bin/sh
# carom's hard-disk gas against the textbook simulator (tools/perf/textbook_gas.cpp: one earliest event
# per ball, an indexed binary heap, cell crossings) on this host, paired on the two cores by
# tools/perf/paired_runs.sh. The world's speed goals (2.5 M collisions/s at 10^4 disks, 1.5 M at
# 10^5) were set on a machine where the textbook reaches about 1.0 M and 0.6 M: 2.5 times the
# textbook's rate at both sizes. Hosts differ by half and more in speed
# (docs/decisions/0024-judging-speed-on-shared-hosts.md), so the textbook run beside carom's says
# which kind of host a verdict came from, and how far the engine is from the goals as that machine
# would judge them: speed-up = the textbook's ns a collision over carom's.
#
# Usage: tools/perf/yardstick.sh TEXTBOOK PROBE [N ETA COLLISIONS_PER_BALL ROUNDS]...
#   TEXTBOOK: build/release/tools/perf/carom_textbook_gas
#   PROBE:    build/release/tools/perf/carom_world_gas_probe
#   default gases: 10000 0.3 50 16  10000 0.6 50 16  100000 0.3 10 8  100000 0.6 10 8
set -eu

if [ $# -lt 2 ] || [ $(($# % 4)) -ne 2 ]; then
  echo "usage: $0 TEXTBOOK PROBE [N ETA COLLISIONS_PER_BALL ROUNDS]..." >&2
  exit 2
fi
textbook=$1
probe=$2
shift 2
for program in "$textbook" "$probe"; do
  if [ ! -x "$program" ]; then
    echo "$0: $program: not an executable (build it: cmake --build --preset release --target carom_textbook_gas carom_world_gas_probe)" >&2
    exit 2
  fi
done
if [ $# -eq 0 ]; then
  set -- 10000 0.3 50 16 10000 0.6 50 16 100000 0.3 10 8 100000 0.6 10 8
fi

here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# paired_runs.sh passes each probe N ETA K 0; the textbook's fourth argument is its equilibration
# (2 collisions a disk by default, as the probe's), so it is dropped.
cat >"$work/textbook" <<EOF
#!/bin/sh
exec "$textbook" "\$1" "\$2" "\$3"
EOF
chmod +x "$work/textbook"

echo "gas                    carom / textbook time: median (quartiles)   speed-up   the goals' speed-up"
while [ $# -ge 4 ]; do
  n=$1
  eta=$2
  per_ball=$3
  rounds=$4
  shift 4
  line=$("$here/paired_runs.sh" "$work/textbook" "$probe" "$n" "$eta" "$per_ball" "$rounds" | tail -n 1)
  # paired_runs.sh's verdict: "... new/old median M, quartiles L and H (...)".
  read -r median low high <<VERDICT
$(echo "$line" | sed -n 's/.*median \([0-9.]*\), quartiles \([0-9.]*\) and \([0-9.]*\).*/\1 \2 \3/p')
VERDICT
  if [ -z "$median" ]; then
    echo "$0: no verdict for N = $n, eta = $eta: $line" >&2
    exit 1
  fi
  # 2.5 M against 1.0 M at 10^4, 1.5 M against 0.6 M at 10^5; no rate goal at other sizes.
  case $n in
    10000 | 100000) goal=2.5 ;;
    *) goal=- ;;
  esac
  awk -v n="$n" -v eta="$eta" -v m="$median" -v lo="$low" -v hi="$high" -v goal="$goal" 'BEGIN {
    printf "N = %-7s eta = %-4s %.3f (%.3f, %.3f)%20.2f   %s\n", n, eta, m, lo, hi, 1 / m, goal
  }'
done
