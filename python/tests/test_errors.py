"""Each exception class for an input of its kind, with the CLI's message and exit code."""

import pytest

import rollbem
from conftest import cli


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
    with pytest.raises(TypeError):
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
