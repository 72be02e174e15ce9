#!/usr/bin/env python3
"""Writes the seed corpus of carom_world_fuzz (tests/fuzz/corpus/world/): one file per scenario,
encoded as world_fuzz.cpp decodes its input (kept in step with it by hand). Each seed is a short
program worth mutating from: a gas in each boundary, walls of every kind (a point, a zero-span arc,
a full circle), sensors (lines, arcs, discs, pockets that remove), moving walls, drags to the nearest free place, inelastic balls with a stop condition, a save and
load, invalid calls, and worlds under gravity. Run it from anywhere; it rewrites its seeds."""
import pathlib
import struct

SIDE = 20.0
OPEN, BOX, PERIODIC = 0, 1, 2
# Opcodes (op % 12 in world_fuzz.cpp).
ADD, REMOVE, MOVE, VELOCITY, STEP, COLLISIONS, UNTIL, SAVE, STOP, BAD = 0, 2, 3, 4, 5, 7, 8, 9, 10, 11


def word(fraction):
    return struct.pack("<H", round(min(max(fraction, 0.0), 1.0) * 65535))


def position(x, y):
    return bytes([1]) + word(x / SIDE) + word(y / SIDE)


def velocity(speed_index, angle_fraction, axis=False):
    return bytes([speed_index]) + word(angle_fraction) + bytes([0 if axis else 1])


def head(boundary, restitution_index=0, fixed_cell=False, gravity=False, growth=False, table=False):
    return bytes([boundary + 3 * restitution_index + (18 if gravity else 0) + (36 if growth else 0) +
                  (72 if table else 0) + (0x80 if fixed_cell else 0)])


def walls(*encoded):
    return bytes([len(encoded)]) + b"".join(encoded)


def segment(a, b):
    return bytes([2]) + position(*a) + position(*b)


def point(a):
    return bytes([0]) + position(*a)


def arc(center, radius, start_fraction, kind):
    """kind: 1 zero span, 3 full circle, 5 a span of span_fraction (appended by the caller)."""
    return bytes([kind]) + position(*center) + word((radius - 0.5) / 8.0) + word(start_fraction)


def motion(vx, vy, spin, px, py, duration=None):
    """Fractions of the harness's ranges: velocity and spin about the middle (0.5 is zero), the
    pivot's offset from the wall's first point; a duration makes the motion end."""
    return (word(vx) + word(vy) + word(spin) + word(px) + word(py)
            + (word(duration) if duration is not None else b""))


def moving_segment(a, b, *moves):
    ends = len(moves) > 5
    return bytes([2 | 64 | (128 if ends else 0)]) + position(*a) + position(*b) + motion(*moves)


def moving_arc(center, radius, start_fraction, span_fraction, *moves):
    ends = len(moves) > 5
    return (bytes([5 | 64 | (128 if ends else 0)]) + position(*center) + word((radius - 0.5) / 8.0)
            + word(start_fraction) + word(span_fraction) + motion(*moves))


def sensor_segment(a, b, remove=False):
    return bytes([2 | 8 | (16 if remove else 0)]) + position(*a) + position(*b)


def sensor_arc(center, radius, start_fraction, span_fraction, remove=False):
    return (bytes([5 | 8 | (16 if remove else 0)]) + position(*center) + word((radius - 0.5) / 8.0)
            + word(start_fraction) + word(span_fraction))


def sensor_disc(center, radius, remove=False):
    return bytes([8 | 32 | (16 if remove else 0)]) + position(*center) + word((radius - 0.05) / 4.0)


def add(x, y, speed_index=1, angle=0.1, radius_index=0, mass_index=0, restitution=0):
    return (bytes([ADD]) + position(x, y) + velocity(speed_index, angle) +
            bytes([radius_index, mass_index, restitution]))


