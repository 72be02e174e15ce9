"""Inelastic balls dropped under gravity through a two-stage funnel of segments.

A World with gravity and restitution below 1: the balls fall, bounce off the sloping segments and
one another, and settle into piles. Under gravity a contact too slow to lift a ball off a still
support leaves the ball sliding or resting instead of bouncing for ever, so the pile comes to rest
in finite time and then costs no events. The script records every ball's height and the total
energy (kinetic + potential) at each frame, checks that the energy never rises, prints how many
balls rest at the end, and saves gravity_drop.png (the final piles, heights and energy over time).
Nothing here has friction: a ball alone on the level floor keeps its sideways speed until the side
walls take it, so it rests later than one held in a pile. The engine solves no contact forces:
balls pressed together that nothing can carry stop where they stand (docs/world.md, "Resting and
sliding"), which is why a few can come to rest on a slope.

    PYTHONPATH=build/release/python python3 examples/python/gravity_drop.py [--balls 60] [--out DIR]
"""
import argparse
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import EllipseCollection  # noqa: E402
import numpy as np  # noqa: E402

import carom  # noqa: E402

WIDTH, HEIGHT, RADIUS = 20.0, 30.0, 0.45
FUNNELS = [((0, 14), (8, 10)), ((20, 14), (12, 10)),  # upper funnel, a gap of 4 at y = 10
           ((6, 5), (9, 4)), ((14, 5), (11, 4))]      # lower funnel, a gap of 2 at y = 4


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--balls", type=int, default=60, help="balls, in rows of 10 (at most 120)")
    parser.add_argument("--until", type=float, default=10.0, help="seconds")
    parser.add_argument("--frame", type=float, default=0.02, help="seconds between frames")
    parser.add_argument("--restitution", type=float, default=0.6)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--out", type=pathlib.Path, default=pathlib.Path("."))
    args = parser.parse_args()

    world = carom.World(boundary="box", lower=(0, 0), upper=(WIDTH, HEIGHT),
                        gravity=(0, -9.81), restitution=args.restitution)
    for a, b in FUNNELS:
        world.add_segment(a, b)
    # Rows of 10 above the upper funnel, with a little random sideways motion.
    rows = -(-args.balls // 10)
    x, y = np.meshgrid(np.linspace(2, 18, 10), np.linspace(18, HEIGHT - 2, rows))
    start = np.column_stack([x.ravel(), y.ravel()])[: args.balls]
    rng = np.random.default_rng(args.seed)
    world.add_balls(start, velocities=rng.normal(scale=0.5, size=start.shape), radii=RADIUS)

    times = np.arange(0.0, args.until + args.frame / 2, args.frame)
    heights = np.empty((len(times), args.balls))
    energy = np.empty(len(times))
    for k, t in enumerate(times):
        world.run_until(t)
        heights[k] = world.positions[:, 1]
        energy[k] = world.kinetic_energy + world.potential_energy

    rise = np.diff(energy).max()
    # A resting ball's velocity is exactly zero; one sliding on the floor is not resting.
    resting = int((np.linalg.norm(world.velocities, axis=1) == 0).sum())
    print(f"{args.balls} balls, restitution {args.restitution}, {world.collision_count} contacts")
    print(f"energy: {energy[0]:.4f} at the start, {energy[-1]:.4f} at {times[-1]:g} s "
          f"({100 * (1 - energy[-1] / energy[0]):.1f}% lost)")
    print(f"largest rise between frames: {rise:.3e} (relative {rise / energy[0]:.1e})")
    print(f"resting: {resting} of {args.balls}")
    print(f"overlaps: {world.audit()}")

    fig = plt.figure(figsize=(11, 6), layout="constrained")
    left, right = fig.subfigures(1, 2, width_ratios=[1, 1.4])
    pile = left.subplots()
    pile.add_collection(EllipseCollection(2 * world.radii, 2 * world.radii, 0, units="xy",
                                          offsets=world.positions, offset_transform=pile.transData))
    for a, b in FUNNELS:
        pile.plot(*np.transpose([a, b]), color="black", lw=2)
    pile.set_aspect("equal")
    pile.set_xlim(0, WIDTH)
    pile.set_ylim(0, HEIGHT)
    pile.set_title(f"at {times[-1]:g} s: {resting} of {args.balls} resting")
    top, bottom = right.subplots(2, 1, sharex=True)
    top.plot(times, heights, lw=0.6)
    for level in (10, 4):
        top.axhline(level, color="0.6", ls=":", lw=1)
    top.set_ylabel("height")
    top.set_title(f"{args.balls} balls dropped through two funnels (e = {args.restitution})")
    bottom.plot(times, energy)
    bottom.set_xlabel("time")
    bottom.set_ylabel("kinetic + potential energy")
    args.out.mkdir(parents=True, exist_ok=True)
    fig.savefig(args.out / "gravity_drop.png", dpi=120, bbox_inches="tight")
    print(f"wrote {args.out / 'gravity_drop.png'}")


if __name__ == "__main__":
    main()
