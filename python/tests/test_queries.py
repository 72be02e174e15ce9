"""The World's queries from Python: ray casts (one, all hits, arrays of rays), ball casts and
overlap queries, checked against NumPy over the world's own arrays and against hand-worked
geometry; filters as keywords; bad arguments refused."""
import math

import numpy as np
import pytest

import carom


def gas(boundary="box", n=300, seed=1):
    world = carom.World(boundary=boundary, lower=(0, 0), upper=(50, 50))
    rng = np.random.default_rng(seed)
    grid = np.stack(np.meshgrid(np.arange(2.0, 48, 2.8), np.arange(2.0, 48, 2.8)), -1).reshape(-1, 2)
    chosen = grid[rng.choice(len(grid), size=min(n, len(grid)), replace=False)]
    world.add_balls(chosen, velocities=rng.normal(size=chosen.shape),
                    radii=rng.uniform(0.4, 1.2, len(chosen)))
    world.run_until(3.0)
    return world


def test_overlap_queries_match_numpy_over_the_worlds_arrays():
    world = gas()
    ids, p, r = world.ids, world.positions, world.radii
    rng = np.random.default_rng(2)
    for _ in range(300):
        centre = rng.uniform(-5, 55, 2)
        radius = rng.uniform(0, 6)
        distance = np.hypot(*(p - centre).T)
        assert np.array_equal(world.balls_in_circle(centre, radius),
                              np.sort(ids[distance <= radius + r]))
        assert np.array_equal(world.balls_at_point(centre), np.sort(ids[distance <= r]))
        lower, upper = centre, centre + rng.uniform(0, 10, 2)
        nearest = np.clip(p, lower, upper)
        assert np.array_equal(world.balls_in_box(lower, upper),
                              np.sort(ids[np.hypot(*(nearest - p).T) <= r]))


def test_cast_rays_is_cast_ray_for_each_ray():
    world = gas()
    rng = np.random.default_rng(3)
    origins = rng.uniform(0, 50, (2000, 2))
    angles = rng.uniform(0, 2 * math.pi, 2000)
    moves = 30 * np.column_stack([np.cos(angles), np.sin(angles)])
    hits = world.cast_rays(origins, moves)
    assert hits.shape == (2000,)
    for k in range(0, 2000, 7):
        one = world.cast_ray(origins[k], moves[k])
        if one is None:
            assert hits["kind"][k] == 0 and hits["fraction"][k] == 1.0
            continue
        assert hits["kind"][k] == (1 if one.kind == "ball" else 2)
        assert hits["fraction"][k] == one.fraction
        assert tuple(hits["point"][k]) == one.point
        if one.kind == "ball":
            assert hits["ball"][k] == one.ball
            # The point lies on that ball's edge, the normal is its outward normal there.
            i = np.searchsorted(world.ids, one.ball)
            out = np.subtract(one.point, world.positions[i])
            assert np.hypot(*out) == pytest.approx(world.radii[i], rel=1e-12)
            assert np.allclose(out / world.radii[i], one.normal)
    # Most rays of 30 in a gas this dense meet a ball; the box stops the rest.
    assert np.mean(hits["kind"] == 1) > 0.8 and np.all(hits["kind"] > 0)


def test_a_pool_aim_line_by_ball_cast():
    world = carom.World()
    cue, target = world.add_balls(np.array([[0.0, 0.0], [20.0, 1.0]]), radii=1.0)
    hit = world.cast_ball((0, 0), 1.0, (40, 0), ignore=cue)
    assert hit.kind == "ball" and hit.ball == target and not hit.overlapping
    assert hit.center[0] == pytest.approx(20 - math.sqrt(3), abs=1e-14)
    # The object ball goes off along the normal's opposite: away from the ghost ball.
    assert hit.normal == pytest.approx((-math.sqrt(3) / 2, -0.5), abs=1e-14)
    assert world.cast_ball((0, 0), 1.0, (40, 0)).overlapping  # it starts inside the cue ball
    assert world.cast_ball((0, 0), 1.0, (40, 0), accept=lambda i: False) is None
    assert world.cast_ball((0, 0), 1.0, (40, 0), balls=False) is None


