"""Scenes from Python: reading files and text, errors that name the field and line, saving and
reading back bit for bit, building a World with the scene's ids, and runs into frames with
pockets and a thermostat at work."""
import os
import pathlib
import signal
import threading

import numpy as np
import pytest

import carom

EXAMPLES = pathlib.Path(
    os.environ.get("CAROM_EXAMPLES", pathlib.Path(__file__).parents[2] / "examples")
)

TWO_BALLS = """{
  "carom_scene": 1,
  "description": "two balls",
  "world": {"boundary": "box", "lower": [0, 0], "upper": [20, 10]},
  "balls": [
    {"position": [3, 5], "velocity": [2, 0], "radius": 1},
    {"position": [12, 5], "velocity": [-1, 0], "radius": 1.5}
  ]
}
"""


def test_parse_and_load_give_a_scene():
    scene = carom.parse_scene(TWO_BALLS)
    assert scene.description == "two balls"
    assert scene.ball_count == 2 and len(scene) == 2
    billiards = carom.load_scene(EXAMPLES / "billiards-frictionless.json")
    assert billiards.ball_count == 16 and billiards.pocket_count == 6
    assert "billiards" in billiards.description


def test_errors_name_the_field_and_line():
    text = TWO_BALLS.replace('"radius": 1.5', '"radius": -2')
    with pytest.raises(carom.SceneError) as caught:
        carom.parse_scene(text, name="mine.json")
    error = caught.value
    assert isinstance(error, ValueError)
    assert error.file == "mine.json"
    assert error.path == "balls[1].radius"
    assert error.line == 7 and error.column > 0  # the second ball's line
    assert error.value == "-2"
    assert "> 0" in error.problem
    assert "mine.json:7:" in str(error)


def test_an_unknown_key_gets_a_suggestion():
    with pytest.raises(carom.SceneError) as caught:
        carom.parse_scene(TWO_BALLS.replace('"radius": 1}', '"radiu": 1}'))
    assert caught.value.suggestion == "radius"


def test_a_missing_file_is_a_scene_error(tmp_path):
    with pytest.raises(carom.SceneError):
        carom.load_scene(tmp_path / "none.json")


def test_saving_reads_back_bit_for_bit(tmp_path):
    scene = carom.load_scene(EXAMPLES / "periodic-gas.json")
    path = tmp_path / "again.json"
    scene.save(path)
    again = carom.load_scene(path)
    assert again.to_json() == scene.to_json()
    assert path.read_text() == scene.to_json()
    assert carom.parse_scene(scene.to_json()).to_json() == scene.to_json()


def test_make_world_maps_scene_indices_to_ids():
    world, ids = carom.make_world(carom.parse_scene(TWO_BALLS))
    assert isinstance(world, carom.World) and len(world) == 2
    assert ids.dtype == np.uint64 and ids.shape == (2,)
    assert world.position(int(ids[0])) == (3.0, 5.0)
    assert world.radius(int(ids[1])) == 1.5
    world.run_until(10)
    assert world.time == 10
    assert world.audit() is None


def test_run_scene_frames_and_contacts():
    run = carom.run_scene(carom.parse_scene(TWO_BALLS), until=2.0, frame_interval=0.5)
    assert run["times"].tolist() == [0.0, 0.5, 1.0, 1.5, 2.0]
    assert run["positions"].shape == (5, 2, 2) and run["velocities"].shape == (5, 2, 2)
    assert run["radii"].shape == (5, 2)
    assert run["positions"][1, 0].tolist() == [4.0, 5.0]  # 3 + 2·0.5, before any contact
    # They meet when 12 − t − (3 + 2t) = 2.5, at t = 6.5 / 3.
    assert len(run["contacts"]) == 0
    longer = carom.run_scene(carom.parse_scene(TWO_BALLS), until=2.5, frame_interval=0.5)
    ball_ball = longer["contacts"][longer["contacts"]["kind"] == 0]
    assert len(ball_ball) == 1
    assert ball_ball["time"][0] == pytest.approx(6.5 / 3)
    assert set(ball_ball[["a", "b"]][0].tolist()) == set(longer["ids"].tolist())


def test_the_same_run_as_the_world_gives():
    scene = carom.load_scene(EXAMPLES / "periodic-gas.json")
    run = carom.run_scene(scene, until=1.0, frame_interval=1.0)
    world, ids = carom.make_world(scene)
    world.run_until(1.0)
    order = np.argsort(world.ids)
    by_id = dict(zip(world.ids[order].tolist(), world.positions[order]))
    expected = np.array([by_id[int(i)] for i in ids])
    assert np.array_equal(run["positions"][-1], expected)


def test_pockets_take_balls_and_leave_nan_rows():
    scene = carom.load_scene(EXAMPLES / "billiards-frictionless.json")
    run = carom.run_scene(scene, until=3.0, frame_interval=0.5)
    assert len(run["potted"]) > 0
    for potted in run["potted"]:
        after = run["times"] >= potted["time"]
        assert np.isnan(run["radii"][after, potted["ball"]]).all()
        assert np.isnan(run["positions"][after, potted["ball"]]).all()
        assert not np.isnan(run["radii"][0, potted["ball"]])
    live = ~np.isnan(run["radii"][-1])
    assert live.sum() == 16 - len(run["potted"])


def test_sensors_in_a_scene_report_and_a_pocket_sensor_removes():
    scene = carom.parse_scene("""{
      "world": {"boundary": "box", "lower": [0, 0], "upper": [20, 10]},
      "balls": [{"position": [2, 5], "velocity": [4, 0], "radius": 0.5}],
      "sensors": [{"shape": "segment", "a": [6, 0], "b": [6, 10]},
                  {"shape": "disc", "center": [17, 5], "radius": 0.3, "action": "remove_ball"}]}""")
    run = carom.run_scene(scene, until=5.0, frame_interval=1.0)
    kinds = [(e["kind"], e["sensor"], e["removed"]) for e in run["sensor_events"]]
    assert kinds == [("enter", 0, False), ("exit", 0, False), ("enter", 1, True)]
    assert run["sensor_events"][0]["ball"] == 0
    # The gate's line is reached when the ball's edge is at x = 6: t = (5.5 - 2) / 4.
    assert abs(run["sensor_events"][0]["time"] - 3.5 / 4.0) < 1e-10
    assert np.isnan(run["radii"][-1, 0])


def test_a_thermostat_holds_the_temperature():
    scene = carom.load_scene(EXAMPLES / "compression.json")
    run = carom.run_scene(scene, until=2.0, frame_interval=0.5)
    # Masses are 1: kT is the kinetic energy a ball; the thermostat resets it to 1 each 0.5.
    v = run["velocities"][-1]
    kinetic = 0.5 * (v**2).sum() / len(v)
    assert kinetic == pytest.approx(1.0, rel=1e-9)
    assert (run["radii"][-1] > run["radii"][0]).all()  # growing, as the scene says


def test_bad_frame_interval_is_refused():
    with pytest.raises(ValueError):
        carom.run_scene(carom.parse_scene(TWO_BALLS), until=1.0, frame_interval=0.0)


def test_ctrl_c_stops_a_long_run():
    scene = carom.load_scene(EXAMPLES / "periodic-gas.json")
    timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        carom.run_scene(scene, until=1e9, frame_interval=1e8)
    timer.join()
