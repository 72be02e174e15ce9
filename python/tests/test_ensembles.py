"""carom.eos shared among processes (comm: an mpi4py communicator) and kept as it goes
(checkpoints: a folder): rank 0 gets the same points, bit for bit, as one process; a sweep started
again reads the runs it kept instead of running them, and so does `carom eos --out` on the same
files."""
import json
import os
import pathlib
import shutil
import subprocess
import sys
import threading

import pytest

import carom
from test_science import same_numbers, tool

pytestmark = pytest.mark.skipif(not hasattr(carom, "eos"), reason="built without the tool")

GAS = dict(n=64, equilibrate=5, collisions=40, seed=3, blocks=4, threads=1)
ETAS = [0.2, 0.3, 0.4]


class ThreadComm:
    """mpi4py's Get_rank, Get_size, bcast and gather for ranks that are threads of this process:
    the collective calls meet at a barrier, as an MPI job's ranks meet in the library."""

    def __init__(self, rank, size, shared):
        self.rank, self.size, self.shared = rank, size, shared

    def Get_rank(self):  # noqa: N802 (mpi4py's name)
        return self.rank

    def Get_size(self):  # noqa: N802
        return self.size

    def bcast(self, obj, root=0):
        if self.rank == root:
            self.shared["bcast"] = obj
        self.shared["barrier"].wait()
        value = self.shared["bcast"]
        self.shared["barrier"].wait()
        return value

    def gather(self, obj, root=0):
        self.shared["gathered"][self.rank] = obj
        self.shared["calls"][self.rank] += 1
        self.shared["barrier"].wait()
        value = list(self.shared["gathered"]) if self.rank == root else None
        self.shared["barrier"].wait()
        return value


