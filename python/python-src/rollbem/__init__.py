"""rollbem from Python: 2D steady rolling contact of elastic cylinders.

The same solver as the ``rollbem`` program, called in-process::

    import rollbem
    r = rollbem.run("cases/carter_051.yaml")
    r.creepage, r.normal_force          # numbers of summary.json
    r.x, r.pressure, r.shear            # contact.csv's columns as numpy arrays

Units are the case's own (``units: {length: mm, force: N}`` by default): lengths in the length
unit, forces per length of the cylinders in force/length, stresses in force/length^2, creepage
and slip dimensionless. Signs are those of docs/outputs.md: pressure p >= 0 compressive, shear q
the traction of B on A along +x, creepage xi = (V_A - V_B)/V.

Functions: :func:`run`, :func:`check`, :func:`sweep` (and :func:`sweep_frame`). Errors:
:class:`InputError`, :class:`NotConverged`, :class:`InternalError` (subclasses of
:class:`RollbemError`), one per exit code of the program. The solver runs without the GIL, so
Python threads run cases in parallel. The library's log messages go to :mod:`logging`, logger
``"rollbem"`` (per-iteration progress at INFO on ``"rollbem.progress"``).
"""

from __future__ import annotations

import itertools
import json
import math
import numbers
import os
import warnings
from typing import Any, Dict, List, Mapping, Optional, Sequence, Union

import numpy as np

from . import _rollbem
from ._errors import InputError, InternalError, NotConverged, RollbemError

__version__: str = _rollbem.__version__

__all__ = [
    "run",
    "check",
    "sweep",
    "sweep_frame",
    "Result",
    "RollbemError",
    "InputError",
    "NotConverged",
    "InternalError",
    "CONTACT_COLUMNS",
]

#: contact.csv's columns, in order: the arrays of a :class:`Result` have these names (the
#: writer's own list, from the Rust library).
CONTACT_COLUMNS = tuple(_rollbem.CONTACT_COLUMNS)

#: The name a case given as a dict goes by in messages. Its folder is the current directory, so
#: relative paths inside a dict case (meshes) are read from the current working directory.
DICT_CASE_NAME = "<case dict>"

Case = Union[str, "os.PathLike[str]", Mapping[str, Any]]


#: What JSON encoding raises for a value that is no case value: a wrong type (TypeError), NaN, a
#: circular reference or an integer of more digits than Python prints (ValueError), nesting
#: deeper than Python's recursion limit (RecursionError).
_ENCODING_ERRORS = (TypeError, ValueError, RecursionError)


# Most threads a sweep takes, the library's bound of `rollbem sweep --jobs` (src/sweep.rs): a
# larger count is a mistake (a typo, a product of numbers), refused rather than capped.
_MAX_JOBS = _rollbem.MAX_JOBS

def _json(value: Any) -> str:
    """A case value as JSON text (a YAML flow document); raises one of ``_ENCODING_ERRORS``."""
    return json.dumps(value, allow_nan=False, default=_plain)


def _case_source(case: Case) -> "tuple[str, Optional[str]]":
    """(path, text): a case file's path, or the dict as JSON text (a YAML document) and its name."""
    if isinstance(case, Mapping):
        try:
            text = _json(case)
        except _ENCODING_ERRORS as e:
            raise InputError(f"case: {DICT_CASE_NAME} cannot be written as a case: {_why(e)}") from None
        return DICT_CASE_NAME, text
    if isinstance(case, (str, bytes, os.PathLike)):
        return _path("case", case), None
    raise InputError(f"case must be a path (str or os.PathLike) or a dict, not {type(case).__name__}")


def _path(argument: str, value: Any) -> str:
    """The path `value` (str, bytes or os.PathLike) as a str; InputError naming `argument` else."""
    try:
        path = os.fspath(value)
    except TypeError:
        raise InputError(
            f"{argument} must be a path (str or os.PathLike), not {type(value).__name__}"
        ) from None
    if isinstance(path, bytes):
        path = os.fsdecode(path)
    if "\0" in path:
        raise InputError(f"{argument}: the path {path!r} holds a NUL character, which no file name can")
    return path


def _why(e: BaseException) -> str:
    """What an encoding error says, in words for a case value."""
    if isinstance(e, RecursionError):
        return "it is nested deeper than Python can write"
    return str(e)


