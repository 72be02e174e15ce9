"""GSD trajectories in HOOMD-blue's schema, for OVITO, VMD, freud or HOOMD itself.

``write(path, source)`` takes a ``carom.run_scene`` result, a ``carom.World`` or a list of
Worlds (each a separate snapshot, e.g. ``carom.World.load(world.save())`` after each run) and
writes one frame each: a 2D box ``[Lx, Ly, 0, 0, 0, 0]`` (``configuration/dimensions`` = 2),
positions as float32 ``(N, 3)`` with z = 0, centred in the box as HOOMD expects
(``[-L/2, L/2)``), velocities, diameters, one particle type ``"A"`` and the periodic images.
A few ``log/carom/*`` entries (scene time, box centre, scene ball index) let ``read`` give the
positions back in carom's own coordinates. It needs Debian's python3-gsd (``import gsd.hoomd``).
"""

import numpy as np

__all__ = ["write", "read"]


def _hoomd():
    import gsd
    import gsd.hoomd

    # gsd 3 names a frame Frame and drops the "b" of the file modes; gsd 2 has Snapshot and "wb".
    frame_type = getattr(gsd.hoomd, "Frame", None) or gsd.hoomd.Snapshot
    major = int(gsd.__version__.split(".")[0])
    return gsd.hoomd, frame_type, ("w" if major >= 3 else "wb"), ("r" if major >= 3 else "rb")


def _box_of(boundary, lower, upper, positions, radii):
    """The box's lower corner and side lengths; an open world's is the extent of its balls."""
    lower = np.asarray(lower, dtype=float)
    upper = np.asarray(upper, dtype=float)
    if boundary != "open" and np.all(upper > lower):
        return lower, upper - lower
    live = ~np.isnan(radii)
    if not live.any():
        return np.zeros(2), np.ones(2)
    low = np.min(positions[live] - radii[live, None], axis=0)
    high = np.max(positions[live] + radii[live, None], axis=0)
    return low, np.maximum(high - low, 1e-300)


def _frames_of_run(run):
    """Frames of a carom.run_scene result: the balls still in play in each, images unwrapped
    from one frame to the next (so a ball must move less than half a side between frames)."""
    positions = np.asarray(run["positions"], dtype=float)
    velocities = np.asarray(run["velocities"], dtype=float)
    radii = np.asarray(run["radii"], dtype=float)
    boundary = run.get("boundary", "open")
    lower, upper = run.get("box", ((0.0, 0.0), (0.0, 0.0)))
    every = positions.reshape(-1, 2)
    box_lower, side = _box_of(boundary, lower, upper, every, radii.reshape(-1))
    image = np.zeros(positions.shape[1:], dtype=np.int64)
    for k in range(positions.shape[0]):
        if boundary == "periodic" and k > 0:
            moved = positions[k] - positions[k - 1]
            jumps = np.nan_to_num(np.rint(moved / side)).astype(np.int64)
            image -= jumps
        live = np.flatnonzero(~np.isnan(radii[k]))
        yield {
            "time": float(run["times"][k]),
            "positions": positions[k, live],
            "velocities": velocities[k, live],
            "radii": radii[k, live],
            "image": image[live],
            "ball": live,
            "lower": box_lower,
            "side": side,
            "periodic": boundary == "periodic",
        }


def _frame_of_world(world):
    d = world.settings
    positions = world.positions
    radii = world.radii
    lower, side = _box_of(d["boundary"], d["lower"], d["upper"], positions, radii)
    return {
        "time": world.time,
        "positions": positions,
        "velocities": world.velocities,
        "radii": radii,
        "image": np.zeros((len(radii), 2), dtype=np.int64),  # a World does not keep its wraps
        "ball": np.arange(len(radii)),
        "lower": lower,
        "side": side,
        "periodic": d["boundary"] == "periodic",
    }


