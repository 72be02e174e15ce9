"""A billiards break, contact by contact.

Builds a World from examples/billiards-frictionless.json (15 racked balls, the cue ball at 6 m/s, cushions as
segments, pockets as immovable balls), runs it with contact recording, and prints the first
contacts of the break: when, what met what, the approach speed and the impulse. A pocket's
contact ends a run (stop_reason "stop_condition"); the script takes the ball off the table and
goes on. Saves billiards_break.png with every ball's path.

    PYTHONPATH=build/release/python python3 examples/python/billiards_break.py [--out DIR]
"""
import argparse
import json
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import carom  # noqa: E402

SCENE = pathlib.Path(__file__).resolve().parents[1] / "billiards-frictionless.json"
BOX_WALLS = 4  # a box world's own walls are walls 0-3; the scene's cushions come after


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", type=pathlib.Path, default=SCENE)
    parser.add_argument("--until", type=float, default=3.0, help="seconds of play")
    parser.add_argument("--frame", type=float, default=0.005,
                        help="seconds between the points of the drawn paths")
    parser.add_argument("--contacts", type=int, default=20, help="contacts to print")
    parser.add_argument("--out", type=pathlib.Path, default=pathlib.Path("."))
    args = parser.parse_args()

    scene = carom.load_scene(args.scene)
    spec = json.loads(scene.to_json())  # names, colours and cushions, for labels and the picture
    names = np.array([b.get("name", str(i)) for i, b in enumerate(spec["balls"])])
    labels = np.append(names, "pocket")  # labels[-1]: what scene_index gives a pocket
    world, ids = carom.make_world(scene)
    world.contact_recording = True

    # ids[i] is scene ball i; every other id in the world is a pocket.
    sorter = np.argsort(ids)

    def scene_index(world_ids):
        at = np.searchsorted(ids, world_ids, sorter=sorter).clip(0, len(ids) - 1)
        return np.where(ids[sorter[at]] == world_ids, sorter[at], -1)

    times = np.arange(0.0, args.until + args.frame / 2, args.frame)
    paths = np.full((len(times), len(ids), 2), np.nan)
    contacts, potted = [], []
    for k, t in enumerate(times):
        while True:
            world.run_until(t)
            contacts.append(world.contacts)  # contacts holds only the last run's
            if world.stop_reason != "stop_condition":
                break
            last = world.contacts[-1]
            ball = last["a"] if scene_index(last["a"]) >= 0 else last["b"]
            potted.append((world.time, labels[scene_index(ball)]))
            world.remove_ball(int(ball))
        index = scene_index(world.ids)
        live = index >= 0
        paths[k, index[live]] = world.positions[live]
    contacts = np.concatenate(contacts)

    print(f"{len(contacts)} contacts in {args.until:g} s; the first {args.contacts}:")
    print(f"{'time s':>9}  {'kind':<8} {'a':>4} {'b':>8} {'speed m/s':>10} {'impulse N s':>12}")
    first = contacts[: args.contacts]
    a = labels[scene_index(first["a"])]
    b = np.where(first["kind"] == 1, np.where(first["wall"] >= BOX_WALLS, "cushion", "box"),
                 labels[scene_index(first["b"])])
    kind = np.where(first["kind"] == 0, "ball", "wall")
    for row in zip(first["time"], kind, a, b, first["approach_speed"], first["impulse"]):
        print("{:9.5f}  {:<8} {:>4} {:>8} {:10.4f} {:12.5f}".format(*row))
    for time, name in potted:
        print(f"potted: ball {name} at {time:.4f} s")

    fig, ax = plt.subplots(figsize=(9, 5))
    lower, upper = spec["world"]["lower"], spec["world"]["upper"]
    ax.add_patch(plt.Rectangle(lower, upper[0] - lower[0], upper[1] - lower[1], color="#1d6b3a"))
    for wall in spec.get("segments", []):
        ax.plot(*np.transpose([wall["a"], wall["b"]]), color="#5a3a1a", lw=3)
    for pocket in spec.get("pockets", []):
        ax.add_patch(plt.Circle(pocket["position"], pocket["radius"], color="black"))
    colours = [b.get("color", "white") for b in spec["balls"]]
    for path, colour in zip(paths.transpose(1, 0, 2), colours):
        ax.plot(path[:, 0], path[:, 1], color=colour, lw=1)
    last = paths[-1]
    on_table = ~np.isnan(last[:, 0])
    ax.scatter(last[on_table, 0], last[on_table, 1], c=np.array(colours)[on_table],
               edgecolors="black", s=40, zorder=3)
    ax.set_aspect("equal")
    ax.set_xlim(lower[0], upper[0])
    ax.set_ylim(lower[1], upper[1])
    ax.set_title(f"The break, {args.until:g} s ({len(potted)} potted)")
    args.out.mkdir(parents=True, exist_ok=True)
    fig.savefig(args.out / "billiards_break.png", dpi=120, bbox_inches="tight")
    print(f"wrote {args.out / 'billiards_break.png'}")


if __name__ == "__main__":
    main()
