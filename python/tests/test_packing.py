"""Packings from Python: the random start, compression to a target and until jammed, the
contact network against the library's rules, and determinism."""
import math

import numpy as np
import pytest

import carom


def test_compression_reaches_the_target_without_overlap():
    world = carom.make_packing_world(n=200, mix=(1.4, 0.5), seed=2, sized_for_eta=0.7)
    assert carom.packing_fraction(world) == pytest.approx(0.3, rel=1e-12)
    result = carom.compress(world, rate=0.01, eta=0.7)
    assert result["end"] == "target" and not result["jammed"]
    assert result["eta"] == pytest.approx(0.7, abs=1e-12)
    assert world.audit() is None
    assert world.settings["growth_rate"] == 0.0


def test_bidisperse_disks_jam_near_isostatic_and_agree_with_the_network():
    world = carom.make_packing_world(n=150, mix=(1.4, 0.5), seed=4)
    result = carom.compress(world, rate=3e-3)
    assert result["jammed"] and result["pressure"] >= 1e12
    assert 0.82 < result["eta"] < 0.86
    net = carom.contact_network(world)
    n = len(world)
    assert net["contacts"].shape == (n,) and net["rattler"].shape == (n,)
    assert net["pairs"].shape[1] == 2 and (net["pairs"][:, 0] < net["pairs"][:, 1]).all()
    # Each disk's count is its appearances among the pairs (periodic: no walls).
    counts = np.bincount(net["pairs"].ravel(), minlength=n)
    assert (counts == net["contacts"]).all()
    assert net["rattlers"] == int(net["rattler"].sum())
    held = n - net["rattlers"]
    assert net["Z"] == pytest.approx(4.0 - 4.0 / held, abs=0.1)
    assert carom.psi6(world) < 0.3


def test_same_seed_same_packing_and_bad_arguments():
    a = carom.make_packing_world(n=100, seed=7)
    b = carom.make_packing_world(n=100, seed=7)
    carom.compress(a, rate=0.02, eta=0.6)
    carom.compress(b, rate=0.02, eta=0.6)
    assert (a.positions == b.positions).all()
    with pytest.raises(carom.InvalidArgument):
        carom.compress(a, rate=-1.0)
    with pytest.raises(carom.InvalidArgument):
        carom.make_packing_world(n=1)
    with pytest.raises(ValueError):
        carom.make_packing_world(n=100, boundary="open")
    assert carom.contact_tolerance_at_pressure(1e12) == pytest.approx(1e-9)
    assert math.isclose(carom.contact_tolerance_at_pressure(10.0), 1e-2)