def _plain(value: Any) -> Any:
    """numpy scalars and arrays as plain Python numbers and lists (for JSON)."""
    if isinstance(value, np.generic):
        return value.item()
    if isinstance(value, np.ndarray):
        return value.tolist()
    raise TypeError(f"{value!r} ({type(value).__name__}) is not a case value")


def _value_text(key: str, value: Any, argument: str = "set") -> str:
    """A value as ``--set`` takes it (read as YAML): true/false, null, the shortest round-trip
    digits of a number, a string as it is, a list or mapping as JSON (a YAML flow collection).
    A value that is none of these is an InputError naming ``argument[key]``."""
    where = f"{argument}[{key!r}]"
    if isinstance(value, np.generic):
        value = value.item()
    if value is None:
        return "null"
    if isinstance(value, bool):
        return "true" if value else "false"
    try:
        if isinstance(value, numbers.Integral):
            return str(int(value))
        if isinstance(value, numbers.Real):
            v = float(value)
            if not math.isfinite(v):
                raise InputError(f"{where} = {v}: must be a finite number")
            return repr(v)
    except (ValueError, OverflowError) as e:
        raise InputError(f"{where}: {e}") from None
    if isinstance(value, str):
        return value
    if isinstance(value, (Mapping, list, tuple, np.ndarray)):
        try:
            return _json(value)
        except _ENCODING_ERRORS as e:
            raise InputError(f"{where}: {_why(e)}") from None
    raise InputError(f"{where}: {value!r:.80} ({type(value).__name__}) is not a case value")


def _overrides(set: Optional[Mapping[str, Any]]) -> List[str]:
    if set is None:
        return []
    if not isinstance(set, Mapping):
        raise InputError(f"set must be a dict {{'key.path': value}}, not {type(set).__name__}")
    texts = []
    for key, value in set.items():
        if not isinstance(key, str):
            raise InputError(f"set: the key {key!r:.80} must be a str ('key.path')")
        texts.append(f"{key}={_value_text(key, value)}")
    return texts


def _out(out: Any) -> Optional[str]:
    """The output folder as a str, or None."""
    return None if out is None else _path("out", out)


