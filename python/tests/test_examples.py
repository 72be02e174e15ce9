"""The example scripts of examples/python run, each at a small size, with this interpreter and
this carom, in a fresh folder: they write their pictures and files and print numbers that agree
with the physics they show."""
import os
import pathlib
import re
import subprocess
import sys

import numpy as np
import pytest

import carom

pytest.importorskip("matplotlib")

SCRIPTS = pathlib.Path(
    os.environ.get("CAROM_EXAMPLES", pathlib.Path(__file__).parents[2] / "examples")
) / "python"

# The scripts import the carom this process imports.
PACKAGE_DIR = str(pathlib.Path(carom.__file__).resolve().parents[1])
ENV = {**os.environ, "MPLBACKEND": "Agg",
       "PYTHONPATH": os.pathsep.join([PACKAGE_DIR, *filter(None, [os.environ.get("PYTHONPATH")])])}

PNG = b"\x89PNG\r\n\x1a\n"
NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"


def run_example(name, *args, cwd):
    done = subprocess.run([sys.executable, str(SCRIPTS / name), *args], cwd=cwd, env=ENV,
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, f"{name} failed:\n{done.stdout}\n{done.stderr}"
    return done.stdout


def value(text, pattern):
    """The number that follows `pattern` in the printed text."""
    found = re.search(pattern + r"\s*(" + NUMBER + ")", text, re.MULTILINE)
    assert found, f"no {pattern!r} in:\n{text}"
    return float(found.group(1))


def rows(text, columns):
    """The lines of a printed table that start with a number, split into `columns` fields."""
    found = [line.split() for line in text.splitlines() if re.match(r"\s*" + NUMBER + r"\s", line)]
    return [row for row in found if len(row) == columns]


def assert_png(path):
    assert path.is_file()
    data = path.read_bytes()
    assert data.startswith(PNG) and len(data) > 10_000  # a drawn figure, not an empty canvas


@pytest.mark.skipif(not hasattr(carom, "eos"), reason="built without the tool")
def test_eos_curve_follows_henderson(tmp_path):
    out = run_example("eos_curve.py", "--quick", cwd=tmp_path)  # default --out: the cwd
    assert_png(tmp_path / "eos.png")
    table = np.array(rows(out, 5), dtype=float)
    eta, z, z_err, z_h = table[:, :4].T
    assert eta.tolist() == [0.1, 0.3, 0.5]
    assert (z > 1).all() and (np.diff(z) > 0).all()
    assert (z_err > 0).all() and (z_err < 0.05 * z).all()
    assert z_h == pytest.approx((1 + eta**2 / 8) / (1 - eta) ** 2, abs=1e-4)
    # Henderson's form is within a percent of the fluid up to eta ~ 0.6; this allows the noise.
    assert z == pytest.approx(z_h, rel=0.03)


@pytest.mark.skipif(not hasattr(carom, "eos"), reason="built without the tool")
def test_eos_mpi_keeps_its_runs_and_reads_them_again(tmp_path):
    out = run_example("eos_mpi.py", "--quick", "--out", str(tmp_path), cwd=tmp_path)
    table = np.array(rows(out, 5), dtype=float)
    eta, z, block_err, seed_err, ratio = table.T
    assert eta.tolist() == [0.3, 0.5]
    assert (z > 1).all() and (block_err > 0).all() and (seed_err > 0).all()
    # Four seeds estimate the error between runs from 3 degrees of freedom: the ratio to the
    # block error lies within [0.12, 2.2] 99 % of the time when both errors are honest.
    assert ((ratio > 0.12) & (ratio < 2.2)).all(), out
    assert len(list((tmp_path / "points").glob("*.json"))) == 8
    # Started again, every run is read back: the same table to the last digit.
    assert run_example("eos_mpi.py", "--quick", "--out", str(tmp_path), cwd=tmp_path) == out


def test_billiards_break_contacts(tmp_path):
    out = run_example("billiards_break.py", "--until", "0.6", "--contacts", "12",
                      "--out", "pictures", cwd=tmp_path)
    assert_png(tmp_path / "pictures" / "billiards_break.png")
    table = rows(out, 6)
    assert len(table) == 12
    time, kind, a, b = (np.array(column) for column in list(zip(*table))[:4])
    speed, impulse = np.array([row[4:] for row in table], dtype=float).T
    # The cue ball (6 m/s, 1.27 m from the rack's apex less two radii) opens the break.
    assert (kind[0], a[0], b[0]) == ("ball", "cue", "1")
    assert 0.19 < float(time[0]) < 0.21
    assert 5.5 < speed[0] <= 6.0 + 1e-9
    assert (np.diff(time.astype(float)) >= 0).all()
    # Equal masses m, restitution e: the impulse of a contact is m (1 + e) / 2 times its speed.
    balls = (kind == "ball") & (b != "pocket")
    assert balls.sum() >= 10
    assert impulse[balls] == pytest.approx(0.17 * 1.95 / 2 * speed[balls], rel=2e-3, abs=2e-5)
    assert (impulse > 0).all() and (speed > 0).all()


def test_gravity_drop_settles_without_gaining_energy(tmp_path):
    out = run_example("gravity_drop.py", "--balls", "60", "--until", "10", "--frame", "0.05",
                      "--out", ".", cwd=tmp_path)
    assert_png(tmp_path / "gravity_drop.png")
    assert "resting: 60 of 60" in out  # a pile of inelastic balls comes to rest in finite time
    assert 50 < value(out, r"^energy:.*\(") < 100  # the percentage of the energy lost
    assert value(out, r"relative") < 1e-12  # the energy never rises, to rounding
    assert "overlaps: None" in out


def test_jamming_is_near_isostatic(tmp_path):
    out = run_example("jamming.py", "--n", "100", "--rate", "0.01", "--out", "jam", cwd=tmp_path)
    assert_png(tmp_path / "jam" / "jamming.png")
    assert "jammed: True" in out
    assert 0.82 < value(out, r"^eta") < 0.87
    assert value(out, r"^pressure") >= 1e12
    z, isostatic = value(out, r"^Z"), value(out, r"N_held =")
    assert isostatic == pytest.approx(4 - 4 / (100 - value(out, r"^rattlers")), abs=1e-4)
    assert abs(z - isostatic) < 0.15
    assert value(out, r"^rattlers") < 20
    assert value(out, r"^psi6") < 0.3  # the two sizes keep it from crystallising


def test_gsd_trajectory_reads_back(tmp_path):
    hoomd = pytest.importorskip("gsd.hoomd")
    import gsd

    out = run_example("gsd_trajectory.py", "--n", "50", "--frames", "11", "--interval", "0.2",
                      "--out", "traj", cwd=tmp_path)
    path = tmp_path / "traj" / "gas.gsd"
    assert value(out, r"^frames:") == 11
    assert value(out, r"^particles:") == 50
    assert value(out, r"^collisions:") > 0
    assert value(out, r"after 2:") > 0
    mode = "r" if int(gsd.__version__.split(".")[0]) >= 3 else "rb"
    with hoomd.open(name=str(path), mode=mode) as trajectory:
        assert len(trajectory) == 11
        assert all(frame.particles.N == 50 for frame in trajectory)
        assert trajectory[-1].configuration.dimensions == 2
