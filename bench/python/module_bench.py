#!/usr/bin/python3
"""Benchmarks of the Python module (carom) against its goals, each beside the same work done
without Python:

  add    world.add_balls(positions, velocities, radii) of 10^6 balls           goal <= 1 s
  read   world.positions of 10^6 balls                                        goal <= 20 ms
  step   a 10^4-disk gas stepped by a Python loop of world.step(dt) or
         world.run_until(t), against the same loop in C++ (carom_step_from_cpp),
         both from the same saved world, with a dt of about one collision a disk
         a call and one of 0.05                                               goal <= 5 % more
  gas    carom.gas(...) against `carom gas ... --json`, wall time             goal: as fast

The host is a shared 2-core guest whose speed moves by 10 to 30 % between minutes, so the two
sides of each comparison run alternately (which goes first alternates too) and the figures are
medians over the repetitions. In the step case each side of a pair times its loop several times
(the world loaded afresh each time) and keeps the least, the run least disturbed by the host's
other work; the figure is the median over the pairs of Python's least over C++'s. The step case
also checks that Python and C++ end in the same world, bit for bit (the saved bytes), so that
both did the same work, and times step(0) alone: the cost of a call with nothing to do.

  /usr/bin/python3 bench/python/module_bench.py --build build/release --json out.json

--build names a release build folder holding the module (python/carom), the tool
(apps/carom/carom) and bench/python/carom_step_from_cpp (the target carom_step_from_cpp).
"""

import argparse
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time


def median(values):
    return statistics.median(values) if values else math.nan


def run_json(command):
    """Runs a command and reads the one JSON object it prints; returns it and the wall time."""
    start = time.perf_counter()
    done = subprocess.run(command, check=True, capture_output=True, text=True)
    wall = time.perf_counter() - start
    return json.loads(done.stdout), wall


# ---- add_balls and positions ------------------------------------------------------------------

SPACING = 1.5  # as carom_step_from_cpp's lattice: radius 0.5 at spacing 1.5, periodic square


