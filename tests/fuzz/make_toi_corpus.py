#!/usr/bin/env python3
"""Writes the seed corpus of carom_toi_fuzz (tests/fuzz/corpus/toi/): one file per case, the
19 doubles of toi_fuzz.cpp's input as little-endian bit patterns (a case of 13 leaves both
accelerations zero, one of 17 both growths). Each seed is a case worth
starting from: ordinary hits and misses, the edges (touching, graze, coincident centres), the
ends of the double range, and invalid input. Run it from anywhere; it rewrites its own cases
and leaves the folder's other files (inputs the fuzzer found, kept by hand) alone."""
import math
import pathlib
import struct

MAX = 1.7976931348623157e308
TINY = 5e-324
PI = math.pi

# name: a.x a.y a.r va.x va.y  b.x b.y b.r vb.x vb.y  horizon  arc.start arc.end
#       [aa.x aa.y ab.x ab.y [ga gb]]
CASES = {
    "head_on_hit": [0, 0, 1, 4, 0, 5, 0, 1, 0, 0, 1, 0, PI],
    "tutorial": [0, 0, 1, 6, 2, 8, 3, 1.5, -4, -1, 1, -PI / 2, PI / 2],
    "miss": [0, 0, 1, 1, 0, 10, 10, 1, 0, 0, 1, 0, 2 * PI],
    "graze": [0, 0, 1, 10, 0, 5, 2, 1, 0, 0, 1, 0, PI],
    "touching_approaching": [0, 0, 1, 1, 0, 2, 0, 1, 0, 0, 1, 0, PI],
    "touching_separating": [0, 0, 1, -1, 0, 2, 0, 1, 0, 0, 1, 0, PI],
    "coincident_moving": [3, 3, 1, 1, 1, 3, 3, 2, 0, 0, 1, 0, 0],
    "overlapping_still": [0, 0, 2, 0, 0, 1, 0, 2, 0, 0, 1, 0, PI],
    "inside_bowl": [0, -3, 1, 0, 9, 0, 0, 5, 0, 0, 1, PI, 2 * PI],
    "huge_1e200": [0, 0, 1e200, 4e200, 0, 5e200, 0, 1e200, 0, 0, 1, 0, PI],
    "tiny_1e-200": [0, 0, 1e-200, 4e-200, 0, 5e-200, 0, 1e-200, 0, 0, 1, 0, PI],
    "overflowing_difference": [-1.5e308, 0, 1e307, 1.5e308, 0, 1.5e308, 0, 1e307, -1.5e308, 0,
                               2, 0, PI],
    "max_everything": [MAX, -MAX, MAX, -MAX, MAX, -MAX, MAX, MAX, MAX, -MAX, MAX, 0, 2 * PI],
    "subnormal_everything": [TINY, 0, TINY, -TINY, 0, 3 * TINY, 0, TINY, 0, 0, 1, 0, PI],
    "tiny_balls_far_apart": [-1e300, 0, 1e-300, 1e300, 0, 1e300, 0, 1e-300, -1e300, 0, 2, 0, PI],
    "speed_1e6_diameters": [0, 0.5, 1, 2e6, 0, 1e6, -0.5, 1, 0, 0, 1, 0, PI],
    "radii_1e-6_1e6": [0, 0, 1e-6, 2e6, 1, 2e6, 0, 1e6, 0, 0, 1, -1, 1],
    "zero_span_arc": [0, 10, 1, 0, -8, 0, 0, 5, 0, 0, 1, PI / 2, PI / 2],
    "nan_position": [math.nan, 0, 1, 1, 0, 5, 0, 1, 0, 0, 1, 0, PI],
    "inf_velocity": [0, 0, 1, math.inf, 0, 5, 0, 1, 0, 0, 1, 0, PI],
    "negative_radius": [0, 0, -1, 1, 0, 5, 0, 1, 0, 0, 1, 0, PI],
    "negative_horizon": [0, 0, 1, 1, 0, 5, 0, 1, 0, 0, -1, 0, PI],
    "arc_span_too_long": [0, 0, 1, 1, 0, 5, 0, 1, 0, 0, 1, 0, 7],
    "falling_onto_floor": [0, 5, 0.5, 0, 0, -5, 0, 1, 5, 0, 2, PI, 2 * PI, 0, -9.81, 0, 0],
    "resting_on_floor": [0, 0.5, 0.5, 0, 0, -5, 0, 1, 5, 0, 2, 0, PI, 0, -9.81, 0, 0],
    "resting_in_bowl": [0, -2, 1, 0, 0, 0, 0, 3, 0, 0, 2, PI, 2 * PI, 0, -9.81, 0, 0],
    "thrown_past_end": [-2, -3, 0.5, 2.5, 12, 0, 0, 1, 10, 0, 10, 0, PI, 0, -9.81, 0, 0],
    "falling_together": [0, 2, 1, 1, 0, 0, 0, 1, 1, 0, 5, 0, PI, 0, -9.81, 0, -9.81],
    "onto_moving_peg": [0, 10, 0.5, 0.3, 0, 0, 0, 1, 0, 1, 5, 0, PI, 0, -9.81, 0, 0],
    "huge_acceleration": [0, 0, 1, 1, 0, 5, 0, 1, 0, 0, 1, 0, PI, -MAX, MAX, MAX, 0],
    "tiny_acceleration": [0, 0, 1, 1, 0, 5, 3, 1, 0, 0, 1e300, 0, PI, TINY, -TINY, 0, 0],
    "nan_acceleration": [0, 0, 1, 1, 0, 5, 0, 1, 0, 0, 1, 0, PI, math.nan, 0, 0, 0],
    "growing_at_rest": [0, 0, 1, 0, 0, 10, 0, 2, 0, 0, 10, 0, PI, 0, 0, 0, 0, 0.5, 1.5],
    "growth_outruns_retreat": [0, 0, 1, -1, 0, 4, 0, 1, 0, 0, 10, 0, PI, 0, 0, 0, 0, 1.5, 1.5],
    "growing_in_bowl": [0, 0, 1, 0.2, 0, 0, 0, 5, 0, 0, 10, 0, 6, 0, 0, 0, 0, 1, 0],
    "growing_under_gravity": [0, 5, 0.5, 1, 0, -5, 0, 1, 5, 0, 2, 0, PI, 0, -9.81, 0, 0, 0.3, 0],
    "huge_growth": [0, 0, 1, 1, 0, 5, 0, 1, 0, 0, 1, 0, PI, 0, 0, 0, 0, MAX, 0],
    "negative_growth": [0, 0, 1, 1, 0, 5, 0, 1, 0, 0, 1, 0, PI, 0, 0, 0, 0, -1, 0],
    "growths_overflowing_sum": [0, 0, 1, 0, 0, 5, 0, 1, 0, 0, 1, 0, PI, 0, 0, 0, 0, MAX, MAX],
    "growing_on_a_segment_line": [0, 0, 1, 0, 0, 10, 0, 2, 0, 0, 10, 0, PI, 0, 0, 0, 0, 0.5, 0],
}


def main() -> None:
    folder = pathlib.Path(__file__).resolve().parent / "corpus" / "toi"
    folder.mkdir(parents=True, exist_ok=True)
    for name, values in CASES.items():
        assert len(values) in (13, 17, 19), name
        (folder / name).write_bytes(
            struct.pack(f"<{len(values)}d", *[float(v) for v in values]))


if __name__ == "__main__":
    main()
