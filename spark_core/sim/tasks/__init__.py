"""Task suites with success predicates and reference plans."""

from .bimanual import SUITE as BIMANUAL
from .builtin import SUITE as BUILTIN
from .spec import TaskSpec

TASKS: dict[str, TaskSpec] = {**BUILTIN, **BIMANUAL}  # every task by name (console, replay, export)
SUITES: dict[str, dict[str, TaskSpec]] = {"builtin": BUILTIN, "bimanual": BIMANUAL}

__all__ = ["BIMANUAL", "BUILTIN", "SUITES", "TASKS", "TaskSpec"]
