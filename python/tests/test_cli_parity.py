"""Python gives the CLI's numbers bit for bit: for every shipped case, summary.json and contact.csv
of `rollbem run --out` against `rollbem.run` (the same doubles: both sides parse the shortest
round-trip text the CLI wrote, or compare the arrays exactly)."""

import math

import numpy as np
import pytest

import rollbem
from conftest import CASES, ROOT, cli, read_contact_csv, read_summary

# Wall-clock values and the command line differ between any two runs.
VARYING = {"timings", "command"}


def differences(a, b, path=""):
    """Paths where two JSON values differ (floats compared exactly)."""
    if isinstance(a, dict) and isinstance(b, dict):
        out = [f"{path}.{k}: only on one side" for k in sorted(set(a) ^ set(b))]
        for k in sorted(set(a) & set(b)):
            if not path and k in VARYING:
                continue
            out += differences(a[k], b[k], f"{path}.{k}")
        return out
    if isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            return [f"{path}: lengths {len(a)} and {len(b)}"]
        return [d for i, (x, y) in enumerate(zip(a, b)) for d in differences(x, y, f"{path}[{i}]")]
    if type(a) is not type(b) or a != b:
        return [f"{path}: {a!r} != {b!r}"]
    return []


def assert_same_contact_line(columns, result):
    assert list(columns) == list(rollbem.CONTACT_COLUMNS)
    for name, texts in columns.items():
        if name == "state":
            assert result.state.tolist() == texts
        elif name == "slip_hbem" and all(t == "" for t in texts):
            assert result.slip_hbem is None
        else:
            values = np.array([float(t) for t in texts])
            got = result.arrays[name]
            assert got.dtype == np.float64 and got.shape == values.shape, name
            # Bit for bit (the CSV writes 0 for -0.0: compare as numbers, which -0.0 == 0 allows).
            assert np.array_equal(got, values), f"{name}: {np.flatnonzero(got != values)[:5]}"


def assert_same_history(cli_csv, history):
    """Result.history against the CLI's own transient.csv, cell for cell: each number equal to
    the digits the CLI printed (bit for bit after parsing), each empty cell masked."""
    import csv

    with open(cli_csv, newline="") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    assert list(history) == header
    for j, name in enumerate(header):
        values = history[name]
        assert len(values) == len(body), name
        for k, row in enumerate(body):
            cell = row[j]
            if cell == "":
                assert np.ma.is_masked(values[k]), (name, k)
            elif name in ("step", "iterations"):
                assert values[k] == int(cell), (name, k)
            else:
                assert not np.ma.is_masked(values[k]) and float(values[k]) == float(cell), (name, k, cell)


@pytest.mark.parametrize("case", CASES, ids=[c.stem for c in CASES])
def test_every_shipped_case_gives_the_cli_numbers(case, tmp_path):
    cli("run", case, "--out", tmp_path / "cli")
    expected = read_summary(tmp_path / "cli")
    if "transient" in expected:
        # A history's results are its files: without a folder it is refused, with one it is
        # the CLI's run (its last step's summary).
        with pytest.raises(rollbem.InputError, match="transient"):
            rollbem.run(case)
        result = rollbem.run(case, out=tmp_path / "py")
        assert differences(expected, result.summary) == []
        assert_same_history(tmp_path / "cli" / "transient.csv", result.history)
        return
    result = rollbem.run(case)
    assert result.history is None
    assert result.output_dir is None
    assert differences(expected, result.summary) == []
    assert result.creepage == expected["creep"] and result.normal_force == expected["normal_force"]
    assert result.regime == expected["slip_regime"] and result.contact == expected["contact"]
    assert_same_contact_line(read_contact_csv(tmp_path / "cli" / "contact.csv"), result)
    assert all(math.isfinite(v) for v in result.timings.values())


def test_out_writes_the_files_the_cli_writes(tmp_path):
    case = "cases/carter_051_true.yaml"
    cli("run", case, "--out", tmp_path / "cli")
    result = rollbem.run(case, out=tmp_path / "py")
    assert result.output_dir == str(tmp_path / "py")
    cli_files = sorted(p.name for p in (tmp_path / "cli").iterdir())
    assert sorted(p.name for p in (tmp_path / "py").iterdir()) == cli_files
    for name in ["contact.csv", "contact.svg"]:
        assert (tmp_path / "py" / name).read_bytes() == (tmp_path / "cli" / name).read_bytes(), name
    assert differences(read_summary(tmp_path / "cli"), read_summary(tmp_path / "py")) == []
    assert differences(read_summary(tmp_path / "py"), result.summary) == []
    # A second run replaces the folder, as the CLI's does.
    rollbem.run(case, set={"contact.friction": 0.2}, out=tmp_path / "py")
    assert read_summary(tmp_path / "py")["case"]["contact"]["friction"] == 0.2


