"""The billiards table from Python (docs/pool.md): carom.Table, a ball's spin and motion state, the
cue's strike, the changes of state as MotionEvent, and a scene on a table run until rest."""
import pathlib
import pickle

import numpy as np
import pytest

import carom

EXAMPLES = pathlib.Path(__file__).resolve().parents[2] / "examples"
R = 0.028575  # a pool ball, in metres


def test_a_stun_shot_rolls_at_the_textbook_time_with_five_sevenths_of_its_speed():
    table = carom.Table()
    world = carom.World(table=table)
    assert world.settings["table"] == table
    ball = world.add_ball((0.0, 0.0), radius=R, mass=0.17)
    assert world.motion_state(ball) == "stationary" and world.at_rest()
    world.strike(ball, speed=2.0)  # through the centre: no spin
    v = world.velocity(ball)[0]
    assert world.motion_state(ball) == "sliding" and world.spin(ball) == (0.0, 0.0, 0.0)
    world.run_until(2.0 * v / (7.0 * table.sliding_friction * table.g) + 1e-9)
    assert world.motion_state(ball) == "rolling"
    assert world.velocity(ball)[0] == pytest.approx(5.0 / 7.0 * v, rel=1e-9)
    [event] = world.motion_events
    assert (event.from_state, event.to_state) == ("sliding", "rolling")
    assert event.ball == ball and "MotionEvent" in repr(event)
    world.run_collisions(10)
    assert world.at_rest() and world.stop_reason == "no_more_contacts"


def test_spin_is_set_kept_through_pickle_and_refused_without_a_table():
    world = carom.World(table=carom.Table(sliding_friction=0.25))
    ball = world.add_ball((0.0, 0.0), radius=R, spin=(0.0, 0.0, 30.0))
    assert world.motion_state(ball) == "spinning"
    world.set_spin(ball, (1.0, -2.0, 3.0))
    assert world.spin(ball) == (1.0, -2.0, 3.0)
    world.step(0.01)
    copy = pickle.loads(pickle.dumps(world))
    assert copy.spin(ball) == world.spin(ball)
    assert copy.settings["table"].sliding_friction == 0.25
    plain = carom.World()
    with pytest.raises(carom.InvalidArgument):
        plain.add_ball((0.0, 0.0), spin=(0.0, 0.0, 1.0))
    other = plain.add_ball((0.0, 0.0))
    with pytest.raises(carom.InvalidArgument) as refused:
        plain.strike(other, speed=1.0)
    assert refused.value.argument == "WorldDef::table"
    with pytest.raises(carom.InvalidArgument):
        world.strike(ball, speed=1.0, side=R)  # the tip off the ball


def test_a_table_refuses_gravity_and_its_fields_read_back():
    with pytest.raises(carom.InvalidArgument):
        carom.World(table=carom.Table(), gravity=(0.0, -9.81))
    with pytest.raises(carom.InvalidArgument):
        carom.World(table=carom.Table(cushion_height=0.3))
    table = carom.Table(g=10.0, contact_time=0.0)
    assert table.g == 10.0 and "Table(" in repr(table) and table != carom.Table()


def test_the_example_break_is_struck_by_its_shot_and_comes_to_rest():
    run = carom.run_scene(carom.load_scene(EXAMPLES / "billiards.json"), until=12.0,
                          frame_interval=1.0)
    first, last = run["velocities"][0], run["velocities"][-1]
    assert np.all(first == 0.0)  # the shot is struck when the run starts
    on_table = ~np.isnan(last[:, 0])
    assert 0 < on_table.sum() <= 16
    assert np.all(last[on_table] == 0.0)
    moved = np.linalg.norm(run["positions"][-1][on_table] - run["positions"][0][on_table], axis=1)
    assert np.count_nonzero(moved) >= 10


def test_a_standard_table_is_a_scene_a_shot_runs_on():
    scene = carom.pool_table_scene(size="8ft", rack="nine")
    assert scene.ball_count == 10 and scene.pocket_count == 6
    world, ids = carom.make_world(scene)
    world.strike(int(ids[0]), speed=4.0, height=0.01)
    world.run_collisions(1_000_000)
    assert world.at_rest()
    with pytest.raises(carom.InvalidArgument):
        carom.pool_table_scene(size="10ft")