def gas(count, speed_index=1):
    out = b""
    for k in range(count):
        out += add(2.0 + 3.0 * (k % 6), 2.0 + 3.0 * (k // 6), speed_index, (k * 0.37) % 1.0)
    return out


def step(index, fraction=0.0):
    return bytes([STEP, index]) + word(fraction)


def bad(which, extra=b""):
    """An invalid call (world_fuzz.cpp's bad_call); 0 and 4 read one more byte, 5 a ball's."""
    return bytes([BAD, which]) + extra


def strike(ball, speed, direction, elevation=0.0, reach=0.0, around=0.0, spin_only=False):
    """On a table, a velocity call that strikes ball `ball` (fractions of the harness's ranges), or
    with spin_only sets its spin instead."""
    return (bytes([VELOCITY, 0, ball]) + word(speed) + word(direction) + word(elevation) + word(reach)
            + word(around) + bytes([0 if spin_only else 1]) + word(0.8) + word(0.3) + word(0.6))


def collisions(count, unlimited=False, limit_index=2):
    return bytes([COLLISIONS, count | (0x80 if unlimited else 0), limit_index])


SEEDS = {
    "box_gas": head(BOX) + walls() + gas(12) + step(2) + collisions(8, True) + step(4),
    "periodic_gas_save": head(PERIODIC) + gas(18, 4) + collisions(8) + bytes([SAVE]) + step(0)
    + bytes([SAVE]) + collisions(5),
    "open_walls_drag": head(OPEN) + walls(segment((1, 1), (19, 1)), point((10, 15)),
                                          arc((10, 10), 6.0, 0.1, 3), arc((4, 16), 2.0, 0.3, 1))
    + add(10, 10, 1, 0.2) + add(14, 10, 2, 0.6) + bytes([MOVE, 0]) + position(10, 2) + bytes([1])
    + bytes([UNTIL, 2]) + bytes([MOVE, 1]) + position(10, 10) + bytes([0]) + step(4),
    "box_arcs_inelastic_stop": head(BOX, 3) + walls(arc((10, 10), 4.0, 0.0, 5) + word(0.5),
                                                    segment((2, 18), (18, 2)))
    + gas(8, 2) + bytes([STOP, 1]) + step(2) + step(2) + bytes([SAVE]) + step(2),
    "tiny_and_large_box": head(BOX, 0, True) + walls()
    + add(10, 10, 0, 0.0, 6) + add(3, 3, 6, 0.125, 5) + add(17, 3, 1, 0.4, 5) + step(2)
    + step(7) + collisions(8, True),
    "bad_calls_and_removal": head(OPEN) + walls() + gas(4) + bad(0, b"\x02") + bad(1) + bad(2) + bad(3)
    + bad(4, b"\x01") + bytes([REMOVE, 1]) + bad(5, b"\x00") + gas(2) + bytes([VELOCITY, 0]) + velocity(4, 0.5)
    + step(2),
    # Under gravity: a pile settling in a box (balls resting on each other, woken by a removal and
    # a thrown ball), slopes and a bowl, and an elastic gas falling onto a floor in an open world.
    "gravity_pile_in_box": head(BOX, 3, gravity=True) + walls() + gas(18, 1) + step(6) + step(7)
    + bytes([SAVE]) + bytes([REMOVE, 2]) + step(4) + add(10, 18, 4, 0.75) + step(7),
    "gravity_slopes_and_bowl": head(BOX, 4, gravity=True)
    + walls(segment((1, 12), (12, 6)), segment((19, 9), (8, 3)), arc((10, 8), 5.0, 0.5, 5) + word(0.5))
    + gas(10, 1) + step(6) + bytes([STOP, 1]) + step(7) + bytes([SAVE]) + step(7),
    "gravity_elastic_open": head(OPEN, 0, gravity=True) + walls(segment((1, 1), (19, 1))) + gas(12, 2) + collisions(8)
    + bytes([SAVE]) + step(4),
    # Growth: a gas compressed in a periodic cell, and growing balls among walls and an arc in a box.
    "growth_periodic_gas": head(PERIODIC, 0, growth=True) + gas(16, 1) + step(7) + bytes([SAVE]) + step(7)
    + collisions(8),
    "growth_in_box_with_walls": head(BOX, 0, growth=True)
    + walls(segment((1, 12), (12, 6)), arc((10, 8), 5.0, 0.5, 5) + word(0.5)) + gas(10, 1) + step(6)
    + bytes([SAVE]) + step(7) + add(10, 18, 4, 0.75) + step(7),
    # Sensors: a line, an arc and a disc crossed by a gas (saved while balls are inside), pockets
    # that remove balls falling into them, and growing balls swelling into a zone.
    "sensors_box_gas": head(BOX) + walls(sensor_segment((1, 10), (19, 10)), sensor_arc((10, 10), 5.0, 0.2, 0.6),
                                         sensor_disc((5, 15), 2.0), segment((2, 2), (6, 6)))
    + gas(12, 3) + step(4) + bytes([SAVE]) + step(5) + collisions(8, True) + bytes([MOVE, 0]) + position(5, 15)
    + bytes([0]) + step(2),
    "sensor_pockets_gravity": head(BOX, 0, gravity=True) + walls(sensor_disc((2, 2), 0.5, True),
                                                                sensor_disc((18, 2), 0.5, True),
                                                                sensor_segment((1, 8), (19, 8)))
    + gas(12, 2) + step(6) + bytes([SAVE]) + step(7) + step(7),
    # Moving walls: a bar turning for ever and a cup turning and drifting through a gas (saved
    # mid-motion), a flipper that swings for a while under gravity, and a paddle among growing balls.
    "moving_walls_box": head(BOX) + walls(moving_segment((5, 10), (15, 10), 0.5, 0.5, 0.8, 0.5, 0.5),
                                          moving_arc((14, 14), 3.0, 0.1, 0.5, 0.6, 0.4, 0.3, 0.5, 0.5, 0.9))
    + gas(12, 2) + step(6) + bytes([SAVE]) + step(7) + collisions(8, True),
    "moving_flipper_gravity": head(BOX, 0, gravity=True)
    + walls(moving_segment((3, 4), (10, 4), 0.5, 0.5, 0.9, 0.0, 0.5, 0.1), segment((12, 2), (19, 6)))
    + gas(8, 1) + step(6) + bytes([SAVE]) + step(7) + step(7),
    "moving_paddle_growth": head(BOX, 0, growth=True)
    + walls(moving_segment((4, 3), (16, 3), 0.5, 0.7, 0.5, 0.5, 0.5, 0.4))
    + gas(10, 1) + step(6) + bytes([SAVE]) + step(7),
    # A billiards table: cushions of every kind, a rack struck with top, back and side spin, a spin
    # set by hand, saved mid-shot; and a table with pockets that remove balls.
    "table_break": head(BOX, 1, table=True) + walls(segment((1, 1), (19, 1)), arc((10, 10), 9.0, 0.1, 5) + word(0.3))
    + gas(10, 0) + strike(0, 0.9, 0.1, 0.0, 0.3, 0.25) + step(5) + strike(3, 0.5, 0.6, 0.4, 0.8, 0.75)
    + bytes([SAVE]) + step(6) + strike(5, 0.0, 0.0, spin_only=True) + collisions(8, True) + step(7),
    "table_pockets": head(BOX, 0, table=True) + walls(sensor_disc((2, 2), 1.0, True), sensor_disc((18, 18), 1.0, True))
    + gas(8, 2) + strike(1, 1.0, 0.6, 0.2, 0.9, 0.5) + step(6) + bytes([SAVE]) + step(7) + collisions(8, True),
    "sensors_growth": head(BOX, 0, growth=True) + walls(sensor_disc((10, 10), 3.0), sensor_segment((3, 3), (17, 3)))
    + gas(10, 1) + step(6) + bytes([SAVE]) + step(7),
}


def main():
    folder = pathlib.Path(__file__).resolve().parent / "corpus" / "world"
    folder.mkdir(parents=True, exist_ok=True)
    for name, data in SEEDS.items():  # (other files there are crashes kept as regressions)
        (folder / name).write_bytes(data)


if __name__ == "__main__":
    main()
