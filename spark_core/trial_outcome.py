"""How a trial ended: one verdict from a closed set, the two parts of success, and the failure attribution."""

from __future__ import annotations

import enum
from dataclasses import dataclass, field
from typing import Any

from .execution import TrialResult


class Verdict(enum.StrEnum):
    """The one verdict of a trial. Success means the task's predicate held within its time limit AND the
    behavior tree succeeded; every other value says which of the two failed, or why nothing was judged."""

    SUCCESS = "success"
    TASK_UNMET = "task_unmet"  # every node passed, but the task's success condition is false
    TREE_FAILED = "tree_failed"  # a node failed after its retries (see failure, failed_node, reason)
    PLANNER_ERROR = "planner_error"  # no plan to run: the planner failed or wrote an invalid plan
    ABORTED = "aborted"  # the operator stopped it (or cancelled it before it started)
    TIMEOUT = "timeout"  # the trial used more simulated time than the task allows
    INTERRUPTED = "interrupted"  # the console stopped while it was queued or running
    CRASHED = "crashed"  # an internal error, or the worker process died


@dataclass
class TrialOutcome:
    """What `run_trial` returns. Times: `sim_time_s` simulated seconds, `wall_time_s` wall seconds."""

    trial_id: str
    task: str
    seed: int
    instruction: str
    verdict: Verdict
    task_success: bool | None  # the task's predicate within its time limit (None: never judged)
    tree_status: str | None  # the executor's TreeStatus value (None: nothing executed)
    failure: str | None  # FailureKind value of the failing module
    failed_node: str | None
    reason: str
    unmet: str | None  # the success condition that was false, named (task_unmet, timeout)
    sim_time_s: float
    wall_time_s: float
    protocol: dict[str, Any]
    retries: int = 0
    events: int = 0  # events published
    trajectory_len: int = 0  # joint-state rows recorded at the control rate
    cost_usd: float = 0.0
    usage: dict[str, int] = field(default_factory=dict)
    plan_text: str = ""
    phases_s: dict[str, float] = field(default_factory=dict)  # wall seconds: setup, perception, planning, ...
    result: TrialResult | None = field(default=None, repr=False)

    @property
    def success(self) -> bool:
        return self.verdict is Verdict.SUCCESS

    def row(self) -> dict[str, Any]:
        """Plain JSON fields (for reports, batch rows and Ray, which pickles it)."""
        out = {k: v for k, v in self.__dict__.items() if k != "result"}
        out["verdict"] = self.verdict.value
        out["success"] = self.success
        return out


def judge(
    *, planned: bool, aborted: bool, timed_out: bool, tree_status: str | None, task_success: bool | None
) -> Verdict:
    """The one success rule. Order matters: an operator's abort and the time limit end the trial whatever
    the tree and the predicate say at that moment."""
    if not planned:
        return Verdict.PLANNER_ERROR
    if aborted:
        return Verdict.ABORTED
    if timed_out:
        return Verdict.TIMEOUT
    if tree_status != "success":
        return Verdict.TREE_FAILED
    return Verdict.SUCCESS if task_success else Verdict.TASK_UNMET


__all__ = ["TrialOutcome", "Verdict", "judge"]
