#!/usr/bin/env bash
# carom_bench_goals end to end, with a stand-in for the carom tool (stand_in_carom.sh) that
# answers at once: the options it takes and refuses, the gases it runs and with what, the report
# in text and JSON, a gas that fails, and Ctrl-C or SIGTERM passed on to the gas that runs. With
# the real tool's path as well, the tool runs the plan's first gas with the very arguments the
# program gave the stand-in (a second or two), so the two cannot drift apart.
# Usage: goals_program_tests.sh PROGRAM STAND_IN WORK_DIR [REAL_TOOL]
set -uo pipefail

program=$1
stand_in=$2
work=$3
real_tool=${4:-}
failures=0

rm -rf "$work"
mkdir -p "$work"
log=$work/arguments

fail() {
  echo "FAILED: $*" >&2
  failures=$((failures + 1))
}
# run ARGS...: the program with the stand-in, its status, stdout and stderr in $status, $out, $err.
run() {
  rm -f "$log"
  "$program" "$@" > "$work/out" 2> "$work/err"
  status=$?
  out=$(cat "$work/out")
  err=$(cat "$work/err")
}
expect_status() { [ "$status" -eq "$1" ] || fail "$2: status $status, not $1 ($err)"; }
expect_in() { [[ $2 == *"$1"* ]] || fail "$3: no \"$1\" in: $2"; }
expect_not_in() { [[ $2 != *"$1"* ]] || fail "$3: \"$1\" in: $2"; }

# Help names every option.
run --help
expect_status 0 "--help"
for option in --tool --seed --equilibrate --json; do expect_in "$option" "$out" "--help"; done

# The plan's gases are fixed: options of one gas are refused before any gas runs, and so are a
# bad seed, equilibration and tool.
for option in --n --eta --collisions-per-ball --repeat; do
  run --tool "$stand_in" "$option" 5
  expect_status 2 "$option"
  expect_in "$option" "$err" "$option"
  [ -z "$out" ] || fail "$option: printed $out"
  [ ! -e "$log" ] || fail "$option: a gas ran"
done
for bad in "--seed x" "--seed -1" "--equilibrate -1" "--equilibrate inf" "--equilibrate x"; do
  # shellcheck disable=SC2086 # the option and its value, as two words
  STAND_IN_LOG=$log run --tool "$stand_in" $bad
  expect_status 2 "$bad"
  expect_in "${bad% *}" "$err" "$bad"
  expect_not_in "gas 1 of" "$err" "$bad"
  [ -z "$out" ] || fail "$bad: printed $out"
  [ ! -e "$log" ] || fail "$bad: a gas ran"
done
run --tool "$work/nothing-here"
expect_status 2 "a missing tool"
expect_in "--tool \"$work/nothing-here\"" "$err" "a missing tool"

# Every gas of the plan, in order, each with the user's seed and equilibration; the verdicts; the
# tool's build and machine as it reported them.
STAND_IN_LOG=$log run --tool "$stand_in"
expect_status 0 "the plan"
[ "$(wc -l < "$log")" -eq 8 ] || fail "the plan: $(wc -l < "$log") gases, not 8"
plan="bench --n 10000 --eta 0.3 --collisions-per-ball 20 --repeat 5 --seed 1 --equilibrate 2 --json
bench --n 100000 --eta 0.3 --collisions-per-ball 10 --repeat 5 --seed 1 --equilibrate 2 --json
bench --n 1000000 --eta 0.3 --collisions-per-ball 2 --repeat 3 --seed 1 --equilibrate 2 --json
bench --n 10000 --eta 0.3 --collisions-per-ball 20 --repeat 5 --seed 1 --equilibrate 2 --json
bench --n 10000 --eta 0.6 --collisions-per-ball 20 --repeat 5 --seed 1 --equilibrate 2 --json
bench --n 100000 --eta 0.6 --collisions-per-ball 10 --repeat 5 --seed 1 --equilibrate 2 --json
bench --n 1000000 --eta 0.6 --collisions-per-ball 2 --repeat 3 --seed 1 --equilibrate 2 --json
bench --n 10000 --eta 0.6 --collisions-per-ball 20 --repeat 5 --seed 1 --equilibrate 2 --json"
[ "$(cat "$log")" = "$plan" ] || fail "the plan ran: $(cat "$log")"
first_gas=$(head -n 1 "$log")
expect_in "gas 8 of 8, 10000 disks at eta 0.6" "$err" "the plan's progress"
expect_in "10^6, eta 0.6" "$out" "the plan's table"
expect_in "7 of 7 goals met" "$out" "the plan's verdicts"
expect_in "build: Release, stand-in (the tool $stand_in)" "$out" "the plan's footer"
expect_in "machine: Stand-in CPU, 2 logical CPUs; caches L1d 48 KiB, L2 1 MiB, L3 unknown" \
  "$out" "the plan's footer"

