"""Ctrl-C (SIGINT) stops a long run or sweep within seconds with KeyboardInterrupt, and the
module works afterwards; threads writing one output folder: one writes it, the others are
refused as the CLI's second process is."""

import json
import signal
import subprocess
import sys
import textwrap
import threading
import time

import pytest

import rollbem
from conftest import ROOT

# Each some 10 s on the two-core development machine (a Newton step of the 701-element grid
# takes about half a second); interrupted 2 s in.
LONG_RUN = """
    out = sys.argv[1]
    rollbem.run("cases/carter_051.yaml", set={"contact.grid.elements": 701}, out=out)
"""
LONG_SWEEP = """
    rollbem.sweep("cases/carter_051.yaml", vary={"contact.friction": [0.1, 0.15, 0.2, 0.25, 0.3, 0.35, 0.4]},
                  set={"contact.grid.elements": 601}, jobs=1)
"""
CHILD = """
import sys, time
import rollbem
try:
{work}
    print("finished")
except KeyboardInterrupt:
    print("interrupted")
    print(rollbem.run("cases/carter_051.yaml").converged)
"""


@pytest.mark.skipif(sys.platform == "win32", reason="SIGINT is a POSIX signal")
@pytest.mark.parametrize("work", [LONG_RUN, LONG_SWEEP], ids=["run", "sweep"])
def test_ctrl_c_stops_a_long_call_within_seconds(work, tmp_path):
    code = CHILD.format(work=textwrap.indent(textwrap.dedent(work), "    "))
    out = tmp_path / "res"
    child = subprocess.Popen(
        [sys.executable, "-c", code, str(out)], cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True
    )
    time.sleep(2.0)
    assert child.poll() is None, child.communicate()
    sent = time.monotonic()
    child.send_signal(signal.SIGINT)
    try:
        stdout, stderr = child.communicate(timeout=12)
    except subprocess.TimeoutExpired:
        child.kill()
        child.communicate()
        pytest.fail("still solving 12 s after SIGINT")
    # The interrupt, then a short run of carter_051 (about 0.5 s).
    assert time.monotonic() - sent < 8
    assert child.returncode == 0, stderr
    assert stdout.split() == ["interrupted", "True"], stderr
    # Nothing written, no lock file left (a run that was not stopped writes its folder, however
    # fast the machine).
    assert sorted(p.name for p in tmp_path.iterdir()) == []


def race(target, out, n=4):
    """Runs `target(out)` on `n` threads started together; returns their results or errors."""
    start = threading.Barrier(n)
    outcomes = [None] * n

    def one(k):
        start.wait()
        try:
            outcomes[k] = target(out)
        except Exception as e:  # noqa: BLE001 - each outcome is checked below
            outcomes[k] = e

    threads = [threading.Thread(target=one, args=(k,)) for k in range(n)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    return outcomes


@pytest.mark.parametrize("case", ["file", "dict"])
def test_threads_writing_one_folder_one_wins(case, tmp_path):
    source = "cases/carter_051.yaml"
    if case == "dict":
        source = rollbem.check(source)["case"]
    out = tmp_path / "res"
    for attempt in range(2):  # into a new folder, then over the earlier result
        outcomes = race(lambda o: rollbem.run(source, out=o), out)
        won = [o for o in outcomes if isinstance(o, rollbem.Result)]
        refused = [o for o in outcomes if not isinstance(o, rollbem.Result)]
        assert len(won) == 1, outcomes
        for e in refused:
            assert isinstance(e, rollbem.InputError), repr(e)
            assert "is being written by another rollbem process" in str(e)
        written = json.loads((out / "summary.json").read_text())
        assert written["creep"] == won[0].creepage
        assert sorted(p.name for p in tmp_path.iterdir()) == ["res"], attempt