def test_rays_see_walls_from_both_sides_and_every_hit_in_order():
    world = carom.World(boundary="box", lower=(0, 0), upper=(20, 20))
    (ball,) = world.add_balls(np.array([[10.0, 5.0]]), radii=1.0)
    segment = world.add_segment((5, 12), (15, 12))
    hits = world.cast_ray_all((10, 0.5), (0, 19.5))
    assert [(h.kind, h.ball if h.kind == "ball" else h.wall) for h in hits] == [
        ("ball", ball), ("wall", segment), ("wall", hits[-1].wall)]
    assert [h.fraction for h in hits] == sorted(h.fraction for h in hits)
    assert hits[-1].point[1] == 20.0 and hits[1].normal == (0.0, -1.0)
    assert world.cast_ray((10, 19), (0, -10)).normal == (0.0, 1.0)
    assert world.cast_ray((10, 0.5), (0, 19.5), walls=False).ball == ball


def test_queries_refuse_bad_arguments():
    world = gas(n=10)
    with pytest.raises(carom.InvalidArgument, match="radius"):
        world.cast_ball((1, 1), 0.0, (1, 0))
    with pytest.raises(carom.InvalidArgument, match="upper"):
        world.balls_in_box((5, 5), (1, 1))
    with pytest.raises(carom.InvalidArgument, match="origin"):
        world.cast_ray((math.nan, 0), (1, 0))
    with pytest.raises(ValueError, match=r"\(N, 2\)"):
        world.cast_rays(np.zeros((3, 3)), np.zeros(2))
    with pytest.raises(ValueError, match="translations"):
        world.cast_rays(np.zeros((3, 2)), np.zeros((2, 2)))


def test_collision_filters_let_kinds_pass_through_and_queries_see_by_mask():
    world = carom.World()
    red = carom.CollisionFilter(category=1, mask=1)
    blue = carom.CollisionFilter(category=2, mask=2)
    (a,) = world.add_balls(np.array([[0.0, 0.0]]), velocities=[[1.0, 0.0]], radii=0.5, filter=red)
    (b,) = world.add_balls(np.array([[4.0, 0.0]]), velocities=[[-1.0, 0.0]], radii=0.5,
                           filter=blue)
    assert world.filter(a) == red and world.filter(b) == blue and not carom.should_collide(red, blue)
    world.run_until(10.0)
    assert world.collision_count == 0  # straight through each other
    assert world.positions.tolist() == [[10.0, 0.0], [-6.0, 0.0]]
    assert world.cast_ray((-20, 0), (40, 0), mask=1).ball == a
    assert world.cast_ray((-20, 0), (40, 0), mask=2).ball == b
    assert world.balls_in_box((-30, -1), (30, 1), mask=1).tolist() == [a]
    world.set_filter(b, carom.CollisionFilter())
    world.set_velocity(a, (-1.0, 0.0))
    world.set_velocity(b, (1.0, 0.0))
    world.run_until(20.0)
    assert world.collision_count == 1  # now they meet
    assert world.cast_ray((-20, 0), (40, 0), mask=2) is None
    wall = world.add_segment((0, -5), (0, 5))
    world.set_wall_filter(wall, blue)
    assert world.wall_filter(wall) == blue


def test_add_balls_takes_a_filter_for_each_ball():
    world = carom.World()
    kinds = [carom.CollisionFilter(category=1 << (k % 2), mask=1 << (k % 2)) for k in range(4)]
    ids = world.add_balls(np.array([[0.0, 0.0], [0.3, 0.0], [5.0, 0.0], [5.3, 0.0]]), radii=0.5,
                          filter=kinds)  # overlapping pairs of two kinds that pass through
    assert [world.filter(i) for i in ids] == kinds
    assert world.audit() is None
    with pytest.raises(ValueError, match="sequence of 2"):
        world.add_balls(np.array([[20.0, 0.0], [30.0, 0.0]]), filter=kinds)
    with pytest.raises(TypeError, match="not int"):
        world.add_balls(np.array([[20.0, 0.0]]), filter=3)