def lattice_arrays(np, n):
    side = math.ceil(math.sqrt(n))
    i = np.arange(n, dtype=np.float64)
    positions = np.column_stack(((i % side + 0.5) * SPACING, (i // side + 0.5) * SPACING))
    velocities = np.column_stack((np.cos(i), np.sin(i)))
    radii = np.full(n, 0.5)
    return side, positions, velocities, radii


def python_add_read(carom, np, n, collisions, reads):
    side, positions, velocities, radii = lattice_arrays(np, n)
    world = carom.World(boundary="periodic", lower=(0, 0), upper=(side * SPACING,) * 2)
    start = time.perf_counter()
    world.add_balls(positions, velocities, radii)
    add_seconds = time.perf_counter() - start
    fresh, after_run = [], []
    for _ in range(reads):
        start = time.perf_counter()
        read = world.positions
        fresh.append(time.perf_counter() - start)
    if not np.array_equal(read, positions):
        raise SystemExit("world.positions differs from the positions added")
    for _ in range(reads):
        world.run_collisions(collisions)
        start = time.perf_counter()
        read = world.positions
        after_run.append(time.perf_counter() - start)
    return {"add_seconds": add_seconds, "read_seconds": fresh, "read_seconds_after_run": after_run}


def bench_add_read(carom, np, args):
    # A hundredth of a collision a ball between reads: a frame's worth of a game or a movie.
    n, collisions, reads = args.add_n, args.add_n // 100, args.reads
    cpp_command = [args.cpp, "add", str(n), str(collisions), str(reads)]
    py_runs, cpp_runs = [], []
    for rep in range(args.add_reps):
        for side in ("python", "cpp") if rep % 2 == 0 else ("cpp", "python"):
            if side == "python":
                py_runs.append(python_add_read(carom, np, n, collisions, reads))
            else:
                cpp_runs.append(run_json(cpp_command)[0])

    def figures(runs):
        # The first read of a world also pays for the pages of the arrays it makes; the median
        # over every read after the first is the steady figure. Reads after a run are each
        # the first after that run.
        adds = [r["add_seconds"] for r in runs]
        steady = [s for r in runs for s in r["read_seconds"][1:]]
        after_run = [s for r in runs for s in r["read_seconds_after_run"]]
        return {
            "add_s": median(adds), "add_s_range": [min(adds), max(adds)],
            "read_first_ms": 1e3 * median([r["read_seconds"][0] for r in runs]),
            "read_ms": 1e3 * median(steady),
            "read_after_run_ms": 1e3 * median(after_run),
            "read_after_run_ms_range": [1e3 * min(after_run), 1e3 * max(after_run)],
        }

    return {
        "n": n, "collisions_before_each_read_after_run": collisions, "reads_per_world": reads,
        "repetitions": args.add_reps,
        "python": figures(py_runs), "cpp": figures(cpp_runs),
        "runs": {"python": py_runs, "cpp": cpp_runs},
    }


# ---- stepping the gas -------------------------------------------------------------------------

def python_advance(carom, world_file, mode, dt, calls, repeats):
    """Loads the world `repeats` times and times the loop on each; returns the last world."""
    seconds = []
    for _ in range(repeats):
        world = carom.World.load(world_file)
        t0 = world.time
        c0 = world.collision_count
        if mode == "until":
            start = time.perf_counter()
            for k in range(1, calls + 1):
                world.run_until(t0 + k * dt)
            seconds.append(time.perf_counter() - start)
        else:
            start = time.perf_counter()
            for _ in range(calls):
                world.step(dt)
            seconds.append(time.perf_counter() - start)
    return world, {"seconds": seconds, "collisions": world.collision_count - c0,
                   "time": world.time}


def quartiles(values):
    if len(values) < 2:
        return list(values)
    q = statistics.quantiles(values, n=4)
    return [q[0], q[2]]


def bench_step(carom, args, scratch):
    world_file = os.path.join(scratch, "gas.world")
    made, _ = run_json([args.cpp, "make", str(args.step_n), repr(args.step_eta), str(args.seed),
                        str(args.equilibrate), world_file])
    tau = made["time_per_collision_per_disk"]
    cases = []
    for per_call in args.per_call:
        calls = max(1, round(args.step_k / per_call))
        for mode in ("step", "until"):
            cases.append({"mode": mode, "collisions_per_disk_per_call": per_call,
                          "dt": per_call * tau, "calls": calls})
    # dt = 0: every call is pure overhead (no event to process), its cost per call on each side.
    cases.append({"mode": "step", "collisions_per_disk_per_call": 0.0, "dt": 0.0,
                  "calls": args.empty_calls})
    cpp_out = os.path.join(scratch, "cpp.world")
    repeats = args.step_repeats
    for case in cases:
        py_best, cpp_best, ratios, identical = [], [], [], True
        py_all, cpp_all = [], []
        collisions = None
        for rep in range(args.step_reps):
            order = ("python", "cpp") if rep % 2 == 0 else ("cpp", "python")
            pair = {}
            for side in order:
                if side == "python":
                    world, pair["python"] = python_advance(carom, world_file, case["mode"],
                                                           case["dt"], case["calls"], repeats)
                else:
                    pair["cpp"], _ = run_json([args.cpp, case["mode"], world_file,
                                               repr(case["dt"]), str(case["calls"]),
                                               str(repeats), cpp_out])
            with open(cpp_out, "rb") as f:
                same = world.save() == f.read()
            identical = (identical and same
                         and pair["python"]["collisions"] == pair["cpp"]["collisions"])
            collisions = pair["cpp"]["collisions"]
            # The least of a side's repeats is its run least disturbed by the host's other work.
            py_best.append(min(pair["python"]["seconds"]))
            cpp_best.append(min(pair["cpp"]["seconds"]))
            ratios.append(py_best[-1] / cpp_best[-1])
            py_all += pair["python"]["seconds"]
            cpp_all += pair["cpp"]["seconds"]
        case.update({
            "collisions": collisions,
            "bit_identical": identical,
            "python_s": median(py_best), "cpp_s": median(cpp_best),
            "python_min_s": min(py_all), "cpp_min_s": min(cpp_all),
            "ratio_median": median(ratios),
            "ratio_quartiles": quartiles(ratios),
            "ratio_of_minima": min(py_all) / min(cpp_all),
            "python_us_per_call": 1e6 * min(py_all) / case["calls"],
            "cpp_us_per_call": 1e6 * min(cpp_all) / case["calls"],
            "runs": {"python_s": py_all, "cpp_s": cpp_all},
        })
    return {"n": args.step_n, "eta": args.step_eta, "seed": args.seed,
            "equilibrate_per_disk": args.equilibrate, "time_per_collision_per_disk": tau,
            "collisions_per_disk_per_run": args.step_k, "pairs": args.step_reps,
            "repeats_per_side": repeats, "cases": cases}


# ---- carom.gas against carom gas --json ---------------------------------------------------------

TIMINGS = {"wall_seconds", "collisions_per_second"}


def without_timings(report):
    return {k: v for k, v in report.items() if k not in TIMINGS}


def bench_gas(carom, args):
    cases = []
    for spec in args.gas:
        kwargs = dict(item.split("=") for item in spec.split(",")) if spec else {}
        cli = [args.cli, "gas", "--json"]
        for key, value in kwargs.items():
            cli += ["--" + key, value]
        py_kwargs = {k: (float(v) if k == "eta" else int(v)) for k, v in kwargs.items()}
        py_wall, cli_wall, py_inner, cli_inner, ratios, same = [], [], [], [], [], True
        for rep in range(args.gas_reps):
            order = ("python", "cli") if rep % 2 == 0 else ("cli", "python")
            got = {}
            for side in order:
                if side == "python":
                    start = time.perf_counter()
                    got["python"] = carom.gas(**py_kwargs)
                    py_wall.append(time.perf_counter() - start)
                else:
                    got["cli"], wall = run_json(cli)
                    cli_wall.append(wall)
            py_inner.append(got["python"]["wall_seconds"])
            cli_inner.append(got["cli"]["wall_seconds"])
            ratios.append(py_wall[-1] / cli_wall[-1])
            same = same and without_timings(got["python"]) == without_timings(got["cli"])
        cases.append({
            "arguments": py_kwargs, "cli": " ".join(cli[1:]),
            "collisions": got["cli"]["collisions"],
            "same_numbers": same,
            "python_call_s": median(py_wall), "cli_process_s": median(cli_wall),
            "python_run_s": median(py_inner), "cli_run_s": median(cli_inner),
            "ratio_median": median(ratios),
            "ratio_quartiles": quartiles(ratios),
            "python_call_min_s": min(py_wall), "cli_process_min_s": min(cli_wall),
            "runs": {"python_call_s": py_wall, "cli_process_s": cli_wall,
                     "python_run_s": py_inner, "cli_run_s": cli_inner},
        })
    return {"repetitions": args.gas_reps, "cases": cases}


# ---- report -----------------------------------------------------------------------------------

def print_report(results):
    if "add" in results:
        a = results["add"]
        p, c = a["python"], a["cpp"]

        def verdict(value, goal):
            return "met" if value <= goal else "NOT met"

        print(f"add/read, N = {a['n']}, {a['repetitions']} worlds a side (medians)")
        print(f"  add_balls          python {p['add_s']:8.3f} s    "
              f"C++ add_ball loop {c['add_s']:8.3f} s    goal <= 1 s: {verdict(p['add_s'], 1)}")
        print(f"  positions, first   python {p['read_first_ms']:8.1f} ms   "
              f"C++ {c['read_first_ms']:8.1f} ms")
        print(f"  positions          python {p['read_ms']:8.1f} ms   C++ {c['read_ms']:8.1f} ms"
              f"    goal <= 20 ms: {verdict(p['read_ms'], 20)}")
        print(f"  after a run        python {p['read_after_run_ms']:8.1f} ms   "
              f"C++ {c['read_after_run_ms']:8.1f} ms"
              f"    goal <= 20 ms: {verdict(p['read_after_run_ms'], 20)}")
    if "step" in results:
        s = results["step"]
        print(f"stepping, N = {s['n']}, eta = {s['eta']}, {s['collisions_per_disk_per_run']} "
              f"collisions a disk a run, {s['pairs']} pairs of the least of "
              f"{s['repeats_per_side']} runs a side")
        print("  mode   coll/disk/call  calls  python s    C++ s  py/C++  quartiles    "
              "min/min  us/call py  C++   same  goal <= 1.05")
        for c in s["cases"]:
            q = c["ratio_quartiles"]
            verdict = "" if c["dt"] == 0 else ("met" if c["ratio_median"] <= 1.05 else "NOT met")
            print(f"  {c['mode']:6} {c['collisions_per_disk_per_call']:14g} {c['calls']:6d} "
                  f"{c['python_s']:8.4f} {c['cpp_s']:8.4f} {c['ratio_median']:7.3f}  "
                  f"{q[0]:.3f}-{q[-1]:.3f}  {c['ratio_of_minima']:7.3f} "
                  f"{c['python_us_per_call']:9.2f} {c['cpp_us_per_call']:7.2f}  "
                  f"{'yes' if c['bit_identical'] else 'NO':4}  {verdict}")
    if "gas" in results:
        g = results["gas"]
        print(f"carom.gas against carom gas --json, {g['repetitions']} pairs (wall; medians, "
              "then least)")
        print("  arguments                                           python call  CLI process"
              "  py run  CLI run  py/CLI  least py  CLI   same")
        for c in g["cases"]:
            print(f"  {c['cli']:51} {c['python_call_s']:11.3f} {c['cli_process_s']:12.3f} "
                  f"{c['python_run_s']:7.3f} {c['cli_run_s']:8.3f} {c['ratio_median']:7.3f} "
                  f"{c['python_call_min_s']:8.3f} {c['cli_process_min_s']:6.3f}  "
                  f"{'yes' if c['same_numbers'] else 'NO'}")


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default="build/release", help="release build folder")
    parser.add_argument("--cases", default="add,step,gas",
                        help="comma-separated: add (add_balls and positions), step, gas")
    parser.add_argument("--json", metavar="FILE", help="write the results as JSON")
    parser.add_argument("--add-n", type=int, default=1_000_000)
    parser.add_argument("--add-reps", type=int, default=5, help="worlds built a side")
    parser.add_argument("--reads", type=int, default=7, help="position reads a world, twice")
    parser.add_argument("--step-n", type=int, default=10_000)
    parser.add_argument("--step-eta", type=float, default=0.3)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--equilibrate", type=int, default=2,
                        help="collisions a disk run before the world is saved")
    parser.add_argument("--step-k", type=float, default=20,
                        help="collisions a disk in each timed run")
    parser.add_argument("--per-call", type=float, nargs="+", default=[1.0, 0.05],
                        help="collisions a disk a call (dt in units of the gas's mean time)")
    parser.add_argument("--empty-calls", type=int, default=20_000,
                        help="calls of step(0) to time the cost of a call alone")
    parser.add_argument("--step-reps", type=int, default=15, help="pairs of runs a case")
    parser.add_argument("--step-repeats", type=int, default=5,
                        help="timed loops a side in each pair, of which the least counts")
    parser.add_argument("--gas", nargs="+",
                        default=["", "n=10000,equilibrate=5,collisions=50"],
                        help="carom gas cases as key=value,...; empty: the defaults")
    parser.add_argument("--gas-reps", type=int, default=11, help="pairs of runs a case")
    parser.add_argument("--cpu", type=int, help="pin this process and its children to one CPU")
    args = parser.parse_args()

    build = os.path.abspath(args.build)
    sys.path.insert(0, os.path.join(build, "python"))
    import numpy as np
    import carom

    args.cpp = os.path.join(build, "bench", "python", "carom_step_from_cpp")
    args.cli = os.path.join(build, "apps", "carom", "carom")
    if args.cpu is not None:
        os.sched_setaffinity(0, {args.cpu})
    cases = args.cases.split(",")
    results = {"started_utc": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()),
               "load_average_before": os.getloadavg(), "module": carom.__file__}
    with tempfile.TemporaryDirectory() as scratch:
        if "add" in cases:
            results["add"] = bench_add_read(carom, np, args)
        if "step" in cases:
            results["step"] = bench_step(carom, args, scratch)
        if "gas" in cases:
            results["gas"] = bench_gas(carom, args)
    results["ended_utc"] = time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime())
    results["load_average_after"] = os.getloadavg()
    print_report(results)
    if args.json:
        with open(args.json, "w") as f:
            json.dump(results, f, indent=1)
            f.write("\n")


if __name__ == "__main__":
    main()
