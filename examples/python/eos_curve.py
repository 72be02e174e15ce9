"""The equation of state of the hard-disk fluid.

Runs carom.eos (an event-driven gas of equal disks at each packing fraction eta) and compares the
compressibility factor Z = PA/(NkT) with Henderson's equation of state,
Z = (1 + eta^2/8) / (1 - eta)^2, which is within a percent of simulation up to eta ~ 0.6. Prints a
table and saves eos.png (Z against eta, with the runs' error bars).

    PYTHONPATH=build/release/python python3 examples/python/eos_curve.py [--quick] [--out DIR]
"""
import argparse
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import carom  # noqa: E402


def henderson(eta):
    return (1 + eta**2 / 8) / (1 - eta) ** 2


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--etas", type=float, nargs="+",
                        default=[0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.65],
                        help="packing fractions (below ~0.7, where the fluid ends)")
    parser.add_argument("--n", type=int, default=400, help="disks")
    parser.add_argument("--collisions", type=int, default=500,
                        help="collisions a disk measured, per point")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--quick", action="store_true",
                        help="three points with 100 disks: a few tenths of a second")
    parser.add_argument("--out", type=pathlib.Path, default=pathlib.Path("."))
    args = parser.parse_args()
    if args.quick:
        args.etas, args.n, args.collisions = [0.1, 0.3, 0.5], 100, 200

    points = carom.eos(args.etas, n=args.n, collisions=args.collisions, seed=args.seed)["points"]
    eta = np.array([p["eta"] for p in points])
    z = np.array([p["Z"] for p in points])
    z_err = np.array([p["Z_err"] for p in points])
    z_h = henderson(eta)

    print(f"{args.n} disks, {args.collisions} collisions a disk per point")
    print(f"{'eta':>6} {'Z':>9} {'+-':>8} {'Henderson':>10} {'diff %':>7}")
    for row in zip(eta, z, z_err, z_h, 100 * (z / z_h - 1)):
        print("{:6.3f} {:9.4f} {:8.4f} {:10.4f} {:7.2f}".format(*row))

    fine = np.linspace(0, max(eta.max(), 0.7), 200)
    fig, ax = plt.subplots(figsize=(6, 4.5))
    ax.plot(fine, henderson(fine), color="0.5", label="Henderson (1975)")
    ax.errorbar(eta, z, yerr=z_err, fmt="o", capsize=3, label=f"carom, N = {args.n}")
    ax.set_xlabel(r"packing fraction $\eta$")
    ax.set_ylabel(r"$Z = PA/NkT$")
    ax.set_title("Hard-disk equation of state")
    ax.legend()
    args.out.mkdir(parents=True, exist_ok=True)
    fig.savefig(args.out / "eos.png", dpi=120, bbox_inches="tight")
    print(f"wrote {args.out / 'eos.png'}")


if __name__ == "__main__":
    main()
