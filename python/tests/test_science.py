"""The hard-disk gas from Python: carom.gas and carom.eos give what `carom gas --json` and
`carom eos --json` print — the same keys and, for the same seed, the same numbers bit for bit
(all but the wall-clock timings) — and refuse a bad argument naming it."""
import json
import math
import os
import pathlib
import shutil
import signal
import subprocess
import threading
import time

import numpy as np
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


def test_eos_with_seeds_is_the_tool_eos_and_each_run_is_that_seeds_gas():
    options = {k: v for k, v in SMALL.items() if k != "eta"}
    ours = carom.eos([0.3], seeds=3, **options)
    theirs = tool_json("eos", "--eta=0.3", "--seeds=3", "--threads=1",
                       *[f"--{k}={v}" for k, v in options.items()])
    point, tools = ours["points"][0], theirs["points"][0]
    same_numbers({k: v for k, v in point.items() if k != "runs"},
                 {k: v for k, v in tools.items() if k != "runs"})
    for a, b in zip(point["runs"], tools["runs"], strict=True):
        same_numbers(a, b)
    assert point["seeds"] == 3 and point["first_seed"] == SMALL["seed"]
    for k, run in enumerate(point["runs"]):
        alone = carom.gas(**dict(SMALL, seed=SMALL["seed"] + k))
        assert run["Z"] == alone["Z"]
    zs = [run["Z"] for run in point["runs"]]
    assert point["Z"] == pytest.approx(sum(zs) / 3, rel=1e-14)
    with pytest.raises(ValueError, match="^seeds = 0"):
        carom.eos([0.3], seeds=0, **options)


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


def test_eos_threads_change_nothing_but_the_wall_time():
    options = dict(n=64, equilibrate=5, collisions=40, seed=3, blocks=4)
    one = carom.eos([0.1, 0.2, 0.3], threads=1, **options)
    two = carom.eos([0.1, 0.2, 0.3], threads=2, **options)
    for a, b in zip(one["points"], two["points"]):
        same_numbers(a, b)
    with pytest.raises(ValueError, match="^threads = 0: between 1 and 256"):
        carom.eos([0.2], threads=0, **options)


# Long enough that the signal lands in the middle (several seconds uninterrupted).
LONG_GAS = dict(n=4000, eta=0.5, equilibrate=20, collisions=4000, seed=1)


@pytest.mark.parametrize("run", [
    lambda: carom.gas(**LONG_GAS),
    lambda: carom.measure_gas(**LONG_GAS),
    lambda: carom.eos([0.4, 0.5], threads=2, **{k: v for k, v in LONG_GAS.items() if k != "eta"}),
], ids=["gas", "measure_gas", "eos"])
def test_ctrl_c_stops_a_gas_in_the_middle(run):
    timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        run()
    timer.join()
    assert time.monotonic() - start < 2.0


def test_a_gas_lets_other_threads_run():
    ticks = []
    stop = threading.Event()

    def count():
        while not stop.is_set():
            ticks.append(1)
            time.sleep(0.001)

    counter = threading.Thread(target=count)
    counter.start()
    try:
        carom.gas(n=1000, eta=0.4, equilibrate=10, collisions=300, seed=2)
    finally:
        stop.set()
        counter.join()
    # The gas runs for a good part of a second; a thread blocked by the GIL would not tick.
    assert len(ticks) > 20


def test_measure_gas_gives_the_distributions_as_arrays():
    m = carom.measure_gas(n=200, eta=0.5, equilibrate=10, collisions=200, seed=2, blocks=4)
    same_numbers(m.report, carom.gas(n=200, eta=0.5, equilibrate=10, collisions=200, seed=2,
                                     blocks=4))
    r, g = m.rdf
    assert r.shape == g.shape and r.ndim == 1 and len(r) > 50
    # g(r) at contact is the contact value the report gives from the collision rate, within
    # the noise of a short run; far out it tends to 1.
    assert g[0] == pytest.approx(m.report["g_contact"], rel=0.15)
    assert abs(g[-20:].mean() - 1.0) < 0.1
    speed, density = m.speed
    assert np.sum(density) * (speed[1] - speed[0]) == pytest.approx(1.0, abs=1e-9)
    assert m.positions.shape == (200, 2) and m.radii.shape == (200,)
    assert np.all((m.psi6_modulus >= 0) & (m.psi6_modulus <= 1 + 1e-12))
    # The last sample's global order, |mean of psi6_j|, is small in a fluid, as the report's
    # average over every sample is.
    last = abs(np.mean(m.psi6_modulus * np.exp(1j * m.psi6_angle)))
    assert last < 0.25 and m.report["psi6"] < 0.25
