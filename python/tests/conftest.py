"""Shared helpers of the Python module's tests: the repository's root, its shipped cases, and the
`rollbem` program that CI builds before these tests (target/release/rollbem, or $ROLLBEM_BIN)."""

import csv
import json
import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
CASES = sorted((ROOT / "cases").glob("*.yaml"))


def cli_binary() -> Path:
    path = Path(os.environ.get("ROLLBEM_BIN", ROOT / "target" / "release" / "rollbem"))
    if not path.is_file():
        pytest.fail(f"{path} is missing: build the program first (cargo build --release)")
    return path


def cli(*args, check=True):
    """Runs the program with `args` from the repository's root; returns the CompletedProcess."""
    done = subprocess.run([str(cli_binary()), *map(str, args)], cwd=ROOT, capture_output=True, text=True)
    if check and done.returncode != 0:
        raise AssertionError(f"rollbem {' '.join(map(str, args))} exited {done.returncode}:\n{done.stderr}")
    return done


def read_contact_csv(path: Path):
    """contact.csv as {column: list of text}, in the file's column order."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    return {name: [r[i] for r in body] for i, name in enumerate(header)}


def read_summary(folder: Path):
    return json.loads((folder / "summary.json").read_text())


@pytest.fixture(autouse=True)
def at_root(monkeypatch):
    """Every test starts in the repository's root (the cases' paths are relative to it)."""
    monkeypatch.chdir(ROOT)
