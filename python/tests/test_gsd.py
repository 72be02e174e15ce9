"""GSD trajectories: what carom.gsd.write puts in a file is HOOMD's schema as gsd.hoomd reads it
(N, a 2D box, positions centred in it, z = 0, images that unwrap the periodic moves), and
carom.gsd.read gives the run back to float32 precision."""
import os
import pathlib

import numpy as np
import pytest

import carom

hoomd = pytest.importorskip("gsd.hoomd")

EXAMPLES = pathlib.Path(
    os.environ.get("CAROM_EXAMPLES", pathlib.Path(__file__).parents[2] / "examples")
)


def open_for_reading(path):
    import gsd

    # gsd 3 dropped the "b" of gsd 2's file modes.
    mode = "r" if int(gsd.__version__.split(".")[0]) >= 3 else "rb"
    return hoomd.open(name=str(path), mode=mode)


def periodic_run():
    scene = carom.parse_scene(
        """{"carom_scene": 1,
            "world": {"boundary": "periodic", "lower": [10, -4], "upper": [30, 6]},
            "generators": [{"count": 40, "radius": 0.4,
                            "velocity": {"distribution": "maxwell_boltzmann",
                                         "temperature": 4}}]}"""
    )
    return carom.run_scene(scene, until=6.0, frame_interval=0.25)


def test_hoomd_reads_the_schema(tmp_path):
    run = periodic_run()
    path = tmp_path / "gas.gsd"
    carom.gsd.write(path, run)
    with open_for_reading(path) as trajectory:
        assert len(trajectory) == len(run["times"])
        for k, frame in enumerate(trajectory):
            assert frame.configuration.dimensions == 2
            assert list(frame.configuration.box) == [20, 10, 0, 0, 0, 0]
            assert frame.configuration.step == k
            assert frame.particles.N == 40
            p = frame.particles.position
            assert p.dtype == np.float32 and p.shape == (40, 3)
            assert (p[:, 2] == 0).all()
            assert (p[:, 0] >= -10).all() and (p[:, 0] < 10).all()
            assert (p[:, 1] >= -5).all() and (p[:, 1] < 5).all()
            assert frame.particles.types == ["A"]
            assert (frame.particles.typeid == 0).all()
            assert np.allclose(frame.particles.diameter, 0.8)
            assert frame.particles.velocity.shape == (40, 3)


def test_images_unwrap_the_periodic_moves(tmp_path):
    run = periodic_run()
    path = tmp_path / "gas.gsd"
    carom.gsd.write(path, run)
    with open_for_reading(path) as trajectory:
        frames = list(trajectory)
    side = np.array([20.0, 10.0])
    unwrapped = np.array(
        [f.particles.position[:, :2] + f.particles.image[:, :2] * side for f in frames]
    )
    assert np.abs(frames[-1].particles.image).max() > 0  # the balls did cross the box
    # A ball moves about its speed (~2) times 0.25 between frames; a missed wrap would show as a
    # jump of a whole side (20 or 10).
    steps = np.abs(np.diff(unwrapped, axis=0))
    assert (steps.max(axis=(0, 1)) < side / 4).all()


def test_read_gives_the_run_back(tmp_path):
    run = periodic_run()
    path = tmp_path / "gas.gsd"
    carom.gsd.write(path, run)
    back = carom.gsd.read(path)
    assert np.array_equal(back["times"], run["times"])
    assert back["positions"].shape == run["positions"].shape
    assert np.allclose(back["positions"], run["positions"], atol=1e-5)
    assert np.allclose(back["velocities"], run["velocities"], rtol=1e-6, atol=1e-6)
    assert np.allclose(back["radii"], run["radii"])
    assert (back["box"] == [20, 10]).all()


def test_potted_balls_leave_the_frames(tmp_path):
    scene = carom.load_scene(EXAMPLES / "billiards-frictionless.json")
    run = carom.run_scene(scene, until=3.0, frame_interval=1.0)
    assert run["potted"]
    path = tmp_path / "break.gsd"
    carom.gsd.write(path, run)
    with open_for_reading(path) as trajectory:
        counts = [frame.particles.N for frame in trajectory]
        box = list(trajectory[0].configuration.box)
    assert counts[0] == 16 and counts[-1] == 16 - len(run["potted"])
    assert box == pytest.approx([2.94, 1.67, 0, 0, 0, 0])
    back = carom.gsd.read(path)
    assert np.array_equal(np.isnan(back["radii"]), np.isnan(run["radii"]))
    assert np.allclose(back["positions"], run["positions"], atol=1e-6, equal_nan=True)


def test_worlds_as_snapshots(tmp_path):
    world = carom.World(boundary="box", lower=(0, 0), upper=(8, 4))
    positions = np.array([[1.0, 1.0], [6.0, 3.0]])
    world.add_balls(positions, velocities=np.array([[1.0, 0.5], [-1, 0]]), radii=0.5)
    snapshots = []
    for _ in range(3):
        snapshots.append(carom.World.load(world.save()))
        world.step(0.5)
    path = tmp_path / "box.gsd"
    carom.gsd.write(path, snapshots)
    back = carom.gsd.read(path)
    assert back["times"].tolist() == [0.0, 0.5, 1.0]
    assert np.allclose(back["positions"][2], snapshots[2].positions, atol=1e-6)
    carom.gsd.write(path, world)
    with open_for_reading(path) as trajectory:
        assert len(trajectory) == 1
        centred = trajectory[0].particles.position[:, :2]
        assert np.allclose(centred, world.positions - (4, 2), atol=1e-6)
