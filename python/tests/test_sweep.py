"""rollbem.sweep: Carter's creepage over the load, the CLI's sweep.csv, failed runs as rows."""

import csv
import math

import pytest

import rollbem
from conftest import cli

RATIOS = [0.1, 0.3, 0.5, 0.7, 0.9]


def test_carter_creepage_at_five_loads():
    """|xi| = (mu a / R*)(1 - sqrt(1 - Q/(mu P))) (Carter 1926; docs/validation.md) within 1 %.

    At 81 elements docs/validation.md measures the creepage within 0.2 % of Carter's on
    cases/carter_051.yaml and carter_084.yaml (second-order slip derivative); the 21 elements of
    the shipped case give up to 0.9 % at Q/(mu P) = 0.9, too close to the bound to test it.
    """
    rows = rollbem.sweep(
        "cases/carter_051.yaml",
        vary={"load.tangential.ratio": RATIOS},
        set={"contact.grid.elements": 81},
        jobs=2,
    )
    estimates = rollbem.check("cases/carter_051.yaml")["estimates"]
    a, r_star = estimates["hertz_half_width"], estimates["effective_radius"]
    assert abs(a - 1.0) < 1e-9 and r_star == 50.0  # the case's a = 1 mm, R* = 50 mm
    mu = 0.1
    assert [row["load.tangential.ratio"] for row in rows] == RATIOS
    for row in rows:
        assert row["status"] == "ok" and row["converged"] is True, row
        ratio = row["load.tangential.ratio"]
        assert row["load_ratio"] == pytest.approx(ratio, rel=1e-12)
        carter = mu * a / r_star * (1 - math.sqrt(1 - ratio))
        assert abs(abs(row["creep"]) / carter - 1) < 0.01, (ratio, row["creep"], carter)


def assert_row_is(row, want, skip, rel_tol):
    """A rollbem.sweep row against the CLI's sweep.csv row `want` (text), key by key but those in
    `skip`: empty cells are None, booleans as the CLI writes them, numbers within `rel_tol`
    (0: equal to the digits the CLI printed, parsed)."""
    for key, value in row.items():
        if key in skip:
            continue
        text = want[key]
        if value is None:
            assert text == "", key
        elif isinstance(value, bool):
            assert text == str(value).lower(), key
        elif rel_tol == 0.0:
            assert float(text) == value, (key, text, value)
        else:
            assert math.isclose(float(text), value, rel_tol=rel_tol, abs_tol=1e-15), (key, text, value)


def test_rows_are_the_cli_sweep_csv(tmp_path):
    vary = {"contact.friction": [0.1, 0.3], "load.tangential.ratio": [0.2, 0.75, 1.5]}
    cli(
        "sweep", "cases/dissimilar_beta0288_075.yaml", "--out", tmp_path / "cli",
        "--vary", "contact.friction=0.1,0.3", "--vary", "load.tangential.ratio=0.2,0.75,1.5",
        check=False,
    )  # fmt: skip
    with open(tmp_path / "cli" / "sweep.csv", newline="") as f:
        expected = list(csv.DictReader(f))
    rows = rollbem.sweep("cases/dissimilar_beta0288_075.yaml", vary=vary, jobs=1)
    assert len(rows) == len(expected) == 6
    timing = {"assembly_s", "condense_s", "solve_s", "total_s"}
    # Both solve the runs warm from their neighbours on one shared assembly, the CLI in one
    # chain per thread, this one (jobs=1) in one chain: the same solution to the Newton
    # tolerance (1e-12 of the residual's scale), reached in other iterations with other
    # round-off where the chains are cut differently.
    path = {"iterations", "residual"}
    for row, want in zip(rows, expected):
        assert list(row) == [k for k in want if k != "folder"]
        assert (row["run"], row["status"], row["message"]) == (int(want["run"]), want["status"], want["message"])
        assert_row_is(row, want, skip=timing | path | {"run", "status", "message"}, rel_tol=1e-9)
    # Q/(mu P) = 1.5 cannot be carried: a failed row with the CLI's message, the others ran.
    failed = [r for r in rows if r["status"] == "failed"]
    assert [r["load.tangential.ratio"] for r in failed] == [1.5, 1.5]
    assert all(r["message"] and r["creep"] is None for r in failed)
    assert rollbem.sweep_frame(rows).shape[0] == 6 if _has_pandas() else True


