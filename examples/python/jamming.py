"""Jamming a bidisperse hard-disk packing, and its contact network.

Places disks of two sizes (diameters 1 and 1.4, half of each) at random in a periodic cell, grows
them by Lubachevsky-Stillinger compression (carom.compress) until the reduced pressure reaches
10^12, and finds the contact network at the tolerance that pressure implies. A jammed
frictionless packing is isostatic: once the rattlers (disks with too few contacts to be held)
are taken out, the mean contact number Z of the held disks is 4 - 4/N_held in a periodic cell.
The two sizes keep it from crystallising, so eta ends near 0.84 with psi6 small. Prints eta,
the pressure, Z against the isostatic value, the rattlers and psi6, and saves jamming.png.

    PYTHONPATH=build/release/python python3 examples/python/jamming.py [--n 300] [--out DIR]
"""
import argparse
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import EllipseCollection, LineCollection  # noqa: E402
import numpy as np  # noqa: E402

import carom  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=300, help="disks")
    parser.add_argument("--rate", type=float, default=2e-3,
                        help="growth rate in thermal speeds; slower packs denser")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--out", type=pathlib.Path, default=pathlib.Path("."))
    args = parser.parse_args()

    world = carom.make_packing_world(n=args.n, mix=(1.4, 0.5), seed=args.seed)
    result = carom.compress(world, rate=args.rate)
    tolerance = carom.contact_tolerance_at_pressure(result["pressure"])
    net = carom.contact_network(world, tolerance=tolerance)
    held = args.n - net["rattlers"]

    print(f"{args.n} disks, rate {args.rate:g}: {result['end']} after "
          f"{result['collisions']} collisions (jammed: {result['jammed']})")
    print(f"eta       {result['eta']:.4f}")
    print(f"pressure  {result['pressure']:.3e}  (Z = PA/NkT)")
    print(f"Z         {net['Z']:.4f}  (isostatic 4 - 4/N_held = {4 - 4 / held:.4f})")
    print(f"rattlers  {net['rattlers']} of {args.n}")
    print(f"psi6      {carom.psi6(world):.4f}")

    cell = world.settings
    lower, upper = np.array(cell["lower"]), np.array(cell["upper"])
    side = upper - lower
    p, r = world.positions, world.radii
    # A bond across the periodic edge is drawn from its first disk to the second's nearest image.
    i, j = net["pairs"].T
    d = p[j] - p[i]
    d -= side * np.round(d / side)
    bonds = np.stack([p[i], p[i] + d], axis=1)

    fig, ax = plt.subplots(figsize=(7, 7))
    colours = np.where(net["rattler"], "0.85", np.where(r > r.min() * 1.2, "#e0a060", "#70a0d0"))
    # Images of the disks by the cell's sides, so that the edge disks are drawn whole.
    shifts = side * np.array([[x, y] for x in (-1, 0, 1) for y in (-1, 0, 1)])
    ax.add_collection(EllipseCollection(
        np.tile(2 * r, 9), np.tile(2 * r, 9), 0, units="xy",
        offsets=(p[None] + shifts[:, None]).reshape(-1, 2), offset_transform=ax.transData,
        facecolors=np.tile(colours, 9), edgecolors="0.3", linewidths=0.3))
    ax.add_collection(LineCollection(bonds, colors="#a01010", linewidths=1.2))
    ax.set_xlim(lower[0], upper[0])
    ax.set_ylim(lower[1], upper[1])
    ax.set_aspect("equal")
    ax.set_title(f"eta = {result['eta']:.4f}, Z = {net['Z']:.3f}, "
                 f"{net['rattlers']} rattlers (grey)")
    args.out.mkdir(parents=True, exist_ok=True)
    fig.savefig(args.out / "jamming.png", dpi=120, bbox_inches="tight")
    print(f"wrote {args.out / 'jamming.png'}")


if __name__ == "__main__":
    main()
