"""The hard-disk gas from Python: carom.gas and carom.eos give what `carom gas --json` and
`carom eos --json` print — the same keys and, for the same seed, the same numbers bit for bit
(all but the wall-clock timings) — and refuse a bad argument naming it."""
import json
import math
import os
import pathlib
import shutil
import subprocess

import pytest

import carom

pytestmark = pytest.mark.skipif(not hasattr(carom, "gas"), reason="built without the tool")

# Wall-clock measurements: they differ from one run to the next.
TIMINGS = {"wall_seconds", "collisions_per_second", "compression_seconds"}
SMALL = dict(n=64, eta=0.3, equilibrate=5, collisions=40, seed=3, blocks=4)


def tool():
    """The carom tool of the build the module comes from (or CAROM_CLI, or the PATH's)."""
    if "CAROM_CLI" in os.environ:
        return os.environ["CAROM_CLI"]
    beside = pathlib.Path(carom.__file__).resolve().parents[2] / "apps" / "carom" / "carom"
    if beside.is_file():
        return str(beside)
    found = shutil.which("carom")
    if found is None:
        pytest.skip("no carom tool to compare with")
    return found


def tool_json(*args):
    done = subprocess.run([tool(), *args, "--json"], capture_output=True, text=True, check=True)
    return json.loads(done.stdout)


def same_numbers(a, b):
    assert a.keys() == b.keys()
    for key in a.keys() - TIMINGS:
        x, y = a[key], b[key]
        if isinstance(x, float) and math.isnan(x):
            assert isinstance(y, float) and math.isnan(y), key
        else:
            assert x == y, key


def test_gas_is_the_tool_gas():
    ours = carom.gas(**SMALL)
    theirs = tool_json("gas", *[f"--{k}={v}" for k, v in SMALL.items()])
    assert set(ours) == set(theirs)
    same_numbers(ours, theirs)
    assert ours["n"] == 64 and ours["seed"] == 3 and ours["blocks_done"] == 4
    assert ours["Z"] > 1


def test_another_seed_gives_other_numbers():
    assert carom.gas(**{**SMALL, "seed": 4})["Z"] != carom.gas(**SMALL)["Z"]


def test_a_mixture_and_a_compressed_start():
    mixed = dict(SMALL, mix=(1.4, 0.5), start="compress")
    ours = carom.gas(**mixed)
    theirs = tool_json(
        "gas", "--n=64", "--eta=0.3", "--equilibrate=5", "--collisions=40", "--seed=3",
        "--blocks=4", "--mix=1.4:0.5", "--start=compress",
    )
    same_numbers(ours, theirs)
    assert carom.gas(**dict(mixed, mix="1.4:0.5")).keys() == ours.keys()


def test_eos_is_the_tool_eos():
    options = {k: v for k, v in SMALL.items() if k != "eta"}
    ours = carom.eos([0.1, 0.2], **options)
    theirs = tool_json("eos", "--eta=0.1:0.2:0.1", "--threads=1",
                       *[f"--{k}={v}" for k, v in options.items()])
    assert list(ours) == ["points"] and len(ours["points"]) == 2
    for a, b in zip(ours["points"], theirs["points"]):
        same_numbers(a, b)
    assert [p["eta"] for p in ours["points"]] == [0.1, 0.2]


@pytest.mark.parametrize(
    "argument, value",
    [("n", 1), ("eta", 0.95), ("blocks", 1), ("start", "hot"), ("mix", "2")],
)
def test_a_bad_argument_is_named(argument, value):
    with pytest.raises(ValueError, match=f"^{argument} = "):
        carom.gas(**dict(SMALL, **{argument: value}))


def test_eos_names_a_bad_point():
    with pytest.raises(ValueError, match="^eta = "):
        carom.eos([0.2, 1.5], n=64, collisions=40)


def test_pack_gives_what_carom_pack_json_gives():
    ours = carom.pack(n=120, mix=(1.4, 0.5), rate=0.01, pressure_limit=1e8, seed=3)
    theirs = tool_json("pack", "--n", "120", "--mix", "1.4:0.5", "--rate", "0.01",
                       "--until-jammed", "--pressure-limit", "1e8", "--seed", "3", "-q")
    same_numbers(ours, theirs)
    assert ours["jammed"] and ours["end"] == "pressure"
    with pytest.raises(ValueError, match="rate"):
        carom.pack(n=100, rate=-1.0)
    with pytest.raises(ValueError, match="eta"):
        carom.pack(n=100, eta=0.95)