def _has_pandas():
    try:
        import pandas  # noqa: F401
    except ImportError:
        return False
    return True


def test_threads_change_the_numbers_only_within_the_newton_tolerance():
    """jobs=1 solves the six runs in one chain of warm starts, jobs=2 in two: the runs where
    the chains are cut start from other neighbours, so they end elsewhere within the Newton
    tolerance (scaled residual 1e-10: forces and creepage within 1e-9 relative)."""
    vary = {"contact.friction": [0.1, 0.2, 0.4], "load.tangential.ratio": [0.3, 0.6]}
    one = rollbem.sweep("cases/carter_051.yaml", vary=vary, jobs=1)
    two = rollbem.sweep("cases/carter_051.yaml", vary=vary, jobs=2)
    path = {"assembly_s", "condense_s", "solve_s", "total_s", "iterations", "residual"}
    for a, b in zip(one, two):
        assert list(a) == list(b)
        for key in a:
            if key in path:
                continue
            if isinstance(a[key], float):
                assert math.isclose(a[key], b[key], rel_tol=1e-9, abs_tol=1e-12), (key, a[key], b[key])
            else:
                assert a[key] == b[key], key


def test_rows_are_the_cli_sweep_bit_for_bit_on_one_thread(tmp_path, monkeypatch):
    """On one thread both solve the runs as one chain of neighbours on one shared assembly, each
    warm-started from the one before it (the library's rollbem::sweep::summaries for Python, the
    same chains for the CLI): every value of every row equals sweep.csv's, parsed from the digits
    the CLI prints, the Newton iterations and residuals included."""
    monkeypatch.setenv("RAYON_NUM_THREADS", "1")
    cli(
        "sweep", "cases/carter_051.yaml", "--out", tmp_path / "cli",
        "--vary", "contact.friction=0.1,0.2", "--vary", "load.tangential.ratio=0.1,0.5,0.9",
    )  # fmt: skip
    with open(tmp_path / "cli" / "sweep.csv", newline="") as f:
        expected = list(csv.DictReader(f))
    vary = {"contact.friction": [0.1, 0.2], "load.tangential.ratio": [0.1, 0.5, 0.9]}
    rows = rollbem.sweep("cases/carter_051.yaml", vary=vary, jobs=1)
    assert len(rows) == len(expected) == 6
    timing = {"assembly_s", "condense_s", "solve_s", "total_s"}
    for row, want in zip(rows, expected):
        assert row["status"] == want["status"] == "ok"
        assert_row_is(row, want, skip=timing | {"status", "message"}, rel_tol=0.0)


def test_bad_sweeps():
    with pytest.raises(rollbem.InputError, match="nothing to sweep"):
        rollbem.sweep("cases/carter_051.yaml", vary={})
    with pytest.raises(rollbem.InputError, match="jobs"):
        rollbem.sweep("cases/carter_051.yaml", vary={"contact.friction": [0.1]}, jobs=0)
    # True is an integer to Python, not a thread count.
    with pytest.raises(rollbem.InputError, match="jobs"):
        rollbem.sweep("cases/carter_051.yaml", vary={"contact.friction": [0.1]}, jobs=True)
    # More threads than cores: capped, with a warning, not a thousand threads; a million is
    # refused (as `rollbem sweep --jobs`).
    with pytest.warns(RuntimeWarning, match="cores"):
        rows = rollbem.sweep("cases/carter_051.yaml", vary={"contact.friction": [0.1]}, jobs=1000)
    assert rows[0]["status"] == "ok"
    with pytest.raises(rollbem.InputError, match="at most 1024"):
        rollbem.sweep("cases/carter_051.yaml", vary={"contact.friction": [0.1]}, jobs=10**6)
    with pytest.raises(rollbem.InputError, match="cannot read case file"):
        rollbem.sweep("cases/none.yaml", vary={"contact.friction": [0.1]})
    rows = rollbem.sweep("cases/carter_051.yaml", vary={"contact.frictio": [0.1]})
    assert rows[0]["status"] == "failed" and "contact.frictio" in rows[0]["message"]