class Result:
    """The result of one run: summary.json's numbers and contact.csv's columns.

    Numbers (units of the case; docs/outputs.md has every key):

    * ``normal_force`` P [force/length], ``tangential_force`` Q [force/length] (of B on A along +x)
    * ``overlap`` delta0 [length], ``creepage`` xi = (V_A - V_B)/V [-]
    * ``load_ratio`` Q/(mu P) [-] (None when mu = 0), ``max_pressure`` [stress]
    * ``converged`` (bool), ``iterations``, ``residual`` (final scaled residual [-])
    * ``contact``: dict ``x_min``, ``x_max``, ``half_width``, ``centre`` [length] (None when
      nothing is in contact)
    * ``stick_zones``, ``slip_zones``: lists of [x0, x1] [length]
    * ``regime``: the slip regime 1-4 of Gonzalez & Abascal (2000) section 5.2, 0 for none
    * ``error_estimate``: the estimated errors of an error-controlled grid, or of a fixed grid
      against its halving (dict; None with ``contact.grid.estimate: false``; its
      ``body_mesh``, where a body has a mesh of its own, is a dict too)
    * ``rolling_resistance``: dict ``leading_edge``, ``trailing_edge``, ``pressure_centre``
      [length], ``moment`` [force*length/length], ``force`` F_r [force/length],
      ``coefficient`` F_r/P [-], ``speed`` [length/time], ``dissipated_power`` (docs/outputs.md;
      None when nothing is in contact)
    * ``timings``: dict of stage times [s]
    * ``case``: the case as resolved after the overrides (dict)
    * ``summary``: the whole summary.json content (dict)
    * ``output_dir``: the folder written (str), or None when nothing was written
    * ``history``: of a transient case (``transient:``, run into a folder), transient.csv's
      columns by name (docs/outputs.md, "A transient run"), one entry a step, step 0 first:
      ``step`` and ``iterations`` as int64 arrays, the others (``rolled``, ``normal_force``,
      ``tangential_force``, ``creep``, ``overlap``, ``max_pressure``, ``max_shear``, ...) as
      numpy masked float64 arrays, masked where transient.csv's cell is empty (``creep`` of
      step 0, ``shift`` of the rolling steps, ``time`` without ``load.speed``); the values are
      the file's, parsed from the digits the CLI prints. None for a steady run.

    Arrays (numpy, one entry per contact node in increasing x, named like contact.csv's
    columns): ``x`` [length], ``pressure`` p >= 0 [stress], ``shear`` q [stress], ``gap``
    [length], ``slip`` s/|V| [-], ``slip_hbem`` [-] (None when the models give no
    boundary-integral slip), ``state`` (str: open, stick, slip), ``u_n_A``, ``u_t_A``,
    ``u_n_B``, ``u_t_B`` [length] (surface displacements; u_n positive into the body). All of
    them are also in the dict ``arrays``.
    """

    normal_force: float
    tangential_force: float
    overlap: float
    creepage: float
    load_ratio: Optional[float]
    max_pressure: float
    converged: bool
    iterations: int
    residual: float
    contact: Optional[Dict[str, float]]
    stick_zones: List[List[float]]
    slip_zones: List[List[float]]
    regime: int
    error_estimate: Optional[Dict[str, Any]]
    rolling_resistance: Optional[Dict[str, Optional[float]]]
    timings: Dict[str, float]
    case: Dict[str, Any]
    summary: Dict[str, Any]
    output_dir: Optional[str]
    history: Optional[Dict[str, np.ndarray]]
    arrays: Dict[str, Optional[np.ndarray]]
    x: np.ndarray
    pressure: np.ndarray
    shear: np.ndarray
    gap: np.ndarray
    slip: np.ndarray
    slip_hbem: Optional[np.ndarray]
    state: np.ndarray
    u_n_A: np.ndarray
    u_t_A: np.ndarray
    u_n_B: np.ndarray
    u_t_B: np.ndarray

    def __init__(self, raw: Mapping[str, Any]) -> None:
        s = json.loads(raw["summary"])
        self.summary = s
        self.normal_force = s["normal_force"]
        self.tangential_force = s["tangential_force"]
        self.overlap = s["overlap"]
        self.creepage = s["creep"]
        self.load_ratio = s["load_ratio"]
        self.max_pressure = s["max_pressure"]
        self.converged = s["converged"]
        self.iterations = s["iterations"]
        self.residual = s["residual"]
        self.contact = s["contact"]
        self.stick_zones = s["stick_zones"]
        self.slip_zones = s["slip_zones"]
        self.regime = s["slip_regime"]
        self.error_estimate = s["error_estimate"]
        self.rolling_resistance = s["rolling_resistance"]
        self.timings = s["timings"]
        self.case = s["case"]
        self.output_dir = None if raw["output_dir"] is None else os.fspath(raw["output_dir"])
        self.history = None
        if "transient" in s and self.output_dir is not None:
            self.history = _read_history(os.path.join(self.output_dir, "transient.csv"))
        columns = raw["columns"]
        arrays: Dict[str, Optional[np.ndarray]] = {}
        for name in CONTACT_COLUMNS:
            if name == "state":
                arrays[name] = np.array(raw["state"], dtype=str)
            else:
                arrays[name] = columns.get(name)
        self.arrays = arrays
        for name, values in arrays.items():
            setattr(self, name, values)

    def to_pandas(self) -> "Any":
        """contact.csv as a pandas DataFrame (columns in contact.csv's order; ``slip_hbem`` is
        left out when the models give none). Needs pandas (``pip install pandas``)."""
        try:
            import pandas as pd
        except ImportError as e:  # pragma: no cover - depends on the environment
            raise ImportError("Result.to_pandas needs pandas: pip install pandas") from e
        return pd.DataFrame({k: v for k, v in self.arrays.items() if v is not None})

    def __repr__(self) -> str:
        return (
            f"<rollbem.Result {self.summary.get('title', '')!r}: P={self.normal_force:g} "
            f"Q={self.tangential_force:g} xi={self.creepage:g} converged={self.converged}>"
        )


def _read_history(path: str) -> Dict[str, np.ndarray]:
    """transient.csv's columns (Result.history): counts as int64, the rest as masked float64
    arrays masked at the empty cells."""
    import csv

    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    history: Dict[str, np.ndarray] = {}
    for j, name in enumerate(header):
        cells = [r[j] for r in body]
        if name in ("step", "iterations"):
            history[name] = np.array([int(c) for c in cells], dtype=np.int64)
        else:
            values = np.array([float(c) if c else 0.0 for c in cells], dtype=np.float64)
            history[name] = np.ma.array(values, mask=[c == "" for c in cells])
    return history


