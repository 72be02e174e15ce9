"""docs/scene.schema.json agrees with carom: every example scene is valid under it, and a few
scenes carom refuses field by field are invalid under it too. Run by ctest when Python has
jsonschema (Debian: python3-jsonschema)."""
import json
import pathlib
import sys

import jsonschema

root = pathlib.Path(sys.argv[1])
schema = json.loads((root / "docs" / "scene.schema.json").read_text())
jsonschema.Draft202012Validator.check_schema(schema)
validator = jsonschema.Draft202012Validator(schema)

failures = []
examples = sorted((root / "examples").glob("*.json"))
if not examples:
    failures.append("no examples found")
for path in examples:
    for error in validator.iter_errors(json.loads(path.read_text())):
        failures.append(f"{path.name}: {error.json_path}: {error.message}")

refused = {
    "unknown key": {"balls": [{"position": [0, 0], "raduis": 1}]},
    "radius 0": {"balls": [{"position": [0, 0], "radius": 0}]},
    "restitution above 1": {"balls": [{"position": [0, 0], "restitution": 1.5}]},
    "nan as a string": {"balls": [{"position": ["nan", 0]}]},
    "box without bounds": {"world": {"boundary": "box"}},
    "gravity with one number": {"world": {"gravity": [1]}},
    "gravity as a word": {"world": {"gravity": "down"}},
    "gravity with a string for a number": {"world": {"gravity": [0, "-inf"]}},
    "rest height 0": {"world": {"rest_height": 0}},
    "rest height below 0": {"world": {"rest_height": -0.01}},
    "rest height as a word": {"world": {"rest_height": "low"}},
    "generator with radius and packing fraction": {
        "generators": [{"count": 3, "radius": 1, "packing_fraction": 0.1}]},
    "sensor of an unknown shape": {"sensors": [{"shape": "square", "center": [0, 0]}]},
    "disc sensor with a segment's field": {"sensors": [{"shape": "disc", "center": [0, 0], "a": [1, 1]}]},
    "sensor with an unknown action": {"sensors": [{"shape": "segment", "a": [0, 0], "b": [1, 0], "action": "eat"}]},
}
# And a scene with gravity and a rest height that carom reads is valid under it.
if not validator.is_valid({"world": {"boundary": "open", "gravity": [0, -9.81]}}):
    failures.append("the schema refuses a scene with gravity that carom reads")
if not validator.is_valid({"world": {"gravity": [0, -9.81], "rest_height": 0.01}}):
    failures.append("the schema refuses a scene with a rest height that carom reads")

# Sensors of each shape that carom reads.
if not validator.is_valid({"sensors": [
        {"name": "gate", "shape": "segment", "a": [0, 0], "b": [1, 0]},
        {"shape": "arc", "center": [0, 0], "radius": 2, "start_angle": 0, "end_angle": 1},
        {"shape": "disc", "center": [5, 5], "radius": 0.5, "action": "remove_ball",
         "filter": {"category": 2}}]}):
    failures.append("the schema refuses sensors that carom reads")

for name, scene in refused.items():
    if validator.is_valid(scene):
        failures.append(f"the schema accepts a scene carom refuses: {name}")

for failure in failures:
    print(failure)
sys.exit(1 if failures else 0)
