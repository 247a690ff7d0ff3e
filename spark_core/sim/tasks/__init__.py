"""Task suites with success predicates and reference plans."""

from .bimanual import SUITE as _BIMANUAL
from .builtin import SUITE as BUILTIN
from .capbench import SUITE as CAPBENCH
from .liberopro import SUITE as LIBEROPRO
from .silverware import SUITE as SILVERWARE
from .spec import TaskSpec

BIMANUAL: dict[str, TaskSpec] = {**_BIMANUAL, **SILVERWARE}  # the paper's silverware task is a bimanual one

TASKS: dict[str, TaskSpec] = {
    **BUILTIN,
    **BIMANUAL,
    **CAPBENCH,
    **LIBEROPRO,
}  # every task by name (console, replay, export)
SUITES: dict[str, dict[str, TaskSpec]] = {
    "builtin": BUILTIN,
    "bimanual": BIMANUAL,
    "capbench": CAPBENCH,
    "liberopro": LIBEROPRO,
}

__all__ = ["BIMANUAL", "BUILTIN", "CAPBENCH", "LIBEROPRO", "SUITES", "TASKS", "TaskSpec"]
