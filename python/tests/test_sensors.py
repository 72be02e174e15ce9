"""Sensors: segments, arcs and discs that balls pass through, recording exact enters and exits
(World.sensor_events), and that may remove the ball that enters (a pocket)."""
import math

import numpy as np
import pytest

import carom


def test_a_bullet_through_a_thin_segment_sensor_enters_and_exits_at_exact_times():
    world = carom.World()
    bullet = world.add_ball((0.0, 0.0), velocity=(2e4, 0.0), radius=0.01)
    gate = world.add_segment_sensor((1e4, -1.0), (1e4, 1.0))
    assert world.sensor(gate) == "report"
    world.run_until(1.0)
    events = world.sensor_events
    assert [e.kind for e in events] == ["enter", "exit"]
    assert all(e.ball == bullet and e.sensor == gate and not e.removed for e in events)
    assert all(e.contacts_before == 0 for e in events)
    assert events[0].time == pytest.approx((1e4 - 0.01) / 2e4, abs=1e-11)
    assert events[1].time == pytest.approx((1e4 + 0.01) / 2e4, abs=1e-11)
    assert world.velocity(bullet) == (2e4, 0.0)  # passed through, not bounced
    assert "enter" in repr(events[0]) and "SensorEvent" in repr(events[0])


def test_a_remove_ball_disc_sensor_is_a_pocket():
    world = carom.World()
    ball = world.add_ball((0.0, 0.0), velocity=(1.0, 0.0), radius=0.5)
    pocket = world.add_disc_sensor((5.0, 0.0), 1.0, action="remove_ball")
    assert world.sensor(pocket) == "remove_ball"
    world.run_until(10.0)
    [event] = world.sensor_events
    assert event.kind == "enter" and event.removed and event.ball == ball
    assert event.time == pytest.approx(3.5, abs=1e-10)
    assert not world.contains(ball)
    assert len(world) == 0
    assert world.balls_in_sensor(pocket).size == 0


def test_balls_in_sensor_follow_enters_and_exits():
    world = carom.World()
    inside, outside = world.add_balls(np.array([[0.0, 0.0], [10.0, 0.0]]),
                                      velocities=[[1.0, 0.0], [0.0, 0.0]], radii=0.5)
    zone = world.add_disc_sensor((0.0, 0.0), 2.0)
    assert world.balls_in_sensor(zone).size == 0  # enters at the start of the next run
    world.run_until(1.0)
    assert world.balls_in_sensor(zone).tolist() == [inside]
    assert world.balls_in_sensor(zone).dtype == np.uint64
    assert [(e.kind, e.time) for e in world.sensor_events] == [("enter", 0.0)]
    world.run_until(3.0)
    assert world.balls_in_sensor(zone).size == 0
    [exit_] = world.sensor_events
    assert exit_.kind == "exit" and exit_.ball == inside
    assert exit_.time == pytest.approx(2.5, abs=1e-10)
    assert outside not in [e.ball for e in world.sensor_events]


def test_an_arc_sensor_counts_as_a_wall():
    world = carom.World()
    walls = world.wall_count
    arc = world.add_arc_sensor((0.0, 0.0), 3.0, -math.pi / 2, math.pi / 2)
    assert arc == walls and world.wall_count == walls + 1
    ball = world.add_ball((0.0, 0.0), velocity=(1.0, 0.0), radius=0.5)
    world.run_until(5.0)
    assert [(e.kind, e.ball) for e in world.sensor_events] == [("enter", ball), ("exit", ball)]
    assert world.sensor_events[0].time == pytest.approx(2.5, abs=1e-10)
    assert world.sensor_events[1].time == pytest.approx(3.5, abs=1e-10)


def test_a_plain_wall_is_no_sensor():
    world = carom.World()
    wall = world.add_segment((0, 0), (1, 0))
    assert world.sensor(wall) is None
    assert world.sensor_events == []


def test_bad_sensors_are_refused():
    world = carom.World()
    with pytest.raises(carom.InvalidArgument):
        world.add_disc_sensor((0, 0), 0.0)
    with pytest.raises(ValueError, match="action"):
        world.add_segment_sensor((0, 0), (1, 0), action="bounce")
    with pytest.raises(carom.InvalidArgument):
        world.sensor(world.wall_count)
    periodic = carom.World(boundary="periodic", lower=(0, 0), upper=(10, 10))
    with pytest.raises(carom.InvalidArgument):
        periodic.add_disc_sensor((5, 5), 1.0)


def test_sensor_events_are_read_only():
    world = carom.World()
    world.add_ball((0.0, 0.0), velocity=(1.0, 0.0), radius=0.5)
    world.add_disc_sensor((3.0, 0.0), 1.0)
    world.run_until(2.0)
    [event] = world.sensor_events
    with pytest.raises(AttributeError):
        event.time = 0.0
