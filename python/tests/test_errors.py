"""Each exception class for an input of its kind, with the CLI's message and exit code."""

import math
from fractions import Fraction

import numpy as np
import pytest

import rollbem
from conftest import ROOT as ROOT_DIR, cli


def test_a_bad_key_is_an_input_error_with_the_cli_message(tmp_path):
    done = cli("run", "cases/carter_051.yaml", "--set", "contact.frictio=0.2", "--out", tmp_path / "o", check=False)
    assert done.returncode == 1
    with pytest.raises(rollbem.InputError) as caught:
        rollbem.run("cases/carter_051.yaml", set={"contact.frictio": 0.2}, out=tmp_path / "p")
    assert f"error: {caught.value}\n" == done.stderr
    assert "contact.frictio" in str(caught.value)
    assert not (tmp_path / "p").exists()
    assert isinstance(caught.value, rollbem.RollbemError)


def test_other_input_errors():
    with pytest.raises(rollbem.InputError, match="cannot read case file"):
        rollbem.run("cases/no_such_case.yaml")
    with pytest.raises(rollbem.InputError, match="friction"):
        rollbem.run("cases/carter_051.yaml", set={"contact.friction": -1})
    with pytest.raises(rollbem.InputError, match="finite"):
        rollbem.run("cases/carter_051.yaml", set={"contact.friction": float("nan")})
    with pytest.raises(rollbem.InputError, match="tolerance"):
        rollbem.check("cases/carter_051.yaml", tolerance=0)
    with pytest.raises(rollbem.InputError, match="top level|title|missing"):
        rollbem.run({"title": "nothing else"})
    with pytest.raises(rollbem.InputError, match="case must be a path"):
        rollbem.run(42)


def test_a_folder_that_is_not_rollbems_is_refused(tmp_path):
    (tmp_path / "mine.txt").write_text("not rollbem's")
    with pytest.raises(rollbem.InputError, match="mine.txt|rollbem did not write"):
        rollbem.run("cases/carter_051.yaml", out=tmp_path)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["mine.txt"]


def test_an_exhausted_iteration_budget_is_not_converged_with_the_partial_result(tmp_path):
    done = cli("run", "cases/carter_051.yaml", "--set", "solver.max_iterations=1", "--out", tmp_path / "cli", check=False)
    assert done.returncode == 2
    with pytest.raises(rollbem.NotConverged) as caught:
        rollbem.run("cases/carter_051.yaml", set={"solver.max_iterations": 1}, out=tmp_path / "py")
    e = caught.value
    assert "did not converge in 1 iterations" in str(e) and "max_iterations" in str(e)
    assert f"error: {e}\n".replace(str(tmp_path / "py"), str(tmp_path / "cli")) == done.stderr
    r = e.result
    assert r is not None and r.converged is False and r.iterations == 1
    assert r.pressure.shape == r.x.shape and r.x.size > 0
    assert e.estimate == {"residual": r.residual, "iterations": 1} and r.residual > 1e-10
    # As the CLI: only summary.json is written, with converged false.
    assert sorted(p.name for p in (tmp_path / "py").iterdir() if not p.name.startswith(".")) == ["summary.json"]


def test_a_missed_grid_tolerance_is_not_converged_with_the_estimate():
    with pytest.raises(rollbem.NotConverged) as caught:
        rollbem.run(
            "cases/carter_051.yaml",
            set={"contact.grid.tolerance": 1e-6, "contact.grid.max_elements": 50},
        )
    e = caught.value
    assert e.result is None
    assert e.estimate["tolerance"] == 1e-6 and e.estimate["max_elements"] == 50
    assert max(e.estimate["pressure"], e.estimate["shear"], e.estimate["creep"]) > 1e-6
    assert "max_elements" in str(e)


def test_a_panic_is_an_internal_error_not_a_crash():
    # No input is known to make the library panic: a hidden hook panics inside the same guard
    # that every call runs in.
    with pytest.raises(rollbem.InternalError, match="internal error — please report it.*deliberate"):
        rollbem._rollbem._panic_for_tests("deliberate")
    # The module still works afterwards.
    assert rollbem.run("cases/carter_051.yaml").converged


def nested(depth):
    value = 1.0
    for _ in range(depth):
        value = [value]
    return value


CARTER = "cases/carter_051.yaml"
ONE = {"contact.friction": [0.1]}

