"""Moving walls: segments and arcs that translate and turn about a pivot for a duration
(World.set_wall_motion), met at exact times and bouncing balls with their own velocity."""
import math

import pytest

import carom


def test_a_rising_paddle_meets_a_ball_at_rest_and_sends_it_off_at_twice_its_speed():
    world = carom.World()
    paddle = world.add_segment((-1.0, 0.0), (1.0, 0.0))
    ball = world.add_ball((0.0, 2.0), radius=0.5)
    world.set_wall_motion(paddle, velocity=(0.0, 1.0))
    world.run_until(2.0)
    [contact] = world.contacts
    assert contact["time"] == 1.5 and contact["wall"] == paddle
    assert world.velocity(ball) == (0.0, 2.0)
    assert world.wall(paddle) == {"kind": "segment", "a": (-1.0, 2.0), "b": (1.0, 2.0)}


def test_a_flipper_meets_a_ball_at_rest_at_the_closed_form_angle():
    world = carom.World()
    flipper = world.add_segment((0.0, 0.0), (2.0, 0.0))
    world.add_ball((1.0, 1.5), radius=0.5)
    world.set_wall_motion(flipper, carom.WallMotion(angular_velocity=1.0, pivot=(0.0, 0.0)))
    world.run_collisions(1, 10.0)
    expected = math.atan2(1.5, 1.0) - math.asin(0.5 / math.sqrt(3.25))
    assert world.contacts[0]["time"] == pytest.approx(expected, abs=1e-12)


def test_the_motion_left_shrinks_and_the_wall_stops_where_its_duration_ends():
    world = carom.World()
    arm = world.add_segment((0.0, 0.0), (2.0, 0.0))
    motion = carom.WallMotion(angular_velocity=2.0, pivot=(0.0, 0.0), duration=0.25)
    assert motion.moves() and "WallMotion" in repr(motion)
    world.set_wall_motion(arm, motion)
    assert world.wall_motion(arm) == motion
    world.step(0.1)
    assert world.wall_motion(arm).duration == pytest.approx(0.15)
    world.step(1.0)
    assert world.wall_motion(arm) == carom.WallMotion(duration=0.0)
    shape = world.wall(arm)
    assert shape["b"][0] == pytest.approx(2.0 * math.cos(0.5), abs=1e-15)
    assert shape["b"][1] == pytest.approx(2.0 * math.sin(0.5), abs=1e-15)


def test_a_removed_wall_is_met_by_nothing():
    world = carom.World()
    wall = world.add_segment((0.0, -1.0), (0.0, 1.0))
    ball = world.add_ball((-2.0, 0.0), velocity=(1.0, 0.0), radius=0.5)
    world.remove_wall(wall)
    assert world.wall_removed(wall) and world.wall_count == 1
    world.run_until(4.0)
    assert len(world.contacts) == 0
    assert world.position(ball) == (2.0, 0.0)


def test_bad_motions_are_refused_naming_the_argument():
    world = carom.World(boundary="box", lower=(-5.0, -5.0), upper=(5.0, 5.0))
    wall = world.add_segment((0.0, 0.0), (1.0, 0.0))
    sensor = world.add_segment_sensor((0.0, 1.0), (1.0, 1.0))
    for side in range(4):
        with pytest.raises(carom.InvalidArgument, match=f"wall = {side}: .*box boundary"):
            world.set_wall_motion(side, velocity=(1.0, 0.0))
    with pytest.raises(carom.InvalidArgument, match=f"wall = {sensor}: .*sensor"):
        world.set_wall_motion(sensor, carom.WallMotion(velocity=(1.0, 0.0)))
    with pytest.raises(carom.InvalidArgument, match="motion.velocity"):
        world.set_wall_motion(wall, velocity=(math.nan, 0.0))
    with pytest.raises(carom.InvalidArgument, match="motion.angular_velocity"):
        world.set_wall_motion(wall, angular_velocity=math.nan)
    with pytest.raises(carom.InvalidArgument, match="motion.duration"):
        world.set_wall_motion(wall, angular_velocity=1.0, duration=-1.0)
    with pytest.raises(carom.InvalidArgument, match="wall = 2: .*box boundary"):
        world.remove_wall(2)
    assert world.wall_motion(wall) == carom.WallMotion(duration=0.0)


def test_save_and_load_continue_a_motion_bit_for_bit(tmp_path):
    world = carom.World(boundary="box", lower=(-10.0, -10.0), upper=(10.0, 10.0))
    bar = world.add_segment((-4.0, 0.0), (3.0, 0.0))
    world.set_wall_motion(bar, angular_velocity=1.5, pivot=(-0.5, 0.0), duration=3.0)
    world.add_ball((0.0, 5.0), velocity=(0.3, -2.0), radius=0.5)
    world.add_ball((2.0, -6.0), velocity=(-1.0, 2.5), radius=0.5)
    world.step(1.0)
    path = tmp_path / "world.carom"
    world.save(str(path))
    resumed = carom.World.load(str(path))
    assert resumed.wall_motion(bar) == world.wall_motion(bar)
    assert resumed.wall_motion(bar).moves() and resumed.wall_motion(bar).duration == 2.0
    assert resumed.wall(bar) == world.wall(bar)
    world.step(4.0)
    resumed.step(4.0)
    assert world.wall_motion(bar) == resumed.wall_motion(bar)
    assert world.wall(bar) == resumed.wall(bar)
    assert (world.positions == resumed.positions).all()
