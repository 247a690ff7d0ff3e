"""Plan errors as values: each names the exact path and what was expected."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class PlanIssue:
    """One problem in a plan. `path` is like `tree.children[2].params.force`; `text` for syntax errors."""

    path: str
    message: str

    def __str__(self) -> str:
        return f"{self.path}: {self.message}"


class PlanError(ValueError):
    """A plan that cannot be used. Carries every issue found, not only the first."""

    def __init__(self, issues: list[PlanIssue]):
        self.issues = list(issues)
        super().__init__("\n".join(str(i) for i in self.issues))
