"""The code in docs/python.md runs: its Python blocks, in order and in one namespace (each block
may use what an earlier one made), from a scratch folder where examples/ is the repository's."""
import os
import pathlib
import re

import pytest

import carom

DOCS = pathlib.Path(__file__).resolve().parents[2] / "docs" / "python.md"


def python_blocks(text):
    return re.findall(r"```python\n(.*?)```", text, flags=re.DOTALL)


def test_the_guide_has_code():
    assert len(python_blocks(DOCS.read_text())) >= 6


def test_the_guides_code_runs(tmp_path, monkeypatch):
    pytest.importorskip("matplotlib")
    if not hasattr(carom, "gas"):
        pytest.skip("built without the tool: carom.gas is not there")
    monkeypatch.setenv("MPLBACKEND", "Agg")
    (tmp_path / "examples").symlink_to(DOCS.parents[1] / "examples")
    monkeypatch.chdir(tmp_path)
    namespace = {}
    for number, block in enumerate(python_blocks(DOCS.read_text()), start=1):
        try:
            exec(compile(block, f"{DOCS.name}, block {number}", "exec"), namespace)
        except Exception as error:  # the block's number says where to look
            pytest.fail(f"docs/python.md, Python block {number} fails: {error!r}\n{block}")
    assert os.path.getsize("run.gsd") > 0 and os.path.getsize("copy.json") > 0
