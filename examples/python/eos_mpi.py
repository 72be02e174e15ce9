"""A dense equation-of-state sweep with seeds, shared among MPI ranks and kept as it goes.

Each packing fraction is run from several seeds (carom.eos(seeds=K)); the runs are shared among
the ranks of MPI.COMM_WORLD, and each run is kept in OUT/points as it ends, so that a sweep
stopped or killed and started again runs only what is missing. Rank 0 prints, for each point, Z
with the error of one run's block averages beside the error between the seeds: where the two
agree, one run's error bar is honest. Without mpirun (or without mpi4py) it runs alone.

    mpirun -n 4 python3 examples/python/eos_mpi.py --out sweep
    PYTHONPATH=build/release/python python3 examples/python/eos_mpi.py --quick
"""
import argparse
import pathlib

import carom

try:
    from mpi4py import MPI
except ImportError:  # Debian's python3-mpi4py is not installed: one process
    MPI = None


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--etas", type=float, nargs="+", default=[0.60, 0.65, 0.68, 0.70],
                        help="packing fractions")
    parser.add_argument("--n", type=int, default=1024, help="disks")
    parser.add_argument("--seeds", type=int, default=8, help="runs a point, from seeds 1, 2, ...")
    parser.add_argument("--collisions", type=int, default=500,
                        help="collisions a disk measured, per run")
    parser.add_argument("--threads", type=int, default=1, help="runs at once in each rank")
    parser.add_argument("--quick", action="store_true",
                        help="two points, 100 disks, 4 seeds: a second or so")
    parser.add_argument("--out", type=pathlib.Path, default=pathlib.Path("."))
    args = parser.parse_args()
    if args.quick:
        args.etas, args.n, args.seeds, args.collisions = [0.3, 0.5], 100, 4, 200

    comm = MPI.COMM_WORLD if MPI is not None else None
    sweep = carom.eos(args.etas, n=args.n, seeds=args.seeds, collisions=args.collisions,
                      threads=args.threads, comm=comm, checkpoints=args.out / "points")
    if sweep is None:
        return  # another rank than 0: rank 0 prints
    ranks = comm.Get_size() if comm is not None else 1
    print(f"{args.n} disks, {args.seeds} seeds a point, {args.collisions} collisions a disk a run,"
          f" {ranks} rank{'s' if ranks > 1 else ''}; runs kept in {args.out / 'points'}")
    print(f"{'eta':>6} {'Z':>9} {'block err':>10} {'seed err':>9} {'ratio':>6}")
    for p in sweep["points"]:
        ratio = p["Z_seed_err"] / p["Z_err"]
        print(f"{p['eta']:6.3f} {p['Z']:9.4f} {p['Z_err']:10.4f} {p['Z_seed_err']:9.4f}"
              f" {ratio:6.2f}")


if __name__ == "__main__":
    main()
