"""A hard-disk gas written as a GSD trajectory, and read back with the gsd package.

Runs a periodic gas (a scene of randomly placed disks with Maxwell-Boltzmann velocities) with
carom.run_scene, writes it with carom.gsd.write in HOOMD-blue's schema (which OVITO, VMD, freud
and HOOMD read), then opens the file with gsd.hoomd alone, as any of those tools would: it prints
the frame count, the box and the particles, and the mean squared displacement, unwrapped across
the periodic edges with the file's images. Writes gas.gsd.

    PYTHONPATH=build/release/python python3 examples/python/gsd_trajectory.py [--n 200] [--out DIR]
"""
import argparse
import json
import pathlib

import gsd
import gsd.hoomd
import numpy as np

import carom


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=200, help="disks")
    parser.add_argument("--eta", type=float, default=0.3, help="packing fraction (at most 0.5)")
    parser.add_argument("--frames", type=int, default=101)
    parser.add_argument("--interval", type=float, default=0.1, help="time between frames")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--out", type=pathlib.Path, default=pathlib.Path("."))
    args = parser.parse_args()

    # Unit diameter; the cell is sized for the packing fraction.
    side = float(np.sqrt(args.n * np.pi * 0.25 / args.eta))
    scene = carom.parse_scene(json.dumps({
        "carom_scene": 1,
        "description": f"{args.n} hard disks at packing fraction {args.eta}, kT = 1",
        "world": {"boundary": "periodic", "lower": [0, 0], "upper": [side, side]},
        "generators": [{"placement": "random", "count": args.n, "radius": 0.5, "seed": args.seed,
                        "velocity": {"distribution": "maxwell_boltzmann", "temperature": 1,
                                     "zero_momentum": True}}],
    }))
    run = carom.run_scene(scene, until=(args.frames - 1) * args.interval,
                          frame_interval=args.interval)
    args.out.mkdir(parents=True, exist_ok=True)
    path = args.out / "gas.gsd"
    carom.gsd.write(path, run)

    # gsd 3 dropped the "b" of gsd 2's file modes.
    mode = "r" if int(gsd.__version__.split(".")[0]) >= 3 else "rb"
    with gsd.hoomd.open(name=str(path), mode=mode) as trajectory:
        frames, first, last = len(trajectory), trajectory[0], trajectory[-1]
        lengths = np.array(first.configuration.box[:3])
        unwrapped = [f.particles.position + f.particles.image * lengths for f in (first, last)]
    elapsed = run["times"][-1] - run["times"][0]
    msd = np.mean(np.sum((unwrapped[1] - unwrapped[0]) ** 2, axis=1))
    print(f"wrote {path}")
    print(f"frames: {frames}")
    print(f"particles: {first.particles.N}, box {lengths[0]:.3f} x {lengths[1]:.3f}")
    print(f"collisions: {len(run['contacts'])}")
    # Ballistic at first (msd = 2 kT t^2 / m), diffusive (msd = 4 D t) after many collisions.
    print(f"mean squared displacement after {elapsed:g}: {msd:.4f} "
          f"(msd / 4t = {msd / (4 * elapsed):.4f})")


if __name__ == "__main__":
    main()