def as_ranks(size, sweep):
    """sweep(comm) on `size` threads, each a rank; what each returned, in rank order."""
    shared = {"barrier": threading.Barrier(size), "gathered": [None] * size, "calls": [0] * size}
    results, errors = [None] * size, []

    def rank(r):
        try:
            results[r] = sweep(ThreadComm(r, size, shared))
        except BaseException as error:  # noqa: B036 (reported by the test)
            errors.append(error)
            shared["barrier"].abort()

    threads = [threading.Thread(target=rank, args=(r,)) for r in range(size)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    if errors:
        raise errors[0]
    return results, shared


def same_points(a, b):
    assert len(a["points"]) == len(b["points"])
    for p, q in zip(a["points"], b["points"]):
        same_numbers({k: v for k, v in p.items() if k != "runs"},
                     {k: v for k, v in q.items() if k != "runs"})
        for x, y in zip(p.get("runs", []), q.get("runs", []), strict=True):
            same_numbers(x, y)


def test_runs_shared_among_ranks_give_rank_0_the_same_points():
    alone = carom.eos(ETAS, seeds=2, **GAS)
    results, shared = as_ranks(3, lambda comm: carom.eos(ETAS, seeds=2, comm=comm, **GAS))
    assert results[1] is None and results[2] is None
    same_points(results[0], alone)
    # Every rank sent its runs to rank 0: 6 runs, two each.
    assert shared["calls"] == [1, 1, 1]
    assert [len(json.loads(m)) for m in shared["gathered"]] == [2, 2, 2]


def test_more_ranks_than_runs():
    alone = carom.eos([0.3], **GAS)
    results, shared = as_ranks(3, lambda comm: carom.eos([0.3], comm=comm, **GAS))
    same_points(results[0], alone)
    assert [len(json.loads(m)) for m in shared["gathered"]] == [1, 0, 0]


def test_a_comm_of_one_is_one_process():
    results, _ = as_ranks(1, lambda comm: carom.eos(ETAS, comm=comm, **GAS))
    same_points(results[0], carom.eos(ETAS, **GAS))


def test_a_comm_that_is_not_one_is_refused():
    with pytest.raises(TypeError, match=r"comm must be an mpi4py communicator \(it has no "
                                        r"Get_rank\(\)\)"):
        carom.eos([0.3], comm=object(), **GAS)


def test_checkpoints_are_read_instead_of_run_again(tmp_path):
    folder = tmp_path / "points"
    first = carom.eos(ETAS, seeds=2, checkpoints=folder, **GAS)
    kept = sorted(folder.iterdir())
    assert len(kept) == 6 and all(p.suffix == ".json" for p in kept)
    stamps = {p.name: p.stat().st_mtime_ns for p in kept}
    # Started again: every run read (no file written again), the same numbers.
    same_points(carom.eos(ETAS, seeds=2, checkpoints=str(folder), **GAS), first)
    assert {p.name: p.stat().st_mtime_ns for p in folder.iterdir()} == stamps
    # A run lost (a sweep killed before it ended) is run again, alone.
    kept[2].unlink()
    same_points(carom.eos(ETAS, seeds=2, checkpoints=folder, **GAS), first)
    assert sorted(p.name for p in folder.iterdir()) == sorted(stamps)
    # Shared among ranks, with the checkpoints of one process: nothing left to run.
    results, shared = as_ranks(2, lambda comm: carom.eos(ETAS, seeds=2, comm=comm,
                                                         checkpoints=folder, **GAS))
    same_points(results[0], first)
    assert [len(json.loads(m)) for m in shared["gathered"]] == [0, 0]


def test_the_tool_reads_what_python_kept(tmp_path):
    carom.eos(ETAS, checkpoints=tmp_path / "sweep" / "points", **GAS)
    options = [f"--{k}={v}" for k, v in GAS.items()]
    done = subprocess.run([tool(), "eos", "--eta=0.2:0.4:0.1", *options, "--out",
                           str(tmp_path / "sweep"), "--json"],
                          capture_output=True, text=True, check=True)
    assert "3 of 3 runs read from" in done.stderr
    same_points(json.loads(done.stdout), carom.eos(ETAS, **GAS))


def test_a_folder_that_cannot_be_made_is_named(tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("")
    with pytest.raises(ValueError, match=f"^checkpoints = {blocker}/points: cannot create it"):
        carom.eos([0.3], checkpoints=blocker / "points", **GAS)


def mpirun():
    found = shutil.which("mpirun")
    if found is None:
        pytest.skip("mpirun is missing: sudo apt-get install -y openmpi-bin")
    try:
        import mpi4py  # noqa: F401
    except ImportError:
        pytest.skip("mpi4py is missing: sudo apt-get install -y python3-mpi4py")
    return found


def test_mpi4py_ranks_under_mpirun_give_the_same_points(tmp_path):
    script = tmp_path / "sweep.py"
    script.write_text(
        "import json, sys\n"
        "from mpi4py import MPI\n"
        "import carom\n"
        f"points = carom.eos({ETAS}, seeds=2, comm=MPI.COMM_WORLD, **{GAS!r})\n"
        "if MPI.COMM_WORLD.Get_rank() == 0:\n"
        "    print(json.dumps(points))\n"
        "else:\n"
        "    assert points is None\n")
    env = dict(os.environ, PYTHONPATH=str(pathlib.Path(carom.__file__).resolve().parents[1]))
    done = subprocess.run([mpirun(), "--oversubscribe", "--allow-run-as-root", "-n", "3",
                           sys.executable, str(script)],
                          capture_output=True, text=True, env=env, timeout=120)
    assert done.returncode == 0, done.stderr
    same_points(json.loads(done.stdout), carom.eos(ETAS, seeds=2, **GAS))


JAMMING = dict(n=120, mix=(1.4, 0.5), rate=0.01, pressure_limit=1e6)


def same_packings(a, b):
    timings = {"wall_seconds", "collisions_per_second"}
    assert {k: v for k, v in a.items() if k != "runs"} == {k: v for k, v in b.items() if k != "runs"}
    for x, y in zip(a["runs"], b["runs"], strict=True):
        assert {k: v for k, v in x.items() if k not in timings} == \
               {k: v for k, v in y.items() if k not in timings}


def test_pack_seeds_is_the_tools_and_each_run_that_seeds_packing():
    ours = carom.pack(seeds=3, seed=2, **JAMMING)
    done = subprocess.run([tool(), "pack", "--n=120", "--mix=1.4:0.5", "--rate=0.01",
                           "--until-jammed", "--pressure-limit=1e6", "--seed=2", "--seeds=3",
                           "-q", "--json"], capture_output=True, text=True, check=True)
    same_packings(ours, json.loads(done.stdout))
    assert ours["seeds"] == 3 and ours["first_seed"] == 2 and ours["completed"] == 3
    alone = carom.pack(seed=3, **JAMMING)
    assert ours["runs"][1]["eta"] == alone["eta"] and ours["runs"][1]["Z"] == alone["Z"]
    with pytest.raises(ValueError, match="^seeds = 0"):
        carom.pack(seeds=0, **JAMMING)


def test_pack_seeds_shared_among_ranks_and_kept(tmp_path):
    alone = carom.pack(seeds=4, **JAMMING)
    results, shared = as_ranks(3, lambda comm: carom.pack(seeds=4, threads=1, comm=comm,
                                                          out=tmp_path / "jams", **JAMMING))
    assert results[1] is None and results[2] is None
    same_packings(results[0], alone)
    assert [len(json.loads(m)) for m in shared["gathered"]] == [2, 1, 1]
    assert sorted(p.name for p in (tmp_path / "jams").glob("seed-*.json")) == \
        [f"seed-{s}.json" for s in range(1, 5)]
    # Started again: every packing read, the reports (timings and all) the same.
    again = carom.pack(seeds=4, out=tmp_path / "jams", **JAMMING)
    assert again == results[0]
