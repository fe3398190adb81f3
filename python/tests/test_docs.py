"""docs/python.md as written: its ```python blocks, in order, in one namespace, from the
repository's root (the plot with matplotlib's Agg backend)."""

import re

import pytest

from conftest import ROOT


def python_blocks(text):
    return re.findall(r"^```python\n(.*?)^```", text, flags=re.S | re.M)


def test_the_python_page_runs_as_written(monkeypatch):
    pytest.importorskip("matplotlib")
    monkeypatch.setenv("MPLBACKEND", "Agg")
    blocks = python_blocks((ROOT / "docs" / "python.md").read_text())
    assert len(blocks) >= 5
    namespace = {"__name__": "__docs__"}
    for i, block in enumerate(blocks):
        exec(compile(block, f"docs/python.md, python block {i + 1}", "exec"), namespace)
    assert (ROOT / "out" / "python_carter_051.png").stat().st_size > 0
    assert (ROOT / "out" / "python_dict_case" / "contact.csv").is_file()