def test_overrides_are_the_cli_set(tmp_path):
    cli(
        "run", "cases/carter_051.yaml", "--out", tmp_path / "cli",
        "--set", "contact.friction=0.3", "--set", "load.tangential.ratio=0.25",
        "--set", "contact.grid={elements: 31, extent: 1.4, element: discontinuous_quadratic}",
        "--set", "output.vtk=true",
    )  # fmt: skip
    result = rollbem.run(
        "cases/carter_051.yaml",
        set={
            "contact.friction": 0.3,
            "load.tangential.ratio": np.float64(0.25),
            "contact.grid": {"elements": 31, "extent": 1.4, "element": "discontinuous_quadratic"},
            "output.vtk": True,
        },
    )
    assert differences(read_summary(tmp_path / "cli"), result.summary) == []
    assert_same_contact_line(read_contact_csv(tmp_path / "cli" / "contact.csv"), result)


def test_a_dict_case_is_the_file_case_and_reads_meshes_from_the_current_directory(monkeypatch, tmp_path):
    by_file = rollbem.run("cases/carter_051_true.yaml")
    case = dict(by_file.case)
    # The mesh paths of the file are relative to cases/: from there the dict reads them too.
    monkeypatch.chdir("cases")
    by_dict = rollbem.run(case)
    # The notices name the mesh by the path it was read from: cases/../meshes/x.msh from the
    # file, ../meshes/x.msh from the dict.
    file_notices = [n.replace("cases/../", "../") for n in by_file.summary.pop("notices")]
    assert by_dict.summary.pop("notices") == file_notices
    assert differences(by_file.summary, by_dict.summary) == []
    for name, values in by_file.arrays.items():
        assert np.array_equal(values, by_dict.arrays[name]), name
    # From elsewhere the same dict names missing meshes: an input error naming the dict case.
    monkeypatch.chdir(tmp_path)
    with pytest.raises(rollbem.InputError, match="mesh"):
        rollbem.run(case)


def test_check_prints_what_the_cli_prints():
    expected = cli("check", "cases/dissimilar_beta0288_004.yaml").stdout
    got = rollbem.check("cases/dissimilar_beta0288_004.yaml")
    assert got["report"] == expected
    assert got["advice"] and got["advice"] in expected
    summary_estimates = rollbem.run("cases/dissimilar_beta0288_004.yaml").summary["estimates"]
    assert got["estimates"] == summary_estimates
    assert got["estimates"]["hertz_half_width"] > 0 and got["estimates"]["hertz_peak_pressure"] > 0
    tight = cli("check", "cases/carter_051.yaml", "--tolerance", "0.001", "--set", "contact.friction=0.2").stdout
    assert rollbem.check("cases/carter_051.yaml", set={"contact.friction": 0.2}, tolerance=0.001)["report"] == tight


def test_check_estimate_prints_what_the_cli_prints():
    """`estimate=True` is `rollbem check --estimate` (but for the seconds the solves took)."""
    import re

    def untimed(text):
        return re.sub(r"solved in [0-9.]+ s", "solved in - s", text)

    expected = cli("check", "cases/carter_051.yaml", "--estimate", "--tolerance", "0.005").stdout
    got = rollbem.check("cases/carter_051.yaml", tolerance=0.005, estimate=True)
    assert untimed(got["report"]) == untimed(expected)
    assert got["items"]["grid error (estimated)"].startswith("pressure ")
    assert "warning: the grid's estimated error" in got["report"]
    with pytest.raises(rollbem.InputError, match="estimate"):
        rollbem.check("cases/carter_051.yaml", estimate="yes")


def test_check_of_a_dict_case_and_to_pandas():
    result = rollbem.run("cases/carter_051.yaml")
    by_dict = rollbem.check(result.case)
    assert by_dict["report"].startswith(f"rollbem check {rollbem.DICT_CASE_NAME}: valid\n")
    assert by_dict["estimates"] == result.summary["estimates"]
    pd = pytest.importorskip("pandas")
    frame = result.to_pandas()
    assert isinstance(frame, pd.DataFrame)
    assert list(frame.columns) == [c for c in rollbem.CONTACT_COLUMNS if result.arrays[c] is not None]
    assert np.array_equal(frame["pressure"].to_numpy(), result.pressure)


def test_rolling_resistance_attribute_is_the_summary_block():
    """A viscoelastic run's rolling resistance: the attribute is summary.json's block, and the
    pressure leans towards the leading edge (a positive resistance)."""
    r = rollbem.run(str(ROOT / "cases" / "visc_cylindr_tc0009.yaml"))
    assert r.rolling_resistance == r.summary["rolling_resistance"]
    assert r.rolling_resistance["coefficient"] > 1e-3
    assert r.rolling_resistance["dissipated_power"] == r.rolling_resistance["force"] * 1000.0