def run(
    case: Case,
    set: Optional[Mapping[str, Any]] = None,
    out: Optional[Union[str, "os.PathLike[str]"]] = None,
) -> Result:
    """Solves a case, like ``rollbem run``.

    Args:
        case: a case file (str or os.PathLike), or a dict with the case file's schema
            (cases/README.md). Relative paths inside a dict case (meshes) are relative to the
            current working directory; inside a file, to the file's folder.
        set: overrides ``{"key.path": value}``, as ``--set key.path=value`` (a number, bool,
            str, None, list or dict; e.g. ``{"contact.friction": 0.2}``).
        out: a folder to write the CLI's files into (summary.json, contact.csv, contact.svg,
            ...), replacing an earlier rollbem result there; None writes nothing.

    Returns:
        the :class:`Result`.

    Raises:
        InputError: bad input (the CLI's message; nothing written), or a bad argument (the
            message names it: ``case``, ``set['key']``, ``out``).
        NotConverged: the solver did not converge (``error.result`` is the partial result; with
            ``out`` only summary.json is written, as by the CLI), the numerics broke down, or an
            error-controlled grid missed its tolerance (``error.estimate``).
        InternalError: a bug.
        KeyboardInterrupt: Ctrl-C (in the main thread), within a Newton step of the solve.
    """
    path, text = _case_source(case)
    raw = _rollbem.run(path, text, _overrides(set), _out(out))
    result = Result(raw)
    if raw["not_converged"] is not None:
        estimate = {"residual": result.residual, "iterations": result.iterations}
        raise NotConverged(raw["not_converged"], result=result, estimate=estimate)
    return result


def check(
    case: Case, set: Optional[Mapping[str, Any]] = None, tolerance: float = 0.01, estimate: bool = False
) -> Dict[str, Any]:
    """The case as understood, without solving, like ``rollbem check``.

    Args:
        case, set: as for :func:`run`.
        tolerance: the accuracy you need, a fraction of p0 and mu p0 (0.01 is 1 %), for the model
            advice.
        estimate: also estimate the grid's discretisation error, like ``rollbem check
            --estimate``: solves the case on its fixed grid and on the grid halved; the report
            (and ``items["grid error (estimated)"]``) gives the estimate and warns when it exceeds
            ``tolerance``.

    Returns:
        a dict: ``report`` (the text the CLI prints), ``items`` (its rows as {label: text}),
        ``advice`` (the model advice row), ``estimates`` (summary.json's ``estimates``:
        ``hertz_half_width`` a [length], ``hertz_peak_pressure`` p0 [stress], ``e_star`` E*
        [stress], ``effective_radius`` R* [length], ``normal_force`` [force/length],
        ``carter_stick_width`` [length] or None, ...) and ``case`` (the resolved case).

    Raises:
        InputError, InternalError: as for :func:`run`.
    """
    path, text = _case_source(case)
    if isinstance(tolerance, bool) or not isinstance(tolerance, numbers.Real):
        raise InputError(f"tolerance must be a number, e.g. 0.01 for 1 %, not {type(tolerance).__name__}")
    try:
        tolerance = float(tolerance)
    except (ValueError, OverflowError) as e:
        raise InputError(f"tolerance: {e}") from None
    if not isinstance(estimate, bool):
        raise InputError(f"estimate must be True or False, not {type(estimate).__name__}")
    raw = _rollbem.check(path, text, _overrides(set), tolerance, estimate)
    report = raw["report"]
    items: Dict[str, str] = {}
    for line in report.splitlines()[1:]:
        # Each row is "  <label padded to 26> <text>" (a longer label shifts its text: skipped).
        if line.startswith("  ") and len(line) > 29 and line[28] == " ":
            items[line[2:28].strip()] = line[29:].strip()
    return {
        "report": report,
        "items": items,
        "advice": items.get("model advice"),
        "estimates": json.loads(raw["estimates"]),
        "case": json.loads(raw["case"]),
    }


