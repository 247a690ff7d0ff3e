"""What a run produced: outcome, failure attribution, per-node records."""

from __future__ import annotations

import enum
from dataclasses import asdict, dataclass, field
from typing import Any

from .events import Event
from .protocols import FailureKind


class NodeStatus(enum.StrEnum):
    """A node's life cycle: pending -> running -> succeeded | failed | aborted. Shared with the API and UI."""

    PENDING = "pending"
    RUNNING = "running"
    SUCCEEDED = "succeeded"
    FAILED = "failed"
    ABORTED = "aborted"


class TreeStatus(enum.StrEnum):
    """How the executor ended the whole tree (`TrialResult.outcome`)."""

    SUCCESS = "success"
    FAILURE = "failure"
    ABORTED = "aborted"


@dataclass
class NodeRecord:
    """Per-node bookkeeping. Times: wall seconds since trial start; sim_time_s: simulated seconds."""

    path: str
    kind: str  # primitive name or composite type
    arm: str | None = None
    status: str = NodeStatus.PENDING.value  # a NodeStatus value
    attempts: int = 0
    retries: int = 0
    started_t: float | None = None
    finished_t: float | None = None
    sim_time_s: float = 0.0
    failure: FailureKind | None = None
    reason: str = ""
    recoveries: list[str] = field(default_factory=list)

    @property
    def duration_s(self) -> float | None:
        if self.started_t is None or self.finished_t is None:
            return None
        return self.finished_t - self.started_t

    def to_dict(self) -> dict[str, Any]:
        d = asdict(self)
        d["failure"] = self.failure.value if self.failure else None
        d["duration_s"] = self.duration_s
        return d


@dataclass
class TrialResult:
    trial_id: str
    outcome: str  # a TreeStatus value
    failure: FailureKind | None
    failed_node: str | None
    reason: str
    nodes: dict[str, NodeRecord]
    events: list[Event]
    wall_time_s: float
    sim_time_s: float
    replans: int = 0

    @property
    def success(self) -> bool:
        return self.outcome == "success"

    def to_dict(self) -> dict[str, Any]:
        return {
            "trial_id": self.trial_id,
            "outcome": self.outcome,
            "failure": self.failure.value if self.failure else None,
            "failed_node": self.failed_node,
            "reason": self.reason,
            "wall_time_s": self.wall_time_s,
            "sim_time_s": self.sim_time_s,
            "replans": self.replans,
            "nodes": {p: r.to_dict() for p, r in self.nodes.items()},
            "events": [e.to_dict() for e in self.events],
        }
