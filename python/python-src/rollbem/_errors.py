"""The exceptions of rollbem, one per exit code of the ``rollbem`` program (docs/reliability.md).

The native module raises them by name (``rollbem._errors``), so they are plain Python classes.
"""

from __future__ import annotations

from typing import Any, Dict, Optional


class RollbemError(Exception):
    """Base class of rollbem's errors; ``str(error)`` is the message the CLI prints."""


class InputError(RollbemError):
    """Bad input, as the CLI's exit code 1: an unknown key, a value out of range, a bad mesh, an
    unreadable file, an output folder that holds files rollbem did not write. The message names
    the file, key or group and what to change (the same text the CLI prints). Nothing was
    written."""


class NotConverged(RollbemError):
    """The run finished without a trustworthy solution, as the CLI's exit code 2.

    Attributes:
        result: the partial :class:`rollbem.Result` (the last iterate, ``converged`` False) when
            the solver stopped without converging; None when the numerics broke down (a number
            not finite) or an error-controlled grid missed its tolerance.
        estimate: how far the run got, or None. For an error-controlled grid that reached
            ``contact.grid.max_elements`` first: ``tolerance``, ``elements``, ``max_elements`` and
            the estimated RMS errors ``pressure`` [p0], ``shear`` [mu p0] and ``creep``
            (relative). For a solver that did not converge: ``residual`` (the final scaled
            residual) and ``iterations``.
    """

    def __init__(
        self,
        message: str,
        result: Optional[Any] = None,
        estimate: Optional[Dict[str, Any]] = None,
    ) -> None:
        super().__init__(message)
        self.result = result
        self.estimate = estimate


class InternalError(RollbemError):
    """A bug in rollbem (a Rust panic, caught before it reached Python), as the CLI's exit code 3.
    Please report it with the case and the message."""
