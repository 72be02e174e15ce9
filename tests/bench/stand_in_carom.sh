#!/bin/sh
# A stand-in for the carom tool in carom_bench_goals' tests: `bench ... --json` answers at once
# with figures that meet every goal (10^4 disks at 300 ns a collision, 10^5 at 500, 10^6 at 550,
# 116 bytes a ball). STAND_IN_LOG names a file that gets each command line. STAND_IN=refuse
# fails as the tool does on a bad option; STAND_IN=hang writes its process id to STAND_IN_PID
# and waits half a minute.
set -eu
if [ -n "${STAND_IN_LOG:-}" ]; then echo "$*" >> "$STAND_IN_LOG"; fi
case ${STAND_IN:-} in
  refuse) echo "carom: error: refused by the stand-in" >&2; exit 2 ;;
  hang) echo $$ > "$STAND_IN_PID"; exec sleep 30 ;;
esac
[ "$1" = bench ] || exit 2
n=0 eta=0
while [ $# -gt 0 ]; do
  case $1 in
    --n) n=$2; shift 2 ;;
    --eta) eta=$2; shift 2 ;;
    *) shift ;;
  esac
done
case $n in
  10000) runs="300,310,290" ;;
  100000) runs="500,500,500" ;;
  *) runs="550,560,540" ;;
esac
printf '{"n":%s,"eta":%s,"repetition_nanoseconds_per_collision":[%s],"bytes_per_ball":116.0,' \
  "$n" "$eta" "$runs"
printf '"build_type":"Release","compiler":"stand-in","machine":{"cpu":"Stand-in CPU",'
printf '"logical_cpus":2,"l1d_cache_bytes":49152,"l2_cache_bytes":1048576,"l3_cache_bytes":0}}\n'