# (call, what the message names): every bad argument is an InputError (before: ValueError,
# OverflowError, RecursionError, TypeError).
BAD_ARGUMENTS = {
    "jobs=True": (lambda: rollbem.sweep(CARTER, vary=ONE, jobs=True), "jobs"),
    "jobs=-1": (lambda: rollbem.sweep(CARTER, vary=ONE, jobs=-1), "jobs"),
    "jobs=2.5": (lambda: rollbem.sweep(CARTER, vary=ONE, jobs=2.5), "jobs"),
    "jobs='2'": (lambda: rollbem.sweep(CARTER, vary=ONE, jobs="2"), "jobs"),
    "jobs=10**30": (lambda: rollbem.sweep(CARTER, vary=ONE, jobs=10**30), "at most 1024"),
    "set nan": (lambda: rollbem.run(CARTER, set={"contact.friction": float("nan")}), "set['contact.friction']"),
    "set inf": (lambda: rollbem.run(CARTER, set={"contact.friction": math.inf}), "set['contact.friction']"),
    "set 10**5000": (lambda: rollbem.run(CARTER, set={"contact.grid.elements": 10**5000}), "contact.grid.elements"),
    "set Fraction 10**400": (lambda: rollbem.run(CARTER, set={"contact.friction": Fraction(10**400, 3)}), "set['contact.friction']"),
    "set nested 100000": (lambda: rollbem.run(CARTER, set={"contact.grid": nested(100_000)}), "set['contact.grid']"),
    "set [nan]": (lambda: rollbem.run(CARTER, set={"contact.grid": [np.nan]}), "set['contact.grid']"),
    "set complex": (lambda: rollbem.run(CARTER, set={"contact.friction": 1j}), "set['contact.friction']"),
    "set object": (lambda: rollbem.run(CARTER, set={"contact.friction": object()}), "set['contact.friction']"),
    "set key 1": (lambda: rollbem.run(CARTER, set={1: 0.2}), "set"),
    "set list": (lambda: rollbem.run(CARTER, set=[("contact.friction", 0.2)]), "set"),
    "case object": (lambda: rollbem.run(object()), "case"),
    "case 42": (lambda: rollbem.check(42), "case"),
    "case nested": (lambda: rollbem.run({"title": nested(100_000)}), "case"),
    "case nan": (lambda: rollbem.run({"title": "x", "contact": {"friction": math.nan}}), "case"),
    "case NUL": (lambda: rollbem.run("cases/carter\0.yaml"), "case"),
    "out=123": (lambda: rollbem.run(CARTER, out=123), "out"),
    "out NUL": (lambda: rollbem.run(CARTER, out="out/a\0b"), "out"),
    "tolerance abc": (lambda: rollbem.check(CARTER, tolerance="abc"), "tolerance"),
    "tolerance None": (lambda: rollbem.check(CARTER, tolerance=None), "tolerance"),
    "tolerance True": (lambda: rollbem.check(CARTER, tolerance=True), "tolerance"),
    "tolerance 10**400": (lambda: rollbem.check(CARTER, tolerance=10**400), "tolerance"),
    "tolerance nan": (lambda: rollbem.check(CARTER, tolerance=math.nan), "tolerance"),
    "vary None": (lambda: rollbem.sweep(CARTER, vary=None), "vary"),
    "vary 'abc'": (lambda: rollbem.sweep(CARTER, vary={"contact.friction": "abc"}), "vary['contact.friction']"),
    "vary [nan]": (lambda: rollbem.sweep(CARTER, vary={"contact.friction": [math.nan]}), "vary['contact.friction']"),
    "vary [10**5000]": (lambda: rollbem.sweep(CARTER, vary={"contact.grid.elements": [10**5000]}), "contact.grid.elements"),
    "vary nested": (lambda: rollbem.sweep(CARTER, vary={"contact.grid": [nested(100_000)]}), "vary['contact.grid']"),
    "vary key 1": (lambda: rollbem.sweep(CARTER, vary={1: [0.1]}), "vary"),
    "sweep of a history": (lambda: rollbem.sweep("cases/cattaneo_to_carter.yaml", vary=ONE), "transient=null"),
}


@pytest.mark.parametrize("name", list(BAD_ARGUMENTS))
def test_a_bad_argument_is_an_input_error_naming_it(name, monkeypatch):
    monkeypatch.chdir(ROOT_DIR)
    call, argument = BAD_ARGUMENTS[name]
    with pytest.raises(rollbem.InputError) as caught:
        call()
    assert argument in str(caught.value), str(caught.value)
    assert not (ROOT_DIR / "out" / "a").exists()