def sweep(
    case: Case,
    vary: Mapping[str, Sequence[Any]],
    set: Optional[Mapping[str, Any]] = None,
    jobs: Optional[int] = None,
) -> List[Dict[str, Any]]:
    """Runs the Cartesian product of ``vary`` over a case, like ``rollbem sweep`` (nothing is
    written), in parallel on ``jobs`` threads (all cores when None), without the GIL.

    Args:
        case, set: as for :func:`run` (``set`` applies to every run).
        vary: ``{"key.path": [v1, v2, ...], ...}``; the first key varies slowest, as with
            ``--vary``.
        jobs: threads (1 to 1024; more than the machine's cores are capped to them, with a
            ``RuntimeWarning``; above 1024, as with ``rollbem sweep --jobs``, an
            :class:`InputError`), or None for every core.

    Returns:
        one dict per run in run order, with sweep.csv's columns but ``folder``: ``run``,
        ``status`` (``ok``, ``not_converged`` or ``failed``), each varied key with its value as
        given, ``message`` (why a run failed, else ""), then ``converged``, ``iterations``,
        ``residual``, ``normal_force``, ``tangential_force``, ``load_ratio``, ``overlap``,
        ``creep``, ``contact_x_min``, ``contact_x_max``, ``contact_centre``, ``half_width``, ``max_pressure``,
        ``slip_regime``, ``stick_zones``, ``slip_zones`` (counts), ``pressure_centre`` (towards
        the leading edge), ``rolling_resistance`` (F_r/P), ``assembly_s``,
        ``condense_s``, ``solve_s``, ``total_s`` (None for a failed run). Units as in
        :class:`Result`. :func:`sweep_frame` makes a pandas DataFrame of them.

    Raises:
        InputError: the case cannot be read, ``vary`` is empty, or an argument is bad (the
            message names it: ``vary['key']``, ``jobs``, ...); a value the case refuses is a
            failed row.
        InternalError: a bug outside the runs (a run's own panic is a failed row).
        KeyboardInterrupt: Ctrl-C (in the main thread): the runs under way stop within a
            Newton step, the others do not start.
    """
    if not isinstance(vary, Mapping) or not vary:
        raise InputError("sweep: nothing to sweep: give vary={'key.path': [v1, v2, ...]}")
    keys = list(vary)
    values = []
    for key in keys:
        if not isinstance(key, str):
            raise InputError(f"sweep: the key {key!r:.80} of vary must be a str ('key.path')")
        vs = vary[key]
        if isinstance(vs, (str, bytes)) or not isinstance(vs, (Sequence, np.ndarray)):
            raise InputError(f"sweep: vary[{key!r}] must be a list of values")
        values.append(list(vs))
    texts = [(key, [_value_text(key, v, "vary") for v in vs]) for key, vs in zip(keys, values)]
    if jobs is not None and (
        isinstance(jobs, bool) or not isinstance(jobs, numbers.Integral) or jobs < 1
    ):
        raise InputError(f"sweep: jobs must be a positive whole number or None (value = {jobs!r})")
    if jobs is not None and jobs > _MAX_JOBS:
        raise InputError(
            f"sweep: jobs = {jobs} is more threads than any machine has cores: give at most {_MAX_JOBS}, "
            "or None for every core"
        )
    cores = os.cpu_count() or 1
    if jobs is not None and jobs > cores:
        # More threads than cores only add switching: each run is one thread's work.
        warnings.warn(
            f"sweep: jobs = {jobs} exceeds the {cores} cores of this machine; running on {cores}",
            RuntimeWarning,
            stacklevel=2,
        )
        jobs = cores
    path, text = _case_source(case)
    rows = _rollbem.sweep(path, text, _overrides(set), texts, None if jobs is None else int(jobs))
    combos = list(itertools.product(*values))
    out = []
    for raw in rows:
        r = json.loads(raw)
        row: Dict[str, Any] = {"run": r.pop("run"), "status": r.pop("status")}
        row.update(zip(keys, combos[row["run"]]))
        row["message"] = r.pop("message")
        row.update((name, r[name]) for name in _rollbem.RESULT_COLUMNS)
        out.append(row)
    return out


def sweep_frame(rows: List[Dict[str, Any]]) -> "Any":
    """The rows of :func:`sweep` as a pandas DataFrame (needs pandas)."""
    try:
        import pandas as pd
    except ImportError as e:  # pragma: no cover - depends on the environment
        raise ImportError("sweep_frame needs pandas: pip install pandas") from e
    return pd.DataFrame(rows)
