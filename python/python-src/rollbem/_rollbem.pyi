"""Type stubs of the native module rollbem._rollbem (python/src/lib.rs); use the functions of
the package ``rollbem`` instead."""

from typing import Any, Dict, List, Optional, Tuple

__version__: str
RESULT_COLUMNS: List[str]
MAX_JOBS: int
CONTACT_COLUMNS: List[str]

def run(path: str, text: Optional[str], overrides: List[str], out: Optional[str] = None) -> Dict[str, Any]: ...
def check(path: str, text: Optional[str], overrides: List[str], tolerance: float = 0.01, estimate: bool = False) -> Dict[str, str]: ...
def sweep(
    path: str,
    text: Optional[str],
    overrides: List[str],
    varies: List[Tuple[str, List[str]]],
    jobs: Optional[int] = None,
) -> List[str]: ...
def _panic_for_tests(message: str) -> None: ...
