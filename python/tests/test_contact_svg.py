"""contact.svg of a run with a rolling speed (a viscoelastic body) shows the rolling resistance:
F_r and F_r/P, the pressure centre and both contact edges; an elastic run's shows none of it."""

import re

import rollbem
from conftest import ROOT


def number_after(label, svg):
    found = re.search(re.escape(label) + r"\s*([-+]?[0-9.]+(?:e[-+]?[0-9]+)?)", svg)
    assert found, f"contact.svg lacks `{label}`"
    return float(found.group(1))


def test_a_viscoelastic_runs_plot_shows_its_rolling_resistance(tmp_path, monkeypatch):
    monkeypatch.chdir(ROOT)
    r = rollbem.run("cases/hunter_rigid_on_sls.yaml", out=tmp_path / "sls")
    svg = (tmp_path / "sls" / "contact.svg").read_text()
    rr = r.rolling_resistance
    # Hunter (1961): F_r/P = 3.9369e-3, the pressure centre 0.39369 mm towards the leading edge.
    assert abs(rr["coefficient"] / 3.9369e-3 - 1) < 0.01
    for label, value in [
        ("F_r =", rr["force"]),
        ("F_r/P =", rr["coefficient"]),
        ("pressure centre", rr["pressure_centre"]),
        ("leading edge", rr["leading_edge"]),
        ("trailing edge", rr["trailing_edge"]),
    ]:
        assert abs(number_after(label, svg) - value) <= 1e-4 * abs(value), label
    for text in ["towards the leading edge", "leading edge", "trailing edge", "pressure centre"]:
        assert text in svg, text
    assert abs(rr["leading_edge"] - 1.8967) < 0.01 and abs(rr["trailing_edge"] + 1.3169) < 0.01


def test_an_elastic_runs_plot_has_no_rolling_resistance(tmp_path, monkeypatch):
    monkeypatch.chdir(ROOT)
    rollbem.run("cases/carter_051.yaml", out=tmp_path / "elastic")
    svg = (tmp_path / "elastic" / "contact.svg").read_text()
    assert "leading edge" in svg
    for text in ["F_r", "pressure centre", "trailing edge"]:
        assert text not in svg, text
