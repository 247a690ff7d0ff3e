"""Task suites with success predicates and reference plans."""

from .builtin import SUITE as BUILTIN
from .spec import TaskSpec

__all__ = ["BUILTIN", "TaskSpec"]
