"""The World from Python: balls in and state out as NumPy arrays, contacts as a structured
array, conservation, determinism, saving to bytes and files, pickle, stop conditions, the audit,
and Ctrl-C stopping a long run with the world consistent."""
import os
import pickle
import signal
import threading

import numpy as np
import pytest

import carom


def gas(n_side=10, seed=1, spacing=2.0):
    side = n_side * spacing
    world = carom.World(boundary="periodic", lower=(0, 0), upper=(side, side))
    grid = (np.arange(n_side) + 0.5) * spacing
    positions = np.stack(np.meshgrid(grid, grid), -1).reshape(-1, 2)
    velocities = np.random.default_rng(seed).normal(size=positions.shape)
    ids = world.add_balls(positions, velocities=velocities, radii=0.5)
    return world, ids


def test_arrays_in_and_out():
    world, ids = gas()
    assert ids.dtype == np.uint64 and ids.shape == (100,)
    assert (world.ids == ids).all()
    assert world.positions.shape == (100, 2)
    assert world.velocities.shape == (100, 2)
    assert (world.radii == 0.5).all() and (world.masses == 1.0).all()
    assert len(world) == 100
    assert world.settings["boundary"] == "periodic"
    world.set_velocities(np.zeros((100, 2)))
    assert world.kinetic_energy == 0.0
    world.set_positions(world.positions + 0.25)
    assert world.positions[0] == pytest.approx((1.25, 1.25))


def test_a_gas_conserves_energy_and_momentum_and_reports_its_contacts():
    world, _ = gas()
    energy = world.kinetic_energy
    momentum = np.array(world.momentum)
    assert world.run_collisions(2000) == 2000
    assert world.stop_reason == "none"
    assert world.kinetic_energy == pytest.approx(energy, rel=1e-12)
    assert np.allclose(world.momentum, momentum, atol=1e-12)
    contacts = world.contacts
    assert contacts.shape == (2000,)
    assert set(contacts.dtype.names) >= {"time", "kind", "a", "b", "point", "normal",
                                         "approach_speed", "impulse"}
    assert (np.diff(contacts["time"]) >= 0).all()
    assert (contacts["kind"] == 0).all()
    assert (contacts["approach_speed"] > 0).all()
    assert np.allclose(np.linalg.norm(contacts["normal"], axis=1), 1.0)
    assert world.audit() is None


def test_runs_are_deterministic_and_survive_save_load_and_pickle(tmp_path):
    first, _ = gas(seed=3)
    second, _ = gas(seed=3)
    first.run_until(5.0)
    second.run_until(5.0)
    assert (first.positions == second.positions).all()
    saved = first.save()
    assert isinstance(saved, bytes)
    copies = [carom.World.load(saved), pickle.loads(pickle.dumps(first))]
    first.save(tmp_path / "world.bin")
    copies.append(carom.World.load(tmp_path / "world.bin"))
    first.run_collisions(500)
    for copy in copies:
        copy.run_collisions(500)
        assert (copy.positions == first.positions).all()
        assert (copy.velocities == first.velocities).all()
    with pytest.raises(carom.InvalidArgument):
        carom.World.load(b"not a world")


def test_a_stop_condition_ends_the_run_after_its_contact():
    world, _ = gas()
    seen = []

    def stop(contact):
        seen.append(contact)
        return len(seen) == 7

    world.set_stop_condition(stop)
    world.run_collisions(100)
    assert world.stop_reason == "stop_condition"
    assert len(seen) == 7 and len(world.contacts) == 7
    assert seen[-1]["time"] == world.time
    assert seen[-1]["kind"] == "ball_ball"
    world.set_stop_condition(None)
    assert world.run_collisions(100) == 100


def test_walls_gravity_growth_and_the_thermostat():
    box = carom.World(boundary="box", lower=(0, 0), upper=(10, 10), gravity=(0, -9.81),
                      restitution=0.5)
    ball = box.add_ball((5, 8), radius=0.5)
    box.step(10.0)
    # Fallen and at rest on the floor.
    assert box.position(ball)[1] == pytest.approx(0.5, abs=1e-6)
    assert (box.contacts["kind"] == 1).all()

    world, _ = gas()
    world.set_growth_rate(0.01)
    radius = world.radii[0]
    world.run_until(10.0)
    assert world.radii[0] == pytest.approx(radius * 1.1, rel=1e-12)
    work = world.set_temperature(1.0)
    assert isinstance(work, float)
    # kT a ball about the centre of mass (unit masses): K − P²/(2M) = N·kT.
    momentum = np.array(world.momentum)
    assert world.kinetic_energy - momentum @ momentum / 200.0 == pytest.approx(100.0, rel=1e-9)
    assert world.audit() is None


def test_bad_calls_raise_value_errors():
    world, ids = gas()
    with pytest.raises(carom.InvalidArgument) as error:
        world.add_ball(tuple(world.positions[0]), radius=1)
    assert isinstance(error.value, ValueError)
    assert error.value.argument
    world.remove_ball(int(ids[0]))
    assert not world.contains(int(ids[0]))
    with pytest.raises(carom.InvalidArgument):
        world.velocity(int(ids[0]))  # a stale handle
    with pytest.raises(ValueError):
        world.add_balls(np.zeros((3, 3)))
    with pytest.raises(ValueError):
        carom.World(boundary="torus")
    with pytest.raises(carom.InvalidArgument):
        world.step(float("nan"))


def test_ctrl_c_stops_a_long_run_with_the_world_consistent():
    world, _ = gas(n_side=30)
    timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        world.run_collisions(10**12)
    timer.join()
    assert world.stop_reason == "interrupted"
    assert 0 < world.collision_count < 10**12
    assert world.audit() is None
    assert world.run_collisions(100) == 100
