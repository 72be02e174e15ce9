"""The core queries from Python: the tutorial's case, the other shapes, the time form with
acceleration and growth, the bounces, the batch over NumPy arrays, and errors as ValueErrors."""
import math

import numpy as np
import pytest

import carom


def test_the_tutorials_two_moving_balls_meet_where_the_library_says():
    hit = carom.sweep_ball_ball(a=(0, 0, 1), move_a=(6, 2), b=(8, 3, 1.5), move_b=(-4, -1))
    assert hit.hit and bool(hit)
    assert 0.0 < hit.t < 1.0
    # At t the centres are the sum of the radii apart, along the normal.
    ax, ay = hit.a_at
    bx, by = hit.b_at
    assert math.hypot(bx - ax, by - ay) == pytest.approx(2.5, rel=1e-12)
    assert hit.a_at == pytest.approx((6 * hit.t, 2 * hit.t))
    nx, ny = hit.normal
    assert math.hypot(nx, ny) == pytest.approx(1.0)
    miss = carom.sweep_ball_ball((0, 0, 1), (1, 0), (0, 10, 1))
    assert not miss.hit and not miss


def test_other_shapes_and_the_time_form():
    assert carom.sweep_ball_point((0, 0, 1), (4, 0), (3, 0)).t == pytest.approx(0.5)
    segment = carom.sweep_ball_segment((0, 0, 1), (0, 4), ((-5, 3), (5, 3)))
    assert segment.t == pytest.approx(0.5)
    arc = carom.sweep_ball_arc((0, 0, 1), (4, 0), (10, 0, 7, math.pi / 2, 3 * math.pi / 2))
    assert arc.t == pytest.approx(0.5)
    # A ball dropped from rest 10 above a floor under g = 2 touches it when 9 = t², t = 3.
    fall = carom.time_of_impact_ball_segment((0, 10, 1), (0, 0), ((-5, 0), (5, 0)), 100,
                                             acceleration=(0, -2))
    assert fall.t == pytest.approx(3.0, rel=1e-12)
    # Two balls at rest 4 apart, radii 1, each growing at 0.5 a time unit: touching at t = 2.
    grow = carom.time_of_impact_ball_ball((0, 0, 1), (0, 0), (4, 0, 1), (0, 0), 10,
                                          growth_a=0.5, growth_b=0.5)
    assert grow.t == pytest.approx(2.0, rel=1e-12)


def test_bounces_keep_momentum_and_energy():
    r = carom.bounce((1, 0), 1.0, (-1, 0), 3.0, (1, 0))
    assert r.velocity_a[0] + 3 * r.velocity_b[0] == pytest.approx(1 - 3)
    energy = 0.5 * 1 + 0.5 * 3
    after = 0.5 * r.velocity_a[0] ** 2 + 1.5 * r.velocity_b[0] ** 2
    assert after == pytest.approx(energy)
    wall = carom.bounce_off_static((1, -1), 1.0, (0, -1), restitution=0.5)
    assert wall.velocity == pytest.approx((1, 0.5))
    post = carom.bounce((1, 0), 1.0, (0, 0), carom.IMMOVABLE, (1, 0))
    assert post.velocity_a == pytest.approx((-1, 0))


def test_the_batch_equals_the_one_pair_query_bit_for_bit():
    rng = np.random.default_rng(7)
    n = 2000
    a = np.column_stack([rng.uniform(-5, 5, (n, 2)), rng.uniform(0.1, 1, n)])
    b = np.column_stack([rng.uniform(-5, 5, (n, 2)), rng.uniform(0.1, 1, n)])
    move_a = rng.uniform(-6, 6, (n, 2))
    move_b = rng.uniform(-6, 6, (n, 2))
    t = carom.sweep_ball_ball_many(a, move_a, b, move_b)
    assert t.shape == (n,)
    hits = 0
    for i in range(n):
        one = carom.sweep_ball_ball(tuple(a[i]), tuple(move_a[i]), tuple(b[i]), tuple(move_b[i]))
        if one.hit:
            hits += 1
            assert t[i] == one.t
        else:
            assert t[i] == math.inf
    assert 100 < hits < n


def test_bad_input_is_a_value_error_naming_the_argument():
    with pytest.raises(carom.InvalidArgument) as error:
        carom.sweep_ball_ball((0, 0, -1), (1, 0), (3, 0, 1))
    assert isinstance(error.value, ValueError)
    assert "radius" in str(error.value)
    with pytest.raises(ValueError):
        carom.sweep_ball_ball_many(np.zeros((3, 2)), np.zeros((3, 2)), np.zeros((3, 3)),
                                   np.zeros((3, 2)))
    with pytest.raises(carom.InvalidArgument):
        carom.sweep_ball_ball_many(np.array([[0, 0, 1.0]]), np.array([[math.nan, 0]]),
                                   np.array([[3, 0, 1.0]]), np.zeros((1, 2)))