# --json: one object, nothing on stderr.
STAND_IN_LOG=$log run --tool "$stand_in" --json --seed 7 --equilibrate 0.5
expect_status 0 "--json"
[ -z "$err" ] || fail "--json: wrote $err"
[ "$(wc -l < "$work/out")" -eq 1 ] || fail "--json: more than one line"
expect_in '{"gases":[{"n":10000,"eta":0.3,' "$out" "--json"
expect_in '"all_met":true}' "$out" "--json"
[ "$(grep -c -- '--seed 7 --equilibrate 0.5 --json$' "$log")" -eq 8 ] ||
  fail "--json: the seed and equilibration did not reach every gas: $(cat "$log")"

# A gas that fails ends the run with status 1 and no verdicts.
STAND_IN=refuse run --tool "$stand_in"
expect_status 1 "a failing gas"
expect_in "refused by the stand-in" "$err" "a failing gas"
expect_in "failed with exit status 2" "$err" "a failing gas"
[ -z "$out" ] || fail "a failing gas: printed $out"

# A signal to the program stops the gas that runs (the stand-in is gone when the program ends),
# and the program ends with 128 + the signal.
for signal in TERM INT; do
  pid_file=$work/stand-in-$signal.pid
  STAND_IN=hang STAND_IN_PID=$pid_file "$program" --tool "$stand_in" > "$work/out" 2> "$work/err" &
  goals=$!
  for _ in $(seq 100); do [ -s "$pid_file" ] && break; sleep 0.1; done
  if [ ! -s "$pid_file" ]; then
    fail "SIG$signal: the gas did not start"
    kill -KILL "$goals"
    continue
  fi
  kill -"$signal" "$goals"
  # The stand-in waits half a minute unless the signal reaches it: give the program ten seconds.
  for _ in $(seq 100); do kill -0 "$goals" 2> /dev/null || break; sleep 0.1; done
  if kill -0 "$goals" 2> /dev/null; then
    fail "SIG$signal: the program still runs ten seconds after the signal"
    kill -KILL "$goals" "$(cat "$pid_file")"
  fi
  wait "$goals"
  status=$?
  err=$(cat "$work/err")
  if [ "$signal" = TERM ]; then
    expect_status 143 "SIGTERM"
    expect_in "terminated (SIGTERM) in gas 1 of 8: no verdicts" "$err" "SIGTERM"
  else
    expect_status 130 "SIGINT"
    expect_in "interrupted (Ctrl-C) in gas 1 of 8: no verdicts" "$err" "SIGINT"
  fi
  [ ! -s "$work/out" ] || fail "SIG$signal: printed $(cat "$work/out")"
  stand_in_pid=$(cat "$pid_file")
  if kill -0 "$stand_in_pid" 2> /dev/null; then
    fail "SIG$signal: the gas's process $stand_in_pid still runs"
    kill -KILL "$stand_in_pid"
  fi
done

# The real tool takes the arguments of the plan's first gas and gives the figures the goals read.
if [ -n "$real_tool" ]; then
  # shellcheck disable=SC2086 # the logged arguments, as words
  if "$real_tool" $first_gas > "$work/real.json"; then
    real=$(cat "$work/real.json")
    for field in '"n":10000,' '"eta":0.3,' '"repetition_nanoseconds_per_collision":[' \
      '"bytes_per_ball":' '"build_type":' '"machine":{"cpu":'; do
      expect_in "$field" "$real" "the real tool"
    done
  else
    fail "the real tool refused: $first_gas"
  fi
fi

if [ "$failures" -ne 0 ]; then
  echo "$failures checks failed" >&2
  exit 1
fi
echo "every check passed"
