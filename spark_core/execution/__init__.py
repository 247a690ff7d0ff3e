"""Execution: runs typed plans with late label binding, post-conditions, recovery and step-through control."""

from .events import EVENT_KINDS, Event, EventBus, EventKind
from .executor import BOTH_ARMS, Executor, Failure, ReplanRequest
from .protocols import ActionOutcome, Actuator, FailureKind, Resolver
from .recovery import PERTURB, REDETECT, REPLAN, RecoveryPolicy
from .result import NodeRecord, NodeStatus, TreeStatus, TrialResult
from .step_control import Aborted, StepControl

__all__ = [
    "Aborted",
    "ActionOutcome",
    "Actuator",
    "BOTH_ARMS",
    "EVENT_KINDS",
    "Event",
    "EventBus",
    "EventKind",
    "Executor",
    "Failure",
    "FailureKind",
    "NodeRecord",
    "NodeStatus",
    "TreeStatus",
    "PERTURB",
    "REDETECT",
    "REPLAN",
    "RecoveryPolicy",
    "ReplanRequest",
    "Resolver",
    "StepControl",
    "TrialResult",
]