def _frames(source):
    if isinstance(source, dict):
        return list(_frames_of_run(source))
    if hasattr(source, "positions") and hasattr(source, "radii"):
        return [_frame_of_world(source)]
    return [_frame_of_world(world) for world in source]


def write(path, source):
    """Writes source (a run_scene result, a World or a list of Worlds) to the GSD file path."""
    hoomd, frame_type, write_mode, _ = _hoomd()
    with hoomd.open(name=str(path), mode=write_mode) as trajectory:
        for step, f in enumerate(_frames(source)):
            n = len(f["radii"])
            side = f["side"]
            centre = f["lower"] + side / 2
            position = np.zeros((n, 3), dtype=np.float32)
            relative = f["positions"] - centre
            if f["periodic"]:
                relative = (relative + side / 2) % side - side / 2
            position[:, :2] = relative
            # float32 can round a coordinate just below L/2 up to L/2, which is outside HOOMD's
            # half-open box; -L/2 is the same point of the periodic box.
            half = (side / 2).astype(np.float32)
            for axis in range(2):
                position[position[:, axis] >= half[axis], axis] = -half[axis]
            velocity = np.zeros((n, 3), dtype=np.float32)
            velocity[:, :2] = f["velocities"]
            image = np.zeros((n, 3), dtype=np.int32)
            image[:, :2] = f["image"]

            frame = frame_type()
            frame.configuration.step = step
            frame.configuration.dimensions = 2
            frame.configuration.box = [float(side[0]), float(side[1]), 0.0, 0.0, 0.0, 0.0]
            frame.particles.N = n
            frame.particles.types = ["A"]
            frame.particles.typeid = np.zeros(n, dtype=np.uint32)
            frame.particles.position = position
            frame.particles.velocity = velocity
            frame.particles.diameter = (2 * f["radii"]).astype(np.float32)
            frame.particles.image = image
            frame.log["carom/time"] = np.array([f["time"]], dtype=np.float64)
            frame.log["carom/centre"] = np.asarray(centre, dtype=np.float64)
            frame.log["carom/ball"] = np.asarray(f["ball"], dtype=np.int64)
            trajectory.append(frame)


def read(path):
    """A GSD file's frames as arrays: times (F,), box (F, 2) side lengths, and positions,
    velocities (F, N, 2), radii and image (F, N[, 2]) in carom's coordinates (the box centre
    added back), N the most balls of any frame, each ball at its index (NaN rows where absent).
    Files not written by carom read with times = step and the HOOMD coordinates."""
    hoomd, _, _, read_mode = _hoomd()
    with hoomd.open(name=str(path), mode=read_mode) as trajectory:
        frames = list(trajectory)
    balls = [
        np.asarray(f.log["carom/ball"], dtype=np.int64)
        if "carom/ball" in f.log
        else np.arange(f.particles.N)
        for f in frames
    ]
    count = max((int(b.max()) + 1 for b in balls if len(b)), default=0)
    shape = (len(frames), count)
    out = {
        "times": np.empty(len(frames)),
        "box": np.empty((len(frames), 2)),
        "positions": np.full(shape + (2,), np.nan),
        "velocities": np.full(shape + (2,), np.nan),
        "radii": np.full(shape, np.nan),
        "image": np.zeros(shape + (2,), dtype=np.int64),
    }
    for k, (f, ball) in enumerate(zip(frames, balls)):
        log = f.log
        out["times"][k] = log["carom/time"][0] if "carom/time" in log else f.configuration.step
        out["box"][k] = f.configuration.box[:2]
        centre = np.asarray(log["carom/centre"]) if "carom/centre" in log else np.zeros(2)
        out["positions"][k, ball] = f.particles.position[:, :2].astype(np.float64) + centre
        out["velocities"][k, ball] = f.particles.velocity[:, :2]
        out["radii"][k, ball] = f.particles.diameter.astype(np.float64) / 2
        out["image"][k, ball] = f.particles.image[:, :2]
    return out
